#!/usr/bin/env bash
# expect_failure.sh STATUS FRAGMENT OUTPUT -- COMMAND... — runs COMMAND and checks that it
# exits with STATUS, that its stderr contains FRAGMENT, and that OUTPUT was not written.
set -uo pipefail
want=$1 fragment=$2 output=$3
shift 4
rm -f "$output"
err=$("$@" 2>&1 >/dev/null)
got=$?
echo "$err"
[ "$got" -eq "$want" ] || { echo "exit status $got, expected $want" >&2; exit 1; }
grep -qF -- "$fragment" <<<"$err" || { echo "message lacks: $fragment" >&2; exit 1; }
[ ! -e "$output" ] || { echo "$output was written although the run failed" >&2; exit 1; }
ls "$(dirname "$output")" | grep -q '\.tmp-' && { echo "a temporary file was left behind" >&2; exit 1; }
exit 0
