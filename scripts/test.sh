#!/usr/bin/env bash
# test.sh — the whole test suite: installs dependencies, builds sylva (Release) and runs every
# ctest test, then builds again with AddressSanitizer + UndefinedBehaviorSanitizer and runs the
# suite there too.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"

echo "== Release build"
"$root/scripts/build.sh" "$root/build"
(cd "$root/build" && ctest --output-on-failure -j"$(nproc)")

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build"
"$root/scripts/build.sh" "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSYLVA_SANITIZE=ON
# Embree's and OpenImageIO's own threads keep memory until exit; leaks are checked in sylva's
# code by the tests' own frees, so leak reports from the libraries are suppressed.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export LSAN_OPTIONS=suppressions="$root/tests/lsan.supp"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$root/build-asan" && ctest --output-on-failure -j"$(nproc)")
