#!/usr/bin/env bash
# CI's extra jobs after the README's test command (ci/test.sh):
#  - sanitize: one clang build with ASan + UBSan (no recovery) and the libFuzzer targets; it
#    runs the unit, analytic, extremes, determinism and golden labels (the second compiler
#    renders every golden bit for bit, under the sanitizers) and the fuzz label (each libFuzzer
#    target for 30 s, docs/fuzzing.md);
#  - slurm: the `slurm` label against a one-node cluster started by ci/slurm-up.sh and stopped
#    by ci/slurm-down.sh (docs/distributed.md);
#  - mutation: the mutation campaign's sample (ci/mutation.py --sample, a few mutants of
#    different features, each killed without the goldens: docs/mutation.md).
# slurm uses the default build of ci/test.sh.
# The presets build the CPU renderer only; the dependencies are those of ci/install-deps.sh.
# Arguments pick jobs (default: sanitize slurm mutation).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=("$@")
[ ${#jobs[@]} -gt 0 ] || jobs=(sanitize slurm mutation)
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
  echo "== $job: built in $((SECONDS - started)) s"
  ctest --preset "$job"
  echo "== $job: done in $((SECONDS - started)) s"
done
