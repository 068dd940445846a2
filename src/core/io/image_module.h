/* image_module.h — what the core and the image module (sylva_image.so, built from
 * oiio_shim.cpp) hand each other. OpenImageIO and the C++ libraries under it are large to load,
 * and most commands never read or write an image through them (a ZTV's GeoTIFFs go through GDAL,
 * its pages through libpng), so the core opens the module with dlopen the first time an image
 * is read or written through image_io.h (io/image_io.c), never at start-up.
 *
 * The module's one exported function, IMAGE_MODULE_ENTRY, takes the host's table of the core
 * functions it calls (those whose state is the process's: the memory budget, the checks of a
 * file before a decoder sees it) and returns its own table of operations. Both tables begin with
 * their size, and fields are only ever appended; IMAGE_MODULE_VERSION changes when one changes
 * meaning. The module keeps the host's table (static data of the core) until the process ends.
 */
#ifndef SYLVA_IMAGE_MODULE_H
#define SYLVA_IMAGE_MODULE_H

#include <stdint.h>

#include "io/atomic_file.h"
#include "util/err.h"

#ifdef __cplusplus
extern "C" {
#endif

struct image_f32; /* io/image_io.h */
struct photo;     /* io/photo.h */

#define IMAGE_MODULE_FILE "sylva_image.so"
#define IMAGE_MODULE_ENTRY "sylva_image_module"
#define IMAGE_MODULE_VERSION 2u

/* The core's functions the module calls (util/memory_budget.h, util/file_check.h,
 * io/png_read_check.h, util/jpeg_frame.h, image_io.h). */
typedef struct image_host {
    uint32_t size;
    int (*memory_check)(uint64_t need, const char *what, err_buf *err);
    int (*file_check_regular)(const char *path, const char *label, err_buf *err);
    int (*png_read_check)(const char *name, const void *bytes, size_t size, int pixels, err_buf *err);
    int (*jpeg_frame)(const char *path, uint32_t *width, uint32_t *height, uint32_t *components);
    void (*image_free)(struct image_f32 *img);
} image_host;

/* The module's operations: image_io.h's functions of the same names, their arguments checked by
 * the core first. */
typedef struct image_module {
    uint32_t size, version;
    int (*read)(const char *path, struct image_f32 *out, err_buf *err);
    int (*read_memory)(const void *bytes, size_t size, const char *format, const char *name, struct image_f32 *out,
                       err_buf *err);
    int (*write_u8_into)(atomic_file *af, uint32_t width, uint32_t height, uint32_t channels, const uint8_t *pixels,
                         err_buf *err);
    int (*read_photo)(const char *path, struct image_f32 *stored, struct photo *meta, err_buf *err);
} image_module;

typedef const image_module *(*image_module_entry)(const image_host *host);

#ifdef __cplusplus
}
#endif
#endif
