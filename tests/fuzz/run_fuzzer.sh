#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time (docs/fuzzing.md): the checked-in corpus is
# copied into a work corpus under the build tree, mutated for SECONDS with the target's
# dictionary, each input limited to 10 s and 2 GiB; any crash, hang, leak or sanitizer report
# exits non-zero and leaves its input under WORK/artifacts/. Prints how many inputs ran.
# suppressions/NAME.lsan, where present, lists library leaks the target may not report.
# Usage: run_fuzzer.sh FUZZER SOURCE_DIR NAME SECONDS WORK
set -euo pipefail
fuzzer=$1 source=$2 name=$3 seconds=$4 work=$5
rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
cp "$source/corpus/$name"/* "$work/corpus/"
# The glTF target also starts from Debian's assimp-testmodels (its glTF 2.0 files, broken ones
# included) where that package is installed.
if [ "$name" = gltf ] && [ -d /usr/share/assimp/models/glTF2 ]; then
  find /usr/share/assimp/models/glTF2 \( -name '*.gltf' -o -name '*.glb' \) -size -64k |
    while read -r f; do cp "$f" "$work/corpus/assimp-$(echo "${f#/usr/share/assimp/models/glTF2/}" | tr / -)"; done
fi
dict=()
[ -f "$source/dict/$name.dict" ] && dict=("-dict=$source/dict/$name.dict")
# A target whose libraries leak where we cannot free (suppressions/NAME.lsan says what and why)
# needs full malloc stacks: the libraries are built without frame pointers.
# A suppressions file the caller's LSAN_OPTIONS names (the sanitize preset's) is kept: both go
# into one file, since a flag given twice keeps only its last value.
if [ -f "$source/suppressions/$name.lsan" ]; then
  cat "$source/suppressions/$name.lsan" >"$work/lsan.supp"
  inherited=$(sed -n 's/.*suppressions=\([^:]*\).*/\1/p' <<<"${LSAN_OPTIONS:-}")
  if [ -n "$inherited" ]; then cat "$inherited" >>"$work/lsan.supp"; fi
  export LSAN_OPTIONS="${LSAN_OPTIONS:+$LSAN_OPTIONS:}suppressions=$work/lsan.supp"
  export ASAN_OPTIONS="fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
fi
set +e
"$fuzzer" "$work/corpus" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
  -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/artifacts/" 2>"$work/log"
status=$?
set -e
grep -E '^stat::number_of_executed_units|^#[0-9]+ *DONE' "$work/log" || true
if [ $status -ne 0 ]; then
  tail -60 "$work/log"
  echo "fuzz.$name: the fuzzer failed (exit $status); the input is in $work/artifacts/"
  ls -l "$work/artifacts/"
  exit 1
fi
echo "fuzz.$name: no finding in $seconds s; corpus now $(ls "$work/corpus" | wc -l) inputs"
