#!/usr/bin/env bash
# mpi_test.sh CASE SYLVA SCENES_DIR — `sylva render`, `sylva ztv` and `sylva study` under mpirun on this machine
# (docs/mpi.md). Skipped (77) without mpirun. Cases:
#   render    scenes rendered by 2 and 4 ranks (and 3 and 1 on a frame of fewer bands than
#             ranks) give the PNG and the EXR of a plain run, byte for byte; the plain run of
#             this build (no mpirun, so no MPI) prints what it always did
#   ztv       maps traced by 2 and 4 ranks (and 3), one block of rows and two, give every file
#             of a plain run byte for byte
#   study     a study rendered by 2 and 3 ranks (whole images each) writes every file of a plain
#             run, byte for byte, its ZTV (rows shared) and index too; a rerun on 2 ranks renders
#             the one product deleted, alone
#   failures  a failure ends every rank with one message and the right exit status, never a
#             hang: rank 0 cannot write (render, ztv), one rank alone is refused by its memory
#             budget (render: its frame, while rank 0 waits to gather; ztv: the scene file,
#             while rank 0 traces), the ranks were given different arguments, or the same ones
#             that name another scene file on one rank (render, ztv)
set -uo pipefail
case=$1 sylva=$2 scenes=$3
command -v mpirun >/dev/null || { echo "no mpirun: skipped"; exit 77; }
mpi=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
# plain COMMAND...: without any launcher's variables, as a user types it
plain() { env -u OMPI_COMM_WORLD_SIZE -u PMI_SIZE -u PMIX_SIZE -u PMIX_RANK "$@"; }
# ranks N COMMAND...: an MPI job of N ranks, stopped after 120 s (a hang is a failure)
ranks() { local n=$1; shift; timeout 120 "${mpi[@]}" -np "$n" "$@"; }

case $case in
render)
  # name scene size: one plain run, then the ranks
  for job in "forest ecology_forest.yaml 100x70" "models imported_models.yaml 72x40" \
             "grass foreground_grass.yaml 64x40" "few sphere_on_plane.yaml 40x20"; do
    read -r name scene size <<<"$job"
    args=(render "$scenes/image/$scene" --size "$size" --spp 4)
    plain "$sylva" "${args[@]}" --threads 2 -o "$out/$name.png" >"$out/$name.stdout" 2>"$out/$name.stderr" ||
      fail "$name: the plain run exited with $?"
    grep -q "^rendered $size, " "$out/$name.stderr" || fail "$name: the plain run's summary line changed"
    [ "$(cat "$out/$name.stdout")" = "$out/$name.png
$out/$name.exr" ] || fail "$name: the plain run's stdout changed"
    for n in 2 4 $([ $name = few ] && echo 3 1); do
      threads=$([ $n = 2 ] && echo 2 || echo 1)
      ranks $n "$sylva" "${args[@]}" --threads $threads -o "$out/$name.$n.png" >"$out/$name.$n.stdout" \
        2>"$out/$name.$n.stderr" || fail "$name: $n ranks exited with $?"
      for ext in png exr; do
        cmp "$out/$name.$ext" "$out/$name.$n.$ext" || fail "$name.$ext: $n ranks differ from one process"
      done
      # rank 0 alone prints: one summary line, the two paths once
      summary="^rendered $size on $n ranks, "
      [ $n = 1 ] && summary="^rendered $size, "
      [ "$(grep -c "$summary" "$out/$name.$n.stderr")" = 1 ] ||
        fail "$name: $n ranks printed no summary line or more than one"
      [ "$(wc -l <"$out/$name.$n.stdout")" = 2 ] || fail "$name: $n ranks printed the paths more than once"
    done
  done
  ;;
ztv)
  site=$scenes/ztv/small_site.yaml
  # 61 x 61 cells: one block of rows; 527 x 527 cells of 0.57 m: two (ZTV_BLOCK_CELLS), the second
  # starting at row 497, which no rank count here divides
  for job in "one 5" "two 0.57"; do
    read -r name cell <<<"$job"
    plain "$sylva" ztv "$site" --cell "$cell" --threads 2 -q -o "$out/$name" >/dev/null ||
      fail "ztv $name: the plain run exited with $?"
    for n in 2 4 $([ $name = one ] && echo 3); do
      ranks $n "$sylva" ztv "$site" --cell "$cell" --threads 1 -q -o "$out/$name.$n" >"$out/$name.$n.stdout" ||
        fail "ztv $name: $n ranks exited with $?"
      [ "$(ls "$out/$name")" = "$(ls "$out/$name.$n")" ] || fail "ztv $name: $n ranks wrote other files"
      for f in "$out/$name"/*; do
        cmp "$f" "$out/$name.$n/${f##*/}" || fail "ztv $name: ${f##*/} differs with $n ranks"
      done
      [ "$(cat "$out/$name.$n.stdout")" = "$out/$name.$n" ] || fail "ztv $name: stdout of $n ranks"
    done
  done
  ;;
study)
  # whole images shared between the ranks, the map's rows too: every file of a plain run, byte for byte; rank 0
  # alone prints; a rerun with one product deleted renders it alone
  scene=$scenes/study/hill_study.yaml
  args=(study "$scene" --frames single,planar_53 --products existing,proposed,wireline,ztv)
  plain "$sylva" "${args[@]}" --threads 2 -q -o "$out/one" >/dev/null || fail "study: the plain run exited with $?"
  for n in 2 3; do
    ranks $n "$sylva" "${args[@]}" --threads 1 -o "$out/s$n" >"$out/s$n.stdout" 2>"$out/s$n.stderr" ||
      fail "study: $n ranks exited with $?"
    diff -r "$out/one" "$out/s$n" >/dev/null || fail "study: $n ranks wrote other files than one process"
    [ "$(grep -c "^study (rank 0 of $n): " "$out/s$n.stderr")" = 1 ] || fail "study: $n ranks: no summary, or more"
    [ "$(cat "$out/s$n.stdout")" = "$out/s$n" ] || fail "study: stdout of $n ranks"
  done
  sleep 1
  touch "$out/mark"
  rm "$out/s2/south/wireline_planar_53.exr"
  ranks 2 "$sylva" "${args[@]}" --threads 1 -q -o "$out/s2" >/dev/null || fail "study: the rerun on 2 ranks exited with $?"
  newer=$(cd "$out/s2" && find . -type f -newer "$out/mark" | sort | tr '\n' ' ')
  [ "$newer" = "./south/wireline_planar_53.exr ./south/wireline_planar_53.manifest ./south/wireline_planar_53.png " ] ||
    fail "study: the rerun on 2 ranks rewrote '$newer'"
  diff -r "$out/one" "$out/s2" >/dev/null || fail "study: after the rerun, 2 ranks' files differ from one process's"
  ;;
