#!/usr/bin/env bash
# Configures and builds the default preset (Release, into build/). The binary is build/tracer.
# Arguments go to the build (e.g. --target tracer: the renderer alone, without the tests).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default -j "$(nproc)" "$@"
