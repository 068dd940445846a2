/* build_tree.h — whether this program runs from the build tree it was built in, so that the
 * modules built beside it (plugins, the image module) are looked for there before the install
 * folders. An installed copy never looks into a build tree.
 */
#ifndef SYLVA_BUILD_TREE_H
#define SYLVA_BUILD_TREE_H

/* 1 when this program's executable lies inside the build tree it was built in (SYLVA_BUILD_ROOT);
 * 0 for an installed copy. */
int build_tree_running(void);

#endif
