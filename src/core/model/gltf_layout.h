/* gltf_layout.h — the layout a glTF 2.0 file states (its bytes, its primitives' vertex counts, its
 * skins, nodes and animations), checked before Assimp reads it.
 * Assimp 5.2 bounds an accessor by its component size times its count, not by its elements and
 * their stride from its offset, and then copies whole elements: an accessor one byte past the end
 * of its buffer view made it read past the end of its buffer. It adds offsets and lengths in
 * 64 bits without minding their sum's wrapping, and it writes a sparse accessor's values where
 * the sparse indices say, unchecked. So, on the JSON as Assimp reads it (json_read.h): the
 * version is 2; every buffer view lies within its buffer (a GLB's buffer 0 is its BIN chunk);
 * every accessor's elements, from its offset at its view's stride, lie within its view; the
 * numbers these take are whole numbers of their ranges; no accessor is sparse; and every mesh
 * primitive has a POSITION and draws enough vertices for its mode, with indices of an unsigned
 * integer type: Assimp makes count - 2 faces of a triangle fan and then writes the first, so a
 * fan of two indices wrote a face into an array of none; and every node's skin is one of the
 * file's, with a MAT4 inverse bind matrix of floats for each joint (a skin without them crashed
 * Assimp); the node hierarchy is a tree no deeper than MODEL_MAX_NODE_DEPTH (Assimp recurses down
 * it); and each animation channel's sampler and node exist, each sampler's output holding a value
 * (three for a cubic spline) for each of its input's times. Nothing is allocated past the call. */
#ifndef SYLVA_GLTF_LAYOUT_H
#define SYLVA_GLTF_LAYOUT_H

#include <stddef.h>
#include <stdint.h>

#include "util/err.h"

/* GLTF_NO_BIN: a file with no BIN chunk (a .gltf, or a GLB without one). */
#define GLTF_NO_BIN UINT64_MAX

/* 0 when the glTF JSON json[0..n) states a layout Assimp reads within its bytes; bin is the
 * length of a GLB's BIN chunk, or GLTF_NO_BIN for a .gltf; where prefixes messages ("model.gltf"
 * or "model.glb (its JSON chunk)"), followed by the line and column in the JSON. -1 with err set
 * (ERR_INPUT; ERR_LIMIT or ERR_NOMEM from the JSON reader) naming the first part that fails. */
int gltf_layout_check(const char *json, size_t n, uint64_t bin, const char *where, err_buf *err);

#endif
