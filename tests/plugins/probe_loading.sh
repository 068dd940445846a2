#!/usr/bin/env bash
# probe_loading.sh SYLVA TEST_PLUGIN_DIR BUILD_PLUGIN_DIR SCENE — which commands open plugin
# modules. The probe modules (probe_constructor.c) leave $SYLVA_TEST_PROBE_DIR/NAME.opened when
# their constructor runs, so a mark means the module was opened:
#   - rendering SCENE, which uses no plugin, opens none;
#   - `plugins --describe example_terrain` does not open probe_open.so, which comes later;
#   - `plugins` opens every module (probe_open.so) but never broken_manifest.so, whose manifest
#     declares ABI 2.0, and says why;
#   - a copy of SYLVA outside its build tree does not search BUILD_PLUGIN_DIR (the build tree's
#     own binary does).
set -uo pipefail
sylva=$1 plugins=$2 build_plugins=$3 scene=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SYLVA_TEST_PROBE_DIR=$work
fail() { echo "FAIL: $*" >&2; exit 1; }

SYLVA_PLUGIN_PATH=$plugins "$sylva" render "$scene" --size 8x6 --spp 1 -q -o "$work/r.png" >/dev/null ||
    fail "the render of $scene failed"
[ ! -e "$work/probe_open.opened" ] || fail "a render of a scene without plugins opened probe_open.so"

SYLVA_PLUGIN_PATH=$plugins "$sylva" plugins --describe example_terrain >/dev/null ||
    fail "plugins --describe example_terrain failed"
[ ! -e "$work/probe_open.opened" ] || fail "describing example_terrain opened probe_open.so"

SYLVA_PLUGIN_PATH=$plugins "$sylva" plugins >"$work/list" 2>"$work/problems"
[ -e "$work/probe_open.opened" ] || fail "sylva plugins did not open probe_open.so (the probe does not work)"
[ ! -e "$work/broken_manifest.opened" ] || fail "broken_manifest.so was opened although its manifest declares ABI 2.0"
grep -q "broken_manifest.so: not opened: its manifest .*broken_manifest.sylva-plugin says plugin 'broken_manifest' is built against sylva plugin ABI 2.0" "$work/problems" ||
    { cat "$work/problems"; fail "no sentence on broken_manifest.so's manifest"; }
grep -q "^probe_open " "$work/list" || fail "probe_open is not listed"

SYLVA_PLUGIN_PATH=$plugins "$sylva" plugins --describe broken_manifest >/dev/null 2>"$work/why"
grep -q "plugin 'broken_manifest' was found but cannot be used: .*ABI 2.0" "$work/why" ||
    { cat "$work/why"; fail "describing broken_manifest does not say why it cannot be used"; }

mkdir "$work/bin" && cp "$sylva" "$work/bin/sylva" || fail "cannot copy $sylva"
env -u SYLVA_PLUGIN_PATH "$sylva" plugins >"$work/built" 2>&1
grep -qF "$build_plugins" "$work/built" || fail "the build tree's sylva does not search $build_plugins"
env -u SYLVA_PLUGIN_PATH "$work/bin/sylva" plugins >"$work/installed" 2>&1
if grep -qF "$build_plugins" "$work/installed"; then
    cat "$work/installed"
    fail "a sylva outside the build tree searched $build_plugins"
fi
"$work/bin/sylva" plugins --help | grep -qF "$build_plugins" && fail "the help of a sylva outside the build tree names $build_plugins"
echo "plugin loading: as documented"
exit 0
