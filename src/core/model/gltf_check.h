/* gltf_check.h — the image MIME types and the URIs of a glTF or GLB file checked before Assimp
 * reads it: Assimp 5.2 takes the part of an embedded image's mimeType after its '/' without
 * looking whether there is one, and crashes on a mimeType without it ("png"); and the filter it
 * hands every file a model refers to through (a buffer's uri) reads past the end of a path ending
 * with "://" or made of two backslashes alone; and its reader of a line loop (a primitive of mode
 * 2) dereferences its first line, which it left empty when that line's indices are past the
 * vertices (a null pointer). The file is read whole and searched for "mimeType", "uri" and "mode"
 * keys; a key written with an escape ("mod\u0065"), which Assimp's JSON reader decodes and the
 * search would not find, is refused. Then the layout its JSON states, read whole, is checked
 * against its bytes (gltf_layout.h). Nothing is allocated past the call. */
#ifndef SYLVA_GLTF_CHECK_H
#define SYLVA_GLTF_CHECK_H

#include "util/err.h"

/* 0 when no key of the JSON is written with an escape, every "mimeType" string value in the file
 * holds a '/', no "uri" value ends with "://" or is two backslashes, no "mode" is 2 and
 * gltf_layout_check passes; -1 with err set ("path...: ...", ERR_INPUT; ERR_LIMIT or ERR_NOMEM
 * from the JSON reader) naming the first that fails, or when the file cannot be read. */
int gltf_check(const char *path, err_buf *err);

#endif
