/* model_assimp.c — the model module opened once, the first time a model is read; found as
 * util/module_load.h says, SYLVA_MODEL_MODULE naming its file. */
#include "model/model_assimp.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>

#include "util/module_load.h"

/* The module once opened (never closed: its C++ runtime stays until the process ends), or the
 * sentence saying why it could not be. */
static pthread_once_t module_once = PTHREAD_ONCE_INIT;
static const model_module *module;
static char module_problem[1024];

static void module_find(void)
{
    void *so = NULL;
    model_module_entry entry = (model_module_entry)module_load("SYLVA_MODEL_MODULE", MODEL_MODULE_FILE,
                                                               SYLVA_MODULE_INSTALL_DIR, MODEL_MODULE_ENTRY, &so,
                                                               module_problem, sizeof module_problem);
    if (!entry) return;
    const model_module *m = entry();
    if (!m || m->size < sizeof(model_module) || m->version != MODEL_MODULE_VERSION) {
        snprintf(module_problem, sizeof module_problem, "%s: the model module is of another version than this "
                 "sylva (rebuild or reinstall both)", MODEL_MODULE_FILE);
        dlclose(so);
        return;
    }
    module = m; /* so stays open until the process ends */
}

const model_module *model_assimp(const char *path, err_buf *err)
{
    pthread_once(&module_once, module_find);
    if (!module)
        err_fail(err, ERR_INPUT, "%s: models are read through Assimp in the module %s, which cannot be loaded "
                 "(%s); reinstall sylva, or name the module's file in SYLVA_MODEL_MODULE",
                 path, MODEL_MODULE_FILE, module_problem);
    return module;
}
