#!/usr/bin/env bash
# Device semantics on the host (docs/cuda.md): the GPU pack written by the tracer (its parity
# answers are the host's), run on the CPU by the runner whose kernel code follows the GPU's
# min/max rules. Every golden hash and parity answer must match.
# Arguments: TRACER DEVICE_SEMANTICS_RUNNER SOURCE_ROOT PACK_DIR
set -euo pipefail
tracer=$1 runner=$2 root=$3 dir=$4
rm -rf "$dir"
"$tracer" gpu-pack "$dir" --root "$root" --runner "$runner"
"$dir/run.sh" --device cpu
