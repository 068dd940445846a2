#!/usr/bin/env bash
# same_plugin_failure.sh SYLVA DIR — a plugin's failure reads the same from every command that
# calls the plugin, and ends each with the exit status of its kind:
#   - refusing_tree.yaml: `render` and `tree-stats` stop at the refused variant with one
#     sentence (the request's variant, age and seed in it), exit status 2;
#   - refusing_ecology.yaml: `render` and `simulate` stop in create() with one sentence placed
#     at the refused parameter (the stream's first number in it), exit status 2;
#   - refusing_tree_nomem.yaml: a plugin returning SYLVA_ERR_NOMEM ends `render` and
#     `tree-stats` with exit status 4.
# The plugins (refusing_plugins.c) are found through SYLVA_PLUGIN_PATH.
set -uo pipefail
sylva=$1 dir=$2
here=$(cd "$(dirname "$0")" && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0

# run NAME WANT_STATUS COMMAND...: runs COMMAND, keeps its stderr in $out/NAME, checks the status.
run() {
  local name=$1 want=$2
  shift 2
  "$@" >/dev/null 2>"$out/$name"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $name: exit status $got, expected $want:" >&2
    cat "$out/$name" >&2
    fails=$((fails + 1))
  fi
}

# same A B PATTERN: stderr of A and B is one identical line matching the extended regex PATTERN.
same() {
  local a=$1 b=$2 pattern=$3
  echo "$a: $(cat "$out/$a")"
  if [ "$(wc -l <"$out/$a")" -ne 1 ] || ! cmp -s "$out/$a" "$out/$b"; then
    echo "FAIL: $a and $b do not print the same one line:" >&2
    diff "$out/$a" "$out/$b" >&2
    fails=$((fails + 1))
  elif ! grep -Eq -- "$pattern" "$out/$a"; then
    echo "FAIL: $a does not read: $pattern" >&2
    fails=$((fails + 1))
  fi
}

tree=$here/refusing_tree.yaml eco=$here/refusing_ecology.yaml nomem=$here/refusing_tree_nomem.yaml
run render_tree 2 "$sylva" render "$tree" -q -o "$out/tree.png"
run tree_stats 2 "$sylva" tree-stats "$tree" sapling
same render_tree tree_stats \
  "^$tree:6:3: tree plugin 'refusing_tree' for species 'sapling': generate failed: variant 2 of 3 at age 1 with seed [0-9a-f]{16} refused on purpose \(.*refusing_plugins\.so\)$"

run render_ecology 2 "$sylva" render "$eco" -q -o "$out/eco.png"
run simulate 2 "$sylva" simulate "$eco" -q
same render_ecology simulate \
  "^$eco:19:8: ecology plugin 'refusing_ecology': create failed: 'tag': tag 3 refused on purpose; first number of the stream [0-9a-f]{16} \(.*refusing_plugins\.so\)$"

run render_nomem 4 "$sylva" render "$nomem" -q -o "$out/nomem.png"
run tree_stats_nomem 4 "$sylva" tree-stats "$nomem" sapling
same render_nomem tree_stats_nomem "generate failed: out of memory for variant 0 \(on purpose\)"

[ ! -e "$out/tree.png" ] && [ ! -e "$out/eco.png" ] && [ ! -e "$out/nomem.png" ] ||
  { echo "FAIL: an image was written although the render failed" >&2; fails=$((fails + 1)); }
[ "$fails" -eq 0 ] && echo "every plugin failure read the same from each command"
exit $((fails > 0))
