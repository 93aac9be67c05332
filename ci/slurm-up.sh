#!/usr/bin/env bash
# Starts a one-node Slurm cluster on this machine for the `slurm` test label
# (docs/distributed.md): installs slurm-wlm and munge from Debian, writes a slurm.conf under
# $TRACER_SLURM_DIR (default /tmp/tracer-slurm: proctrack/linuxproc, task/none,
# select/cons_tres, no accounting), starts munged (unless one runs), slurmctld and slurmd as
# root without systemd, and waits until the node is idle. Writes $TRACER_SLURM_DIR/env
# (`. $TRACER_SLURM_DIR/env` sets SLURM_CONF for the clients) and the pids it started in
# $TRACER_SLURM_DIR/started.pids, which ci/slurm-down.sh stops. Exit 0 when the node is idle.
set -euo pipefail
dir=${TRACER_SLURM_DIR:-/tmp/tracer-slurm}

packages=(slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ -f "$dir/started.pids" ]; then
  echo "slurm-up: $dir/started.pids exists; run ci/slurm-down.sh first" >&2
  exit 1
fi
rm -rf "$dir"
mkdir -p "$dir/state" "$dir/spool"
: > "$dir/started.pids"
host=$(hostname -s)

# munge: the key Debian's package made; our own daemon only when none runs.
if ! pgrep -x munged >/dev/null; then
  [ -s /etc/munge/munge.key ] || { mungekey --create --force && chown munge:munge /etc/munge/munge.key; }
  mkdir -p /run/munge /var/lib/munge /var/log/munge
  chown munge:munge /run/munge /var/lib/munge /var/log/munge
  runuser -u munge -- /usr/sbin/munged  # writes /run/munge/munged.pid
  for _ in $(seq 50); do [ -s /run/munge/munged.pid ] && break; sleep 0.1; done
  cat /run/munge/munged.pid >> "$dir/started.pids"
fi

cat > "$dir/slurm.conf" <<EOF
ClusterName=tracer
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=tracer Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF=$dir/slurm.conf
echo "export SLURM_CONF=$SLURM_CONF" > "$dir/env"

/usr/sbin/slurmctld -f "$SLURM_CONF"
for _ in $(seq 50); do [ -s "$dir/slurmctld.pid" ] && break; sleep 0.1; done
cat "$dir/slurmctld.pid" >> "$dir/started.pids"
/usr/sbin/slurmd -f "$SLURM_CONF"
for _ in $(seq 50); do [ -s "$dir/slurmd.pid" ] && break; sleep 0.1; done
cat "$dir/slurmd.pid" >> "$dir/started.pids"

for _ in $(seq 60); do
  if [ "$(sinfo -h -N -o %t 2>/dev/null)" = "idle" ]; then
    echo "slurm-up: node $host idle ($(nproc) CPUs); . $dir/env sets SLURM_CONF"
    exit 0
  fi
  sleep 0.5
done
echo "slurm-up: the node did not become idle in 30 s:" >&2
sinfo -N >&2 || true
tail -20 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
exit 1
