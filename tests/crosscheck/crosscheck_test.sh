#!/usr/bin/env bash
# crosscheck_test.sh SYLVA SCENE OUTDIR CASE [OPTION...] — one cross-check test
# (tests/crosscheck/CMakeLists.txt). OPTIONs (e.g. --year 15) go to both export-pov and crosscheck.
#   agree            `sylva crosscheck SCENE` passes (exit 0) and writes its report
#   mirror_camera    the export's camera is mirrored (right x instead of right -x)
#   move_object      the export's first object moves 0.3 m along x
#   move_plant       the export's first plant moves 0.3 m along x
#   rotate_instance  the export's first plant turns 25 degrees about its own vertical axis
#   shadowless_sun   the export's sun casts no shadows
#   thin_fog         the export's fog (the physical sky's air) reaches twice as far
#   broken_pov       the export ends in a syntax error
#   before_plan      the export is of the scene before its planting plan (OPTIONs without --year)
#   year_1           the export is of the planting plan 1 year after planting (--year 1)
# Every case but agree edits only the POV-Ray side (the export), then runs the cross-check on
# the edited scene: it must report disagreement (exit 5), or for broken_pov POV-Ray's failure
# (exit 4, with POV-Ray's error line in the message).
set -euo pipefail
sylva=$1 scene=$2 outdir=$3 case=$4
shift 4
options=("$@")
povray=${SYLVA_POVRAY:-povray}
if ! command -v "$povray" >/dev/null; then
  echo "POV-Ray ($povray) is not installed: skipped" >&2
  exit 77
fi
name=$(basename "$scene" .yaml)
dir="$outdir/$name.$case"
rm -rf "$dir"
mkdir -p "$dir"

if [ "$case" = agree ]; then
  "$sylva" crosscheck "$scene" -o "$dir" --quiet "${options[@]}"
  for f in report.html metrics.json sylva.png povray.png difference.png classes.png; do
    [ -s "$dir/$f" ] || { echo "missing $dir/$f" >&2; exit 1; }
  done
  grep -q '"pass": true' "$dir/metrics.json" || { echo "metrics.json does not say pass" >&2; exit 1; }
  exit 0
fi

# before_plan and year_1 export the scene as it stands at another time: the options with
# --year N left out, or with N replaced by 1.
export_options=()
for ((i = 0; i < ${#options[@]}; i++)); do
  if [ "${options[i]}" = --year ] && { [ "$case" = before_plan ] || [ "$case" = year_1 ]; }; then
    i=$((i + 1))
    [ "$case" = year_1 ] && export_options+=(--year 1)
    continue
  fi
  export_options+=("${options[i]}")
done
if [ "$case" = before_plan ] || [ "$case" = year_1 ]; then
  if [ "${export_options[*]}" = "${options[*]}" ]; then
    echo "$case needs the test's options to hold --year N" >&2
    exit 2
  fi
  "$sylva" export-pov "$scene" -o "$dir/unperturbed.pov" --quiet "${options[@]}" >/dev/null
  "$sylva" export-pov "$scene" -o "$dir/$name.pov" --quiet "${export_options[@]}" >/dev/null
  if cmp -s "$dir/${name}_plants.inc" "$dir/unperturbed_plants.inc"; then
    echo "the export for $case places the same plants as the test's year" >&2
    exit 1
  fi
else
"$sylva" export-pov "$scene" -o "$dir/$name.pov" --quiet "${options[@]}" >/dev/null
case "$case" in
  mirror_camera)   file="$dir/$name.pov";        edit='s/^  right -x \*/  right x */' ;;
  move_object)     file="$dir/$name.pov";        edit='0,/^object { O[0-9]/s/^\(object { O[0-9][A-Za-z0-9_]*\) }/\1 translate <0.3, 0, 0> }/' ;;
  move_plant)      file="$dir/${name}_plants.inc"; edit='0,/^object { /s/> }$/> translate <0.3, 0, 0> }/' ;;
  rotate_instance) file="$dir/${name}_plants.inc"; edit='0,/^object { /s/ matrix </ rotate 25*z matrix </' ;;
  shadowless_sun)  file="$dir/$name.pov";        edit='s/^  parallel$/  parallel shadowless/' ;;
  thin_fog)        file="$dir/$name.pov";        edit='s/^  fog { fog_type 1 distance /  fog { fog_type 1 distance 2 * /' ;;
  broken_pov)      file="$dir/$name.pov";        edit='$a sphere { <0, 0, 0> 1 pigment {' ;;
  *) echo "unknown case '$case'" >&2; exit 2 ;;
esac
[ -f "$file" ] || { echo "$file was not exported: the scene has nothing for $case to change" >&2; exit 1; }
cp "$file" "$dir/unperturbed"
sed -i "$edit" "$file"
if cmp -s "$file" "$dir/unperturbed"; then
  echo "the $case edit changed nothing in $file" >&2
  exit 1
fi
fi
set +e
"$sylva" crosscheck "$scene" -o "$dir" --pov "$dir/$name.pov" --quiet "${options[@]}" 2>"$dir/stderr.txt"
rc=$?
set -e
cat "$dir/stderr.txt" >&2
if [ "$case" = broken_pov ]; then
  if [ "$rc" -ne 4 ] || ! grep -q "Parse Error" "$dir/stderr.txt"; then
    echo "expected POV-Ray's parse error (exit 4) from the broken export, got exit $rc" >&2
    exit 1
  fi
  exit 0
fi
if [ "$rc" -ne 5 ]; then
  echo "expected the cross-check to report disagreement (exit 5) after $case, got exit $rc" >&2
  exit 1
fi