failures)
  scene=$scenes/image/sphere_on_plane.yaml site=$scenes/ztv/small_site.yaml
  # expect NAME STATUS FRAGMENT COMMAND...: exits with STATUS, FRAGMENT once on stderr
  expect() {
    local name=$1 want=$2 fragment=$3
    shift 3
    "$@" >/dev/null 2>"$out/err"
    local got=$?
    [ $got = "$want" ] || fail "$name: exit status $got, expected $want: $(cat "$out/err")"
    [ "$(grep -cF -- "$fragment" "$out/err")" = 1 ] || fail "$name: '$fragment' not printed once: $(cat "$out/err")"
  }
  expect "render, rank 0 cannot write" 3 "no/such/folder" \
    ranks 3 "$sylva" render "$scene" --size 40x30 --spp 2 -o "$out/no/such/folder/x.png"
  touch "$out/file"
  expect "ztv, rank 0 cannot make the folder" 3 "$out/file" \
    ranks 3 "$sylva" ztv "$site" -q -o "$out/file/maps"
  # the same arguments, but rank 1 may plan for 1 MB only: its frame or its map is refused
  expect "render, rank 1 out of budget" 4 "[rank 1 of 2] sylva render: a 400x300 frame needs" \
    ranks 1 "$sylva" render "$scene" --size 400x300 --spp 1 -q -o "$out/budget.png" : \
    -np 1 env SYLVA_MEMORY_LIMIT=1M "$sylva" render "$scene" --size 400x300 --spp 1 -q -o "$out/budget.png"
  [ -e "$out/budget.png" ] && fail "render, rank 1 out of budget: budget.png was written"
  expect "ztv, rank 1 out of budget" 2 "[rank 1 of 2] " \
    ranks 1 "$sylva" ztv "$site" -q -o "$out/budget" : -np 1 env SYLVA_MEMORY_LIMIT=1K "$sylva" ztv "$site" -q -o "$out/budget"
  ls "$out/budget" 2>/dev/null | grep -q . && fail "ztv, rank 1 out of budget: files were written"
  expect "ranks given different arguments" 1 "not started with the same arguments" \
    ranks 1 "$sylva" render "$scene" --size 40x30 --spp 2 -o "$out/args.png" : \
    -np 1 "$sylva" render "$scene" --size 40x31 --spp 2 -o "$out/args.png"
  [ -e "$out/args.png" ] && fail "ranks given different arguments: args.png was written"
  # the same arguments, but rank 1's working folder holds another scene.yaml (a bigger ball)
  mkdir -p "$out/a" "$out/b"
  cp "$scene" "$out/a/scene.yaml"
  sed 's/radius: 1,/radius: 1.2,/' "$scene" >"$out/b/scene.yaml"
  for job in "render other.png" "ztv other_maps"; do
    read -r cmd output <<<"$job"
    expect "$cmd, rank 1 sees another scene" 2 "rank 1 of the 2 ranks built another scene than rank 0" \
      ranks 1 -wdir "$out/a" "$sylva" $cmd scene.yaml -q -o "$out/$output" : \
      -np 1 -wdir "$out/b" "$sylva" $cmd scene.yaml -q -o "$out/$output"
    [ -e "$out/$output" ] && fail "$cmd, rank 1 sees another scene: $output was written"
  done
  # and with the same scene on both, the same job goes through
  cp "$scene" "$out/b/scene.yaml"
  ranks 1 -wdir "$out/a" "$sylva" render scene.yaml --size 40x30 --spp 2 -q -o "$out/same.png" : \
    -np 1 -wdir "$out/b" "$sylva" render scene.yaml --size 40x30 --spp 2 -q -o "$out/same.png" >/dev/null 2>&1 ||
    fail "render, the same scene in two folders: exit status $?"
  ;;
*)
  echo "mpi_test.sh: unknown case '$case'" >&2
  exit 2
  ;;
esac
[ $fails -eq 0 ] && echo "mpi $case: as expected"
exit $((fails > 0))
