/* png_read_check.h — a PNG read once by libpng with sylva's own error and warning handlers
 * before OpenImageIO reads it. OpenImageIO's PNG reader leaves libpng's handlers as they are, so
 * what libpng finds wrong in a file it reads ("libpng error: bad adaptive filter value") is
 * printed on stderr before sylva's own sentence, under -q too, and libpng allocates the length a
 * chunk states before it finds that the file ends sooner. Read here first, a damaged PNG is
 * refused in sylva's sentence alone and OpenImageIO only ever sees one that reads cleanly. */
#ifndef SYLVA_PNG_READ_CHECK_H
#define SYLVA_PNG_READ_CHECK_H

#include <stddef.h>

#include "util/err.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The PNG in the file `name`, or in the `size` bytes at `bytes` when bytes is not NULL (name then
 * only names it), read as far as its header and the chunks before its pixels, or with pixels set
 * through every row of its pixels and the chunks after them too, expanded as OpenImageIO reads
 * them (call that once the image's size has passed the memory budget: it costs a decoding).
 * Each call first checks the chunks' lengths against the file (util/chunk_check.h), a walk of
 * their headers alone. Returns 0 when it reads cleanly that far or does not start with the PNG
 * signature; -1 with err set ("name: the PNG is damaged or cut short ...", ERR_INPUT, libpng's
 * words quoted) when it does not, or when the file cannot be read. */
int png_read_check(const char *name, const void *bytes, size_t size, int pixels, err_buf *err);

#ifdef __cplusplus
}
#endif

#endif
