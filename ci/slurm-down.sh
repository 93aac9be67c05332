#!/usr/bin/env bash
# Stops exactly the daemons ci/slurm-up.sh started (the pids in
# $TRACER_SLURM_DIR/started.pids), waits for them to exit, and removes the directory.
set -uo pipefail
dir=${TRACER_SLURM_DIR:-/tmp/tracer-slurm}
[ -f "$dir/started.pids" ] || { echo "slurm-down: nothing started in $dir"; exit 0; }
pids=$(cat "$dir/started.pids")
for pid in $pids; do kill "$pid" 2>/dev/null; done
for _ in $(seq 100); do
  alive=0
  for pid in $pids; do kill -0 "$pid" 2>/dev/null && alive=1; done
  [ $alive = 0 ] && break
  sleep 0.1
done
for pid in $pids; do kill -9 "$pid" 2>/dev/null; done
rm -rf "$dir"
echo "slurm-down: stopped $(echo $pids | wc -w) daemons"
