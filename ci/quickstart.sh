#!/usr/bin/env bash
# README command 1: install the dependencies, build the renderer (not the tests: ci/test.sh
# builds those), and render the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh build
bash ci/build.sh --target tracer
./build/tracer render scenes/cornell-box.json -o build/cornell-box.png
