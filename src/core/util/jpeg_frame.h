/* jpeg_frame.h — the size of the frame a JPEG file states, read from its start-of-frame marker
 * before the library that decodes it sees the file. OpenImageIO's JPEG reader starts libjpeg's
 * decompression when it opens a file, and libjpeg then allocates for the whole frame (all of a
 * progressive JPEG's coefficients), so a file of 753 bytes stating 65285 x 59651 pixels took
 * 11 GB before any size could be checked against the memory budget. Only the marker headers
 * are read; nothing is allocated. */
#ifndef SYLVA_JPEG_FRAME_H
#define SYLVA_JPEG_FRAME_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* 1 with *width, *height and *components set when path starts with a JPEG's SOI marker and a
 * start-of-frame marker (any SOFn) is found among the markers before the first scan; 0 when the
 * file is not a JPEG, cannot be read or states no frame before its data (the decoder then finds
 * the fault itself). */
int jpeg_frame(const char *path, uint32_t *width, uint32_t *height, uint32_t *components);

#ifdef __cplusplus
}
#endif

#endif
