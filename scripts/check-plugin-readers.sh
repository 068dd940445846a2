#!/usr/bin/env bash
# check-plugin-readers.sh [ROOT] — lists every call in src/plugins of a parameter reader that
# does not report a name the schema lacks (sylva_param, sylva_param_real, sylva_param_int,
# sylva_param_str, sylva_param_index of sylva/plugin.h, which stay for plugins built against ABI
# 1.0 to 1.5); exit 0 when there is none. sylva's own plugins read through
# src/plugins/common/plugin_params.h, so that a misspelt name is the host's error at the block.
# The test plugins of tests/ are not held to it (one misspells a name on purpose).
cd "${1:-$(dirname "$0")/..}/src/plugins" || exit 2
unchecked='\bsylva_param(_real|_int|_str|_index)?[[:space:]]*\('
if grep -rnE --include='*.[ch]' "$unchecked" . ; then
  echo "plugin readers: the calls above read a parameter unchecked; read through plugin_params.h"
  exit 1
fi
echo "plugin readers: every parameter read in src/plugins goes through a checked reader"
