#!/usr/bin/env bash
# run_fuzz.sh TARGET WORK_DIR [libFuzzer options...] — runs the fuzz target TARGET (one of
# tests/fuzz/fuzz_*.c, built with -DSYLVA_FUZZ=ON) from its seeds with its dictionary and input
# size limit. New inputs go to WORK_DIR/corpus, a crashing input to WORK_DIR/crash-* (libFuzzer's
# artifacts). Seeds:
#   scene_load      scenes/, tests/scenes/ (with the bad-scene corpus)
#   lsystem         tests/fuzz/seeds/lsystem/, the .ls files of $SYLVA_SHARED_DATA_DIR/lparser
#                   (default ../shared/data beside the clone) when present
#   model_import    tests/fuzz/seeds/model_import/, the OBJ, STL, PLY, glTF and GLB files of
#                   $SYLVA_SHARED_DATA_DIR/models under 64 KiB when present (each copied with the
#                   first byte that chooses its format)
#   the others      tests/fuzz/seeds/<target>/
# and every target its regression inputs, tests/fuzz/regressions/<target>/.
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
# The targets write each input to a scratch file: keep it in memory where there is a tmpfs.
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi

shared_data=${SYLVA_SHARED_DATA_DIR:-$root/../shared/data}
seeds=()
# shared_seeds SUBFOLDER FIND_TESTS...: the files of the shared data's SUBFOLDER that the find
# tests select, each put into $work/seeds-SUBFOLDER by the target's copy_seed FILE FOLDER, added
# to the seeds; nothing (a note) when the folder is absent.
shared_seeds() {
  local from=$shared_data/$1 to=$work/seeds-$1
  shift
  if [ ! -d "$from" ]; then
    echo "run_fuzz.sh: $from is absent; seeding from tests/fuzz/seeds/$name alone" >&2
    return 0
  fi
  rm -rf "$to"
  mkdir -p "$to"
  find "$from" -type f "$@" | while read -r f; do copy_seed "$f" "$to"; done
  seeds+=("$to")
}
case $name in
  scene_load)
    seeds+=("$root/scenes" "$root/tests/scenes")
    max_len=16384 ;;
  lsystem)
    seeds+=("$here/seeds/lsystem")
    # Only the L-parser files: the folder also holds reference renders and papers.
    copy_seed() { cp "$1" "$2/$(basename "$(dirname "$1")")-$(basename "$1")"; }
    shared_seeds lparser -name '*.ls'
    max_len=4096 ;;
  layout_csv|control_points|tree_survey)
    seeds+=("$here/seeds/$name")
    max_len=4096 ;;
  weber_penn)
    seeds+=("$here/seeds/weber_penn")
    max_len=8192 ;;
  photo)
    seeds+=("$here/seeds/photo")
    max_len=16384 ;;
  ecology_state)
    seeds+=("$here/seeds/ecology_state")
    max_len=16384 ;;
  model_import)
    seeds+=("$here/seeds/model_import")
    # The input's first byte chooses the format (fuzz_model_import.c): 0 OBJ, 1 STL, 2 PLY,
    # 3 glTF, 4 GLB.
    copy_seed() {
      local k
      case ${1##*.} in obj|OBJ) k=0 ;; stl|STL) k=1 ;; ply|PLY) k=2 ;; gltf|GLTF) k=3 ;; *) k=4 ;; esac
      { printf "\\$k"; cat "$1"; } > "$2/$(basename "$1")"
    }
    shared_seeds models -size -64k \( -iname '*.obj' -o -iname '*.stl' -o -iname '*.ply' -o -iname '*.gltf' \
                 -o -iname '*.glb' \)
    max_len=65536 ;;
  *)
    echo "run_fuzz.sh: unknown target $target (see tests/fuzz/fuzz_*.c)" >&2
    exit 2 ;;
esac
[ -d "$here/regressions/$name" ] && seeds+=("$here/regressions/$name")

# Leaks inside the third-party libraries (tests/lsan.supp) are theirs, matched by the library's
# name in the leak's call stack.
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
dict=()
[ -f "$here/$name.dict" ] && dict=(-dict="$here/$name.dict")
exec "$target" "${dict[@]}" -max_len="$max_len" -timeout=10 -error_exitcode=1 -timeout_exitcode=1 \
     -print_final_stats=1 \
     -artifact_prefix="$work/" "$@" "$work/corpus" "${seeds[@]}"
