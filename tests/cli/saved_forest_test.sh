#!/usr/bin/env bash
# saved_forest_test.sh SYLVA DIR SCENE — a forest kept between renders: SCENE's ecology run,
# saved by `simulate --save`, rendered through `plants: {file: ...}` gives the same image bytes
# as SCENE rendering its own run, says so, and does not simulate; a run saved at another year is
# placed too, and named as such; a state file that is not one is refused at its key.
set -uo pipefail
sylva=$1 dir=$2 scene=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
fail() { echo "$*" >&2; exit 1; }
"$sylva" simulate "$scene" -q --save run.state || fail "simulate --save failed"
{ cat "$scene"; printf 'plants: {file: run.state}\n'; } > saved.yaml
render() { "$sylva" render "$1" --size 48x36 --spp 2 --threads 2 -o "$2"; }
render "$scene" simulated.exr 2> simulated.log || fail "render of the simulating scene failed"
render saved.yaml saved.exr 2> saved.log || { cat saved.log >&2; fail "render of the saved forest failed"; }
cmp -s simulated.exr saved.exr || fail "the saved forest renders differently from the simulated one"
cmp -s simulated.png saved.png || fail "the saved forest's PNG differs"
grep -q "from the ecology run saved in .*run.state (year 70), not simulated again" saved.log ||
  { cat saved.log >&2; fail "render does not say it reuses the saved run"; }
"$sylva" simulate "$scene" -q --years 20 --save young.state || fail "simulate --years 20 failed"
{ cat "$scene"; printf 'plants: {file: young.state}\n'; } > young.yaml
render young.yaml young.png 2> young.log || { cat young.log >&2; fail "render of a younger saved run failed"; }
grep -q "(year 20, not the scene's years)" young.log || { cat young.log >&2; fail "the other year is not named"; }
printf 'not a state\n' > bad.state
{ cat "$scene"; printf 'plants: {file: bad.state}\n'; } > bad.yaml
render bad.yaml bad.png 2> bad.log && fail "a file that is no saved run was accepted"
grep -q "bad.yaml:[0-9]*:16: .*bad.state" bad.log || { cat bad.log >&2; fail "the refusal does not name the file"; }
exit 0
