/* gltf_check.h — the image MIME types of a glTF or GLB file checked before Assimp reads it:
 * Assimp 5.2 takes the part of an embedded image's mimeType after its '/' without looking
 * whether there is one, and crashes on a mimeType without it ("png"). The file is read whole
 * and searched for "mimeType" keys; nothing is allocated past the call. */
#ifndef SYLVA_GLTF_CHECK_H
#define SYLVA_GLTF_CHECK_H

#include "util/err.h"

/* 0 when every "mimeType" string value in the file holds a '/'; -1 with err set ("path: ...",
 * ERR_INPUT) naming the first that does not, or when the file cannot be read. */
int gltf_check(const char *path, err_buf *err);

#endif
