#!/usr/bin/env bash
# run_fuzz.sh TARGET WORK_DIR [libFuzzer options...] — runs the fuzz target TARGET
# (fuzz_scene_load or fuzz_lsystem, built with -DSYLVA_FUZZ=ON) from its seeds with its
# dictionary and input size limit. New inputs go to WORK_DIR/corpus, a crashing input to
# WORK_DIR/crash-* (libFuzzer's artifacts). Seeds:
#   scene_load  scenes/, tests/scenes/ (with the bad-scene corpus), tests/fuzz/regressions/scene_load/
#   lsystem     tests/fuzz/seeds/lsystem/, the .ls files of $SYLVA_SHARED_DATA_DIR/lparser
#               (default ../shared/data beside the clone) when present,
#               tests/fuzz/regressions/lsystem/
# Exits 0 when nothing was found, 1 when an input crashed, leaked, hung or tripped a sanitizer
# (libFuzzer's own status for that is 77, which ctest reads as "skipped").
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=$1 work=$2
shift 2
name=$(basename "$target")
name=${name#fuzz_}
mkdir -p "$work/corpus"
# The scene target writes each input to a scratch file: keep it in memory where there is a tmpfs.
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi

seeds=()
case $name in
  scene_load)
    seeds+=("$root/scenes" "$root/tests/scenes")
    max_len=16384 ;;
  lsystem)
    seeds+=("$here/seeds/lsystem")
    shared=${SYLVA_SHARED_DATA_DIR:-$root/../shared/data}/lparser
    if [ -d "$shared" ]; then
      # Only the L-parser files: the folder also holds reference renders and papers.
      rm -rf "$work/seeds-lparser"
      mkdir -p "$work/seeds-lparser"
      find "$shared" -name '*.ls' -type f | while read -r f; do
        cp "$f" "$work/seeds-lparser/$(basename "$(dirname "$f")")-$(basename "$f")"
      done
      seeds+=("$work/seeds-lparser")
    else
      echo "run_fuzz.sh: $shared is absent; seeding from tests/fuzz/seeds/lsystem alone" >&2
    fi
    max_len=4096 ;;
  *)
    echo "run_fuzz.sh: unknown target $target (fuzz_scene_load or fuzz_lsystem)" >&2
    exit 2 ;;
esac
[ -d "$here/regressions/$name" ] && seeds+=("$here/regressions/$name")

exec "$target" -dict="$here/$name.dict" -max_len="$max_len" -timeout=10 -error_exitcode=1 -timeout_exitcode=1 \
     -print_final_stats=1 \
     -artifact_prefix="$work/" "$@" "$work/corpus" "${seeds[@]}"
