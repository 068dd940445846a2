#!/usr/bin/env bash
# output_is_input_test.sh SYLVA DIR SCENE — no output replaces what the run reads: simulate's -o
# and --save naming the scene file (however spelled: another path, a link), a species file it
# includes, the --load state, or each other, are refused with exit status 1 and both files named,
# and the files stay as they were; an output a command makes in its folder (factors) is refused
# the same way. SCENE is an ecology scene whose species move to an included file here.
set -uo pipefail
sylva=$1 dir=$2 scene=$(realpath "$3")
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "$*" >&2; exit 1; }
# the scene with its species in species.yaml, included
awk '/^species:/{s=1} /^ecology:/{s=0} s' "$scene" > species.yaml
{ awk '/^species:/{s=1} /^ecology:/{s=0} !s' "$scene"; printf 'species: {include: species.yaml}\n'; } > eco.yaml
cp eco.yaml eco.orig && cp species.yaml species.orig
ln -s eco.yaml link.yaml
# refused: expect_refusal FRAGMENT... -- ARGS...: exit 1, every fragment in stderr
refused() {
  local fragments=()
  while [ "$1" != -- ]; do fragments+=("$1"); shift; done
  shift
  "$sylva" "$@" -q 2> err.log && fail "accepted: $*"
  local rc=$?
  [ $rc -eq 1 ] || { cat err.log >&2; fail "exit status $rc, expected 1: $*"; }
  for f in "${fragments[@]}"; do grep -qF -- "$f" err.log || { cat err.log >&2; fail "message lacks '$f': $*"; }; done
  cmp -s eco.yaml eco.orig || fail "the scene file was changed by: $*"
  cmp -s species.yaml species.orig || fail "the included file was changed by: $*"
}
refused "-o: the output 'eco.yaml' is the scene file 'eco.yaml'" -- simulate eco.yaml --years 1 -o eco.yaml
refused "-o: the output './eco.yaml' is the scene file" -- simulate eco.yaml --years 1 -o ./eco.yaml
refused "-o: the output 'link.yaml' is the scene file" -- simulate eco.yaml --years 1 -o link.yaml
refused "--save: the output '../$(basename "$dir")/eco.yaml' is the scene file" -- \
  simulate eco.yaml --years 1 --save "../$(basename "$dir")/eco.yaml"
refused "-o: the output 'species.yaml' is a species file the scene includes" -- \
  simulate eco.yaml --years 1 -o species.yaml
refused "-o 'same.x' and --save 'same.x' are the same file" -- simulate eco.yaml --years 1 -o same.x --save same.x
[ -e same.x ] && fail "same.x was written although the run was refused"
refused "-o 'a.csv' and --save './a.csv' are the same file" -- simulate eco.yaml --years 1 -o a.csv --save ./a.csv
"$sylva" simulate eco.yaml --years 1 -q --save run.state > /dev/null || fail "simulate --save failed"
cp run.state run.orig
refused "-o: the output 'run.state' is the file --load reads" -- simulate eco.yaml --years 1 --load run.state -o run.state
cmp -s run.state run.orig || fail "the loaded state was changed"
# an output folder holding a file the scene reads under a name the command writes
mkdir maps && cp eco.yaml maps/factors.csv && cp species.yaml maps/
refused "the output 'maps/factors.csv' is the scene file 'maps/factors.csv'" -- factors maps/factors.csv -o maps
cmp -s maps/factors.csv eco.orig || fail "factors replaced its scene file"
# different outputs, all written
"$sylva" simulate eco.yaml --years 1 -q -o plants.csv --save other.state > /dev/null || fail "a valid run failed"
[ -s plants.csv ] && [ -s other.state ] || fail "the outputs of a valid run are missing"
exit 0
