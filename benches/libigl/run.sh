#!/usr/bin/env bash
# Builds and runs libigl's C++ peer of `harmonic_report`, `skinning_report` and `arap_report`
# (peer.cpp) the way the issues measure it: g++ -O3 -DNDEBUG, no -march, one thread, Eigen from
# Debian (`apt-get install libeigen3-dev`) and libigl's headers (v2.6.0: `git clone -b v2.6.0
# https://github.com/libigl/libigl`). Nothing of libigl is kept in this repository.
#
#   benches/libigl/run.sh LIBIGL_DIR [MESHES_DIR]
#
# MESHES_DIR defaults to $CGA_DATA_DIR/meshes, else ../shared/data/meshes beside the checkout.
# Run our side in the same window:
#   RAYON_NUM_THREADS=1 cargo run --release -p deform --example harmonic_report
#   RAYON_NUM_THREADS=1 cargo run --release -p deform --example skinning_report dual-quaternion matrix
#   cargo run --release -p deform --example arap_report      (its one-thread rows)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
igl="${1:?usage: run.sh LIBIGL_DIR [MESHES_DIR]}"
root="$(cd "$here/../.." && pwd)"
meshes="${2:-${CGA_DATA_DIR:+$CGA_DATA_DIR/meshes}}"
meshes="${meshes:-$root/../shared/data/meshes}"
[ -f "$igl/include/igl/harmonic.h" ] || { echo "no libigl headers under $igl/include" >&2; exit 2; }
[ -d /usr/include/eigen3 ] || { echo "no Eigen: apt-get install libeigen3-dev" >&2; exit 2; }
version="$(git -C "$igl" describe --tags 2>/dev/null || echo unknown)"
out="$root/target/libigl-peer"
mkdir -p "$(dirname "$out")"
g++ -O3 -DNDEBUG -std=c++17 -DIGL_PEER_VERSION="\"$version\"" -I/usr/include/eigen3 \
  -I"$igl/include" "$here/peer.cpp" -o "$out"
IGL_NUM_THREADS=1 OMP_NUM_THREADS=1 "$out" "$meshes"
