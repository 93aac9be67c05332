#!/usr/bin/env bash
# The cost of splitting a render over Slurm (docs/distributed.md). The scene is rendered once
# with `tracer render` on all cores and once with --threads 1 (T1), then through `tracer slurm
# submit --parts N --wait` for N = 1, 2, 4, 8 with one CPU per task, each merged image checked
# bit for bit against the single render. With C CPUs the N tasks run in ceil(N/C) waves, so an
# ideal split takes T1 / N x ceil(N/C); the table gives the wall time, that ideal, the
# overhead (wall - ideal) and the overhead per wave of tasks. Prints a markdown table.
# Usage: ci/slurm-overhead.sh SCENE [render options...]   (needs SLURM_CONF: ci/slurm-up.sh)
set -euo pipefail
tracer=${TRACER:-build/tracer}
scene=$1
shift
cpus=$(nproc)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
now() { date +%s.%N; }
calc() { awk "BEGIN { printf \"%.2f\", $1 }"; }
timed_render() {
  local t0
  t0=$(now)
  "$tracer" render "$scene" "$@" --quiet >/dev/null
  calc "$(now) - $t0"
}
single=$(timed_render "$@" -o "$work/single.exr")
t1=$(timed_render "$@" --threads 1 -o "$work/single-1.exr")
echo "single render: $single s on $cpus CPUs, $t1 s on 1 CPU"
echo
echo "| parts | waves of $cpus tasks | wall s | ideal s | overhead s | overhead per wave s |"
echo "| --- | --- | --- | --- | --- | --- |"
for parts in 1 2 4 8; do
  t0=$(now)
  "$tracer" slurm submit "$scene" "$@" --parts "$parts" --dir "$work/job-$parts" -o "$work/merged-$parts.exr" \
    --wait >/dev/null
  wall=$(calc "$(now) - $t0")
  "$tracer" compare "$work/merged-$parts.exr" "$work/single.exr" --fail 0 >/dev/null
  waves=$(((parts + cpus - 1) / cpus))
  ideal=$(calc "$t1 / $parts * $waves")
  echo "| $parts | $waves | $wall | $ideal | $(calc "$wall - $ideal") | $(calc "($wall - $ideal) / $waves") |"
done
