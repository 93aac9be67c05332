#!/usr/bin/env bash
# Times a README command as a new user meets it: a minimal Debian 12 (debootstrap --variant=minbase)
# in a chroot under DIR, a clean clone of this checkout's HEAD in it, then the command, apt included.
# nvcc is the host's CUDA toolkit, mounted read-only where the host has it (it is not a Debian
# package). Run as root:
#   bash ci/time-fresh-machine.sh DIR 'bash ci/quickstart.sh'
#   bash ci/time-fresh-machine.sh DIR 'bash ci/test.sh -j2'
# Prints the command's wall time; DIR is left for a look and removed by the next run.
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: ci/time-fresh-machine.sh DIR COMMAND" >&2; exit 2; }
dir=$1 command=$2
repo=$(cd "$(dirname "$0")/.." && pwd)
cuda=$(readlink -f /usr/local/cuda || true)  # /usr/local/cuda-13.0: the toolkit's own name for itself
mounts=(dev/pts dev proc sys "${cuda#/}")
for m in "${mounts[@]}"; do umount "$dir/root/$m" 2>/dev/null || true; done
if grep -q " $(realpath -m "$dir")/" /proc/mounts; then echo "ci/time-fresh-machine.sh: $dir still has mounts" >&2; exit 1; fi
rm -rf "$dir" && mkdir -p "$dir"
command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }
debootstrap --variant=minbase bookworm "$dir/root" http://deb.debian.org/debian >"$dir/debootstrap.log"
cp /etc/resolv.conf "$dir/root/etc/resolv.conf"
cat >"$dir/root/etc/apt/sources.list" <<'EOF'
deb http://deb.debian.org/debian bookworm main
deb http://deb.debian.org/debian bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
for m in dev dev/pts proc sys; do mount --bind "/$m" "$dir/root/$m"; done
if [ -d "$cuda" ]; then
  mkdir -p "$dir/root$cuda" && mount --bind -o ro "$cuda" "$dir/root$cuda"
  [ "$cuda" = /usr/local/cuda ] || ln -s "$cuda" "$dir/root/usr/local/cuda"
fi
trap 'for m in "${mounts[@]}"; do umount "$dir/root/$m" 2>/dev/null || true; done' EXIT
git clone -q --no-hardlinks "$repo" "$dir/root/root/tracer"
start=$(date +%s)
chroot "$dir/root" /usr/bin/env -i HOME=/root PATH=/usr/local/cuda/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  bash -c "cd /root/tracer && $command" >"$dir/command.log" 2>&1 || { tail -20 "$dir/command.log"; exit 1; }
echo "$command: $(($(date +%s) - start)) s on a fresh minimal Debian 12 ($(nproc) cores), log in $dir/command.log"
