# sheet_lib.sh — what the sheet tests share (sourced by sheet_test.sh and montage_sheet_test.sh):
# poppler's tools and python3 required (the test skipped, 77, without them), a scratch folder
# $out removed at exit, and fail, which reports a check and counts it in $fails.
set -uo pipefail
for tool in pdftotext pdfinfo pdfimages python3; do
  command -v $tool >/dev/null || { echo "SKIP: $tool is missing (scripts/install-deps.sh)"; exit 77; }
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
