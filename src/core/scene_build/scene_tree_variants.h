/* scene_tree_variants.h — a species' age variants from its tree plugin, on several threads when
 * the plugin allows it (SYLVA_PLUGIN_CONCURRENT_GENERATE). Each variant is seeded by the species
 * and its index alone (plugin_call_tree) and lands in its own slot, and the prototypes are added
 * in index order, so the scene is the same bytes for any thread count. */
#ifndef SYLVA_SCENE_TREE_VARIANTS_H
#define SYLVA_SCENE_TREE_VARIANTS_H

#include "scene_build/plugin_call.h"

/* Makes variants 0..count-1 of species sp through c (opened with
 * plugin_call_open_tree) and adds them to s as prototypes in index order, counting them in
 * s->species[sp].n_variants. threads: at most this many at once (0: one per processor);
 * a plugin without the concurrent flag runs one variant at a time. Returns 0, or -1 with err
 * set by the lowest-numbered variant that failed (the failure a one-thread run meets first). */
int tree_variants_build(plugin_call *c, scene *s, uint32_t sp, uint32_t count, unsigned threads,
                        err_buf *err);

#endif
