#!/usr/bin/env bash
# The build's CUDA compiler launcher (CMAKE_CUDA_COMPILER_LAUNCHER): runs nvcc's command and keeps
# what the two CUDA audits read beside the object (docs/cuda.md):
#  - OBJECT.resources: ptxas' report (--resource-usage: each kernel's registers, stack frame,
#    spills and shared memory, per architecture), for `tracer audit resources`;
#  - OBJECT.compute_NN.ptx: the PTX this compile made for each virtual architecture (nvcc
#    --keep; named by its .target line), for `tracer audit cuda`: the very PTX the machine code
#    was compiled from.
# The report's lines are kept out of the build's output; nvcc's warnings and errors are shown as
# they are. A failed compile, or a file that cannot be kept, leaves no object, report or PTX.
set -u
out="" prev=""
for arg in "$@"; do
  [ "$prev" = "-o" ] && out=$arg
  prev=$arg
done
case "$out" in
  *.o) ;;
  *) exec "$@" ;;
esac
log="$out.resources.partial"
rm -f "$out.resources" "$out".compute_*.ptx
keep=$(mktemp -d "${TMPDIR:-/tmp}/nvcc-keep.XXXXXX") || exit 1
"$@" --resource-usage --keep --keep-dir "$keep" 2>"$log"
status=$?
grep -v -e '^ptxas info' -e '^    [0-9]* bytes stack frame' "$log" >&2
if [ $status -eq 0 ]; then
  for ptx in "$keep"/*.ptx; do
    [ -e "$ptx" ] || continue
    arch=$(sed -n 's/^\.target[[:space:]]*sm_\([0-9][0-9]*\).*/\1/p' "$ptx" | head -n 1)
    if [ -z "$arch" ]; then
      echo "$0: $ptx names no .target sm_NN" >&2
      status=1
    elif ! cp "$ptx" "$out.compute_$arch.ptx.partial" || ! mv -f "$out.compute_$arch.ptx.partial" "$out.compute_$arch.ptx"; then
      status=1
    fi
  done
fi
rm -rf "$keep"
if [ $status -eq 0 ]; then
  mv -f "$log" "$out.resources" || status=1
fi
if [ $status -ne 0 ]; then  # nvcc's object too, so that the next build compiles it again
  rm -f "$out" "$log" "$out".compute_*.ptx "$out".compute_*.ptx.partial "$out.resources"
fi
exit $status
