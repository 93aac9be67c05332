#!/usr/bin/env bash
# README command 2: install the dependencies, build, and run the whole test suite.
# Extra arguments go to ctest (e.g. -L analytic, -R Philox).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
bash ci/build.sh
bash ci/fetch-gltf-validator.sh
ctest --preset default "$@"
