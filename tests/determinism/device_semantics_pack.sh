#!/usr/bin/env bash
# The device-semantics build's check (docs/cuda.md): the GPU pack written by a host-semantics
# tracer (its parity answers are the host's), run on the CPU by this build's runner, whose
# kernel code follows the GPU's min/max rules. Every golden hash and parity answer must match.
# Arguments: REFERENCE_TRACER RUNNER SOURCE_ROOT PACK_DIR
set -euo pipefail
reference=$1 runner=$2 root=$3 dir=$4
if [ ! -x "$reference" ]; then
  echo "no host-semantics tracer at '$reference': build the default preset first (bash ci/build.sh)" >&2
  exit 1
fi
rm -rf "$dir"
"$reference" gpu-pack "$dir" --root "$root" --runner "$runner"
"$dir/run.sh" --device cpu
