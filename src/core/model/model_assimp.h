/* model_assimp.h — Assimp, for the core, through the model module (model/model_module.h), which
 * is opened the first time a model is read. */
#ifndef SYLVA_MODEL_ASSIMP_H
#define SYLVA_MODEL_ASSIMP_H

#include "model/model_module.h"
#include "util/err.h"

/* The module's operations, or NULL with err (ERR_INPUT) saying, for the model at path, why the
 * module cannot be loaded. */
const model_module *model_assimp(const char *path, err_buf *err);

#endif
