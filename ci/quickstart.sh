#!/usr/bin/env bash
# README command 1: install the dependencies, build the renderer (not the tests: ci/test.sh
# builds those), and render the default scene. The CUDA renderer is built where the machine has
# an NVIDIA GPU to run it on; elsewhere the build is the CPU renderer alone (nvcc's share of the
# build is more than half of it), and `bash ci/build.sh` or `bash ci/test.sh` adds the CUDA
# renderer later (the default preset always configures it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh build
if nvidia-smi -L 2>/dev/null | grep -q '^GPU'; then
  cuda=ON
  echo "ci/quickstart.sh: $(nvidia-smi -L | head -1): building the CPU and the CUDA renderer"
else
  cuda=OFF
  echo "ci/quickstart.sh: no NVIDIA GPU on this machine (nvidia-smi lists none): building the CPU renderer;" \
    "'bash ci/build.sh' adds the CUDA renderer"
fi
cmake --preset default -DTRACER_WITH_CUDA="$cuda" >/dev/null
cmake --build --preset default -j "$(nproc)" --target tracer
./build/tracer render scenes/cornell-box.json -o build/cornell-box.png
