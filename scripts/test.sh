#!/usr/bin/env bash
# test.sh — the whole test suite: installs the dependencies, then builds sylva four ways and
# tests each (15 to 20 minutes on 2 cores):
#   build/        gcc, Release, with MPI: every ctest test (the mpi ones with mpirun)
#   build-asan/   gcc, AddressSanitizer + UndefinedBehaviorSanitizer: every test but the slow ones
#   build-clang/  clang, Release, warnings as errors, without MPI (SYLVA_MPI=OFF, as on a machine
#                 without Open MPI): every test but the slow ones
#   build-fuzz/   clang with libFuzzer: each fuzz target for a short fixed number of runs
# Stops at the first build or stage that fails. Tests that cannot run here (no POV-Ray, no
# ../shared/data) are reported as skipped.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
jobs=$(nproc)
start=$SECONDS
stage() { echo "== $* ($((SECONDS - start)) s)"; }

stage "gcc Release build"
"$root/scripts/build.sh" "$root/build"
(cd "$root/build" && ctest --output-on-failure -j"$jobs")

# Embree's and OpenImageIO's own threads and fontconfig's cache keep memory until exit; leaks are
# checked in sylva's code by the tests' own frees, so leak reports from the libraries are
# suppressed, without the table of suppressions used (tests check that -q leaves stderr empty).
# OpenImageIO lives in a module opened with dlopen, so its thread-local storage is dynamic: the
# leak checker's walk of dynamic TLS (through __tls_get_addr) crashes on it when the process
# exits with threads still about, so that walk is off.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0
export LSAN_OPTIONS=suppressions="$root/tests/lsan.supp":print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

stage "gcc AddressSanitizer + UndefinedBehaviorSanitizer build"
"$root/scripts/build.sh" "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSYLVA_SANITIZE=ON
(cd "$root/build-asan" && ctest --output-on-failure -j"$jobs" -LE slow)

stage "clang Release build, warnings as errors, without MPI"
CC=clang CXX=clang++ "$root/scripts/build.sh" "$root/build-clang" -DSYLVA_WERROR=ON -DSYLVA_MPI=OFF
(cd "$root/build-clang" && ctest --output-on-failure -j"$jobs" -LE slow)

stage "clang libFuzzer build: short fuzz runs"
CC=clang CXX=clang++ cmake -S "$root" -B "$root/build-fuzz" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSYLVA_FUZZ=ON >/dev/null
cmake --build "$root/build-fuzz" -j"$jobs" --target fuzz_scene_load fuzz_lsystem fuzz_weber_penn fuzz_layout_csv \
      fuzz_control_points fuzz_tree_survey fuzz_photo fuzz_model_import fuzz_ecology_state
(cd "$root/build-fuzz" && ctest --output-on-failure -j"$jobs" -L fuzz)

stage "all passed"
