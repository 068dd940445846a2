/* model_limits.h — the limits of model import, shared by the reader (model_import.h) and the
 * checks that run before Assimp reads a file (gltf_layout.h). */
#ifndef SYLVA_MODEL_LIMITS_H
#define SYLVA_MODEL_LIMITS_H

/* The default triangle limit (instances counted): a model above it is refused before any of
 * its geometry is copied. Memory per triangle is stated in docs/models-import.md. */
#define MODEL_MAX_TRIANGLES 20000000u
/* The deepest node hierarchy read (levels from a root); glTF's is checked before Assimp reads it,
 * whose reader recurses through it. */
#define MODEL_MAX_NODE_DEPTH 1000

#endif
