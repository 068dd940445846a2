/* tree_weber_penn.h — the tree_weber_penn descriptor: create() reads the species and the look,
 * makes the leaf form, the model's caps and the bark and leaf materials; generate() grows one
 * age variant with wp_model_grow and appends its mesh; destroy() frees the state. The module's
 * entry point (wp_entry.c) returns it; tests call it through a host of their own. */
#ifndef TREE_WEBER_PENN_H
#define TREE_WEBER_PENN_H

#include <stdint.h>

#include "sylva/plugin.h"

/* The descriptor (static const data). */
const sylva_plugin *wp_plugin(void);

#endif
