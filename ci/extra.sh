#!/usr/bin/env bash
# CI's extra jobs after the README's test command (ci/test.sh): the second compiler (clang)
# running the unit, analytic, extremes, determinism and golden labels (every golden bit for
# bit); the sanitizer build running the unit, analytic, extremes and determinism labels under
# ASan + UBSan with no recovery; the device-semantics build (the GPU's min/max rules in host
# kernel code, docs/cuda.md) rendering every golden and running the GPU pack that the default
# build writes; the libFuzzer targets, 60 s each (docs/fuzzing.md); the `slurm` label against
# a one-node cluster started by ci/slurm-up.sh and stopped by ci/slurm-down.sh
# (docs/distributed.md); the mutation campaign's sample (ci/mutation.py --sample, a few
# mutants of different features, each killed without the goldens: docs/mutation.md).
# device-semantics and slurm use the default build of ci/test.sh.
# The presets build the CPU renderer only; the dependencies are those of ci/install-deps.sh.
# Arguments pick jobs (default: clang asan device-semantics fuzz slurm mutation).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=("$@")
[ ${#jobs[@]} -gt 0 ] || jobs=(clang asan device-semantics fuzz slurm mutation)
for job in "${jobs[@]}"; do
  started=$SECONDS
  if [ "$job" = slurm ]; then
    echo "== slurm: one-node cluster, ctest -L slurm"
    trap 'bash ci/slurm-down.sh' EXIT
    if bash ci/slurm-up.sh; then
      # shellcheck disable=SC1091
      . "${TRACER_SLURM_DIR:-/tmp/tracer-slurm}/env"
    else
      echo "slurm: the cluster did not start; the slurm tests report themselves skipped"
    fi
    ctest --test-dir build -L slurm --output-on-failure
    bash ci/slurm-down.sh
    trap - EXIT
    echo "== slurm: done in $((SECONDS - started)) s"
    continue
  fi
  if [ "$job" = mutation ]; then
    echo "== mutation: the campaign's sample in a scratch clone"
    python3 ci/mutation.py --sample
    echo "== mutation: done in $((SECONDS - started)) s"
    continue
  fi
  echo "== $job: configure, build, test"
  cmake --preset "$job" >/dev/null
  cmake --build --preset "$job" -j "$(nproc)"
  ctest --preset "$job"
  echo "== $job: done in $((SECONDS - started)) s"
done
