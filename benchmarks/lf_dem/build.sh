#!/bin/bash
# Build LF_DEM (dense-suspension Stokesian dynamics with lubrication + contacts) from a source tree.
# usage: build.sh <LF_DEM source dir (the repository root)> [build dir, default /work/lfdem/build]
# Installs the Debian packages it needs (CHOLMOD from SuiteSparse, BLAS/LAPACK), copies the LF_DEM/
# sources into the build dir, writes config/Makefile_config.mk there and runs `make -j1`.
# The binary is <build dir>/LF_DEM. Nothing is written into the source tree.
set -euo pipefail
src=$(cd "${1:?usage: build.sh <LF_DEM source dir> [build dir]}" && pwd)
build=${2:-/work/lfdem/build}
[ -f "$src/LF_DEM/main.cpp" ] || { echo "no LF_DEM/main.cpp under $src" >&2; exit 1; }

need=()
for p in g++ make libsuitesparse-dev liblapack-dev libblas-dev; do
    dpkg -s "$p" >/dev/null 2>&1 || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y "${need[@]}"
fi

version=$(git -C "$src" describe --dirty --always 2>/dev/null || echo unknown)
mkdir -p "$build"
cp -a "$src/LF_DEM/." "$build/"
cat > "$build/config/Makefile_config.mk" <<MK
DSFMT_RNG = no
UseMetis = no
install_dir = $build/
CXX = g++
override_default_cholmod = true
Cholmod_path = -I /usr/include/suitesparse
Cholmod_Linking_Flags = -lcholmod
# The build dir is not a git work tree: pass the source's version explicitly.
CXXFLAGS_EXTRA = -DGIT_VERSION='"$version"'
Blas_Linking_Flags = -lblas
Lapack_Linking_Flags = -llapack
Extra_Linking_Flags =
MK
cd "$build"
make -j1 all
echo "built $build/LF_DEM (LF_DEM $version)"
