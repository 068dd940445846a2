/* image_io.c — image_io.h on the image module (io/image_module.h), opened with dlopen the first
 * time an image is read or written, so that a run that never needs OpenImageIO never loads it.
 * The module is found as util/module_load.h says, SYLVA_IMAGE_MODULE naming its file.
 * The arguments are checked here, and the freeing and the atomic write are the core's own.
 */
#include "io/image_io.h"

#include <dlfcn.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#include "io/image_module.h"
#include "io/png_read_check.h"
#include "util/file_check.h"
#include "util/jpeg_frame.h"
#include "util/memory_budget.h"
#include "util/module_load.h"

static const image_host host = {sizeof(image_host), memory_check, file_check_regular, png_read_check, jpeg_frame,
                                image_free};

/* The module once opened (never closed: its C++ runtime stays until the process ends), or the
 * sentence saying why it could not be. */
static pthread_once_t module_once = PTHREAD_ONCE_INIT;
static const image_module *module;
static char module_problem[1024];

static void module_find(void)
{
    void *so = NULL;
    image_module_entry entry = (image_module_entry)module_load("SYLVA_IMAGE_MODULE", IMAGE_MODULE_FILE,
                                                               SYLVA_MODULE_INSTALL_DIR, IMAGE_MODULE_ENTRY, &so,
                                                               module_problem, sizeof module_problem);
    if (!entry) return;
    const image_module *m = entry(&host);
    if (!m || m->size < sizeof(image_module) || m->version != IMAGE_MODULE_VERSION) {
        snprintf(module_problem, sizeof module_problem, "%s: the image module is of another version than this "
                 "sylva (rebuild or reinstall both)", IMAGE_MODULE_FILE);
        dlclose(so);
        return;
    }
    module = m; /* so stays open until the process ends: the module's C++ runtime lives until then */
}

/* The module, or NULL with err saying why it cannot be loaded. */
static const image_module *module_get(const char *path, err_buf *err)
{
    pthread_once(&module_once, module_find);
    if (!module)
        err_fail(err, ERR_INPUT, "%s: images are read and written through OpenImageIO in the module %s, which "
                 "cannot be loaded (%s); reinstall sylva, or name the module's file in SYLVA_IMAGE_MODULE",
                 path, IMAGE_MODULE_FILE, module_problem);
    return module;
}

int image_read(const char *path, image_f32 *out, err_buf *err)
{
    if (!path || !out) return err_set(err, "image_read needs a path and an output image");
    const image_module *m = module_get(path, err);
    return m ? m->read(path, out, err) : -1;
}

int image_read_memory(const void *bytes, size_t size, const char *format, const char *name, image_f32 *out,
                      err_buf *err)
{
    if (!bytes || !size || !format || !name || !out)
        return err_set(err, "image_read_memory needs bytes, a format and a name");
    const image_module *m = module_get(name, err);
    return m ? m->read_memory(bytes, size, format, name, out, err) : -1;
}

void image_free(image_f32 *img)
{
    if (!img) return;
    if (img->channel_names)
        for (uint32_t c = 0; c < img->channels; c++) free(img->channel_names[c]);
    free(img->channel_names);
    free(img->pixels);
    *img = (image_f32){0};
}

int image_write_u8_into(atomic_file *af, uint32_t width, uint32_t height, uint32_t channels, const uint8_t *pixels,
                        err_buf *err)
{
    if (!af || !af->stream || !pixels) return err_set(err, "image_write_u8_into needs an open temporary and pixels");
    const char *path = af->path;
    if (width == 0 || height == 0 || width > INT_MAX || height > INT_MAX)
        return err_set(err, "%s: cannot write a %ux%u image; width and height must be between 1 and %d", path, width,
                       height, INT_MAX);
    if (channels < 1 || channels > 4)
        return err_set(err, "%s: cannot write %u channels; 1 to 4 (grey, grey+alpha, RGB, RGBA) are supported", path,
                       channels);
    const image_module *m = module_get(path, err);
    return m ? m->write_u8_into(af, width, height, channels, pixels, err) : -1;
}

int image_write_u8(const char *path, uint32_t width, uint32_t height, uint32_t channels, const uint8_t *pixels,
                   err_buf *err)
{
    if (!path || !pixels) return err_set(err, "image_write_u8 needs a path and pixels");
    atomic_file tmp;
    if (!atomic_file_open_stream(&tmp, path, err)) return -1;
    if (image_write_u8_into(&tmp, width, height, channels, pixels, err)) {
        atomic_file_abort(&tmp);
        return -1;
    }
    return atomic_file_commit(&tmp, err);
}

int image_read_photo(const char *path, image_f32 *stored, struct photo *meta, err_buf *err)
{
    if (!path || !stored || !meta) return err_set(err, "image_read_photo needs a path, an image and a photo");
    const image_module *m = module_get(path, err);
    return m ? m->read_photo(path, stored, meta, err) : -1;
}
