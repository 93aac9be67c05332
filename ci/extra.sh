#!/usr/bin/env bash
# CI's extra jobs after the README's test command (ci/test.sh): the sanitizer build running
# the unit, analytic, extremes and determinism labels under ASan + UBSan with no recovery,
# and the second compiler (clang) rendering every golden bit for bit. Both build the CPU
# renderer only; the dependencies are those of ci/install-deps.sh. Arguments pick presets
# (default: asan clang).
set -euo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(asan clang)
for preset in "${presets[@]}"; do
  echo "== $preset: configure, build, test"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(nproc)"
  ctest --preset "$preset"
done
