#!/usr/bin/env bash
# readme_usage_test.sh SYLVA README — README.md's usage lines are the commands' own: for every
# command `sylva --help` lists, the first line of `sylva CMD --help` (its synopsis, printed from
# the command's option table) stands in README.md as "    build/sylva CMD ...", word for word.
sylva=$1 readme=$2
cmds=$("$sylva" --help | awk '/^commands:/{on=1; next} on && /^  [a-z]/{print $1}')
[ -n "$cmds" ] || { echo "FAIL: sylva --help lists no commands" >&2; exit 1; }
bad=0
for c in $cmds; do
  line=$("$sylva" "$c" --help | head -1)
  synopsis=${line#usage: }
  [ "$synopsis" != "$line" ] || { echo "FAIL: sylva $c --help does not start with 'usage: '" >&2; bad=1; continue; }
  grep -qxF "    build/$synopsis" "$readme" ||
    { echo "FAIL: README.md lacks the usage line of sylva $c:" >&2; echo "    build/$synopsis" >&2; bad=1; }
done
exit $bad
