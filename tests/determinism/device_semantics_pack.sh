#!/usr/bin/env bash
# Device semantics on the host (docs/cuda.md): the GPU pack the tracer wrote (the fixture
# gpu-pack.write; its parity answers are the host's), run on the CPU by the runner whose kernel
# code follows the GPU's min/max rules, in a copy of the pack. Every golden hash and parity
# answer must match.
# Arguments: PACK_DIR DEVICE_SEMANTICS_RUNNER COPY_DIR
set -euo pipefail
pack=$1 runner=$2 dir=$3
rm -rf "$dir"
cp -r "$pack" "$dir"
cp "$runner" "$dir/tracer-gpu"
"$dir/run.sh" --device cpu
