#!/usr/bin/env bash
# install-deps.sh — installs sylva's build and test dependencies from Debian 12's archive.
# Idempotent: installs only what is missing. Uses sudo when not run as root.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  clang libclang-rt-dev  # the clang build and the libFuzzer targets (tests/fuzz)
  libembree-dev          # Embree 3: ray tracing kernels
  libopenexr-dev         # OpenEXR Core C API: EXR output
  libopenimageio-dev openimageio-tools  # PNG output, image reading and comparison
  libyaml-dev            # scene files
  libgdal-dev            # DTM input (terrain plugin), a site's CRS from its DTM
  gdal-bin               # gdal_viewshed: the bare-earth oracle of the ZTV tests and benchmark
  libproj-dev            # site CRS: EPSG codes, WKT, longitude/latitude to map coordinates
  povray                 # cross-check renders
  libassimp-dev          # 3-D model import (OBJ, glTF, PLY, STL, FBX, COLLADA, 3DS)
  libgsl-dev             # photomontage camera match: nonlinear least squares (multifit_nlinear)
  libimage-exiftool-perl # exiftool: the EXIF tests compare what sylva reads with what it reports
  libcairo2-dev libpango1.0-dev  # study sheets and ZTV maps: vector PDF and PNG, real fonts
  libpng-dev             # the pages' PNGs written straight through libpng (src/core/io/png_write.c)
  fonts-dejavu-core      # the sheets' and maps' typeface
  valgrind               # Assimp's own heap writes, which the sanitizers cannot see (unit.model_import_valgrind)
  poppler-utils          # pdfinfo, pdfimages, pdftotext: the sheet tests read the PDFs back
  libopenmpi-dev openmpi-bin  # MPI: render and ztv split between ranks (docs/mpi.md); optional
  chromium fonts-dejavu-core  # the study's index.html opened headless by its test (cli.study_index)
)
case ${1:-} in
  --bench) packages+=(blender) ;;  # never a build or test dependency
  "") ;;
  *) echo "usage: $0 [--bench]" >&2; exit 1 ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
