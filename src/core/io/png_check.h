/* png_check.h — a PNG file's chunks walked before OpenImageIO reads it: libpng allocates the
 * length a chunk states before it finds the file ends sooner, so a damaged length (up to 2 GiB)
 * in a file of a few hundred bytes became an allocation of that size. Each chunk's length is
 * checked against the bytes that follow it; nothing is read beyond the chunk headers.
 * Nothing is allocated past the call. */
#ifndef SYLVA_PNG_CHECK_H
#define SYLVA_PNG_CHECK_H

#include "util/err.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 0 when the file is not a PNG (it lacks the PNG signature) or when every chunk up to IEND
 * fits in the file; -1 with err set ("path: ...", ERR_INPUT) naming the first chunk that
 * states more bytes than the file holds. */
int png_check(const char *path, err_buf *err);

#ifdef __cplusplus
}
#endif

#endif
