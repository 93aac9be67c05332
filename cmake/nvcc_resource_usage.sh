#!/usr/bin/env bash
# The build's CUDA compiler launcher (CMAKE_CUDA_COMPILER_LAUNCHER): runs nvcc's command with
# --resource-usage and keeps ptxas' report (each kernel's registers, stack frame, spills and
# shared memory, per architecture) beside the object as OBJECT.resources, for
# `tracer audit resources` (docs/cuda.md, "Resource budgets"). The report's lines are kept out
# of the build's output; nvcc's warnings and errors are shown as they are.
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
"$@" --resource-usage 2>"$log"
status=$?
grep -v -e '^ptxas info' -e '^    [0-9]* bytes stack frame' "$log" >&2
if [ $status -eq 0 ]; then mv -f "$log" "$out.resources"; else rm -f "$log"; fi
exit $status
