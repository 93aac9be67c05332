#!/usr/bin/env bash
# CI's extra jobs after the README's test command (ci/test.sh): the second compiler (clang)
# rendering every golden bit for bit; the sanitizer build running the unit, analytic, extremes
# and determinism labels under ASan + UBSan with no recovery; the libFuzzer targets, 60 s each
# (docs/fuzzing.md). All build the CPU renderer only; the dependencies are those of
# ci/install-deps.sh. Arguments pick presets (default: clang asan fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(clang asan fuzz)
for preset in "${presets[@]}"; do
  echo "== $preset: configure, build, test"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$(nproc)"
  ctest --preset "$preset"
done
