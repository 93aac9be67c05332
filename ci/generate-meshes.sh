#!/usr/bin/env bash
# Writes the benchmark meshes into scenes/generated/ (not committed): deterministic
# procedural stand-ins for the reference designs' test scenes, made by `tracer generate`,
# and the Stanford bunny (ci/fetch-bunny.sh). Then e.g.:
#   build/tracer bench rays scenes/generated/terrain-1m.obj
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bash "$root/ci/build.sh"
dir="$root/scenes/generated"
mkdir -p "$dir"
make_mesh() {  # name kind triangles
  [ -f "$dir/$1.obj" ] || "$root/build/tracer" generate "$2" --triangles "$3" -o "$dir/$1.obj"
}
make_mesh three-boxes boxes 36          # the stream tracer's three boxes
make_mesh room-cubes cubes 2000         # cubes spread through a room
make_mesh mixed-60k mixed 60000         # high- and low-polygon objects together
make_mesh sphere-33k sphere 33000       # where the Whitted design used Lucy
make_mesh sphere-100k sphere 100000     # and the dragon
make_mesh terrain-1m terrain 1000000    # a one-million-triangle sine-sum terrain
bash "$root/ci/fetch-bunny.sh"
