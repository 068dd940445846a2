/* image_io.h — the C side of the one C++ file (oiio_shim.cpp) that talks to OpenImageIO:
 * reading any image format as float pixels and writing 8-bit images (PNG). Nothing of C++
 * crosses this header. Writes go to a temporary name and are renamed into place. */
#ifndef SYLVA_IMAGE_IO_H
#define SYLVA_IMAGE_IO_H

#include <stddef.h>
#include <stdint.h>

#include "io/atomic_file.h"
#include "util/err.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct image_f32 {
    uint32_t width, height, channels;
    float *pixels;             /* width*height*channels, row 0 at the top; owned (image_free) */
    char **channel_names;      /* channels strings; owned */
} image_f32;

/* Bytes per pixel that a reader of image_read keeps besides the float samples: a texture's
 * 8-bit RGBA and the scene's copy of it. */
#define IMAGE_READ_COPY_BYTES_PER_PIXEL 8u

/* Reads path (PNG, EXR, JPEG, TIFF, ... whatever OpenImageIO reads), every channel as float
 * (8- and 16-bit values scaled to [0, 1], 32-bit integers such as EXR id channels kept by
 * value, alpha unassociated, no colour conversion). Before the pixels are allocated, the float
 * samples and IMAGE_READ_COPY_BYTES_PER_PIXEL a pixel are checked against the memory budget
 * (util/memory_budget.h); an image that does not fit is refused with ERR_LIMIT. A file cut short
 * or damaged is refused even where the decoder would fill the rest in. Returns 0 or -1 with err
 * set. */
int image_read(const char *path, image_f32 *out, err_buf *err);
/* The same for an image held in memory (a texture embedded in a model file): `format` is the
 * file extension that names its encoding ("png", "jpg"), `name` names it in messages. The
 * bytes stay the caller's. */
int image_read_memory(const void *bytes, size_t size, const char *format, const char *name,
                      image_f32 *out, err_buf *err);
void image_free(image_f32 *img); /* accepts a zeroed image */

/* The Software tag of every 8-bit image sylva writes: a montage tells a plate sylva rendered
 * (whose light is the render's own) from a photograph by it (io/photo.h). */
#define SYLVA_SOFTWARE_TAG "sylva"

/* Writes 8-bit pixels (channels 1..4) to path; the format follows the extension, tagged with
 * Software = SYLVA_SOFTWARE_TAG. */
int image_write_u8(const char *path, uint32_t width, uint32_t height, uint32_t channels,
                   const uint8_t *pixels, err_buf *err);
/* The same into a temporary the caller opened (atomic_file_open_stream) and commits or aborts
 * itself, for outputs that appear together. The format follows af->path's extension. */
int image_write_u8_into(atomic_file *af, uint32_t width, uint32_t height, uint32_t channels,
                        const uint8_t *pixels, err_buf *err);

struct photo;
/* Reads the photograph `path` for io/photo.c: the stored pixels (before the orientation, no
 * colour conversion, every channel as float) into *stored, and into *meta the stored size,
 * bits per sample, floating-point flag, oiio:ColorSpace and the EXIF record (io/photo.h);
 * meta->rgb is left alone. The memory check (util/memory_budget.h) covers the stored pixels
 * and a linear RGB copy. Returns 0 or -1 with err naming the file and what OpenImageIO said. */
int image_read_photo(const char *path, image_f32 *stored, struct photo *meta, err_buf *err);

#ifdef __cplusplus
}
#endif
#endif
