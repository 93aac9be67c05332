#!/usr/bin/env bash
# The peer table of docs/gltf.md: every glTF file of Debian's assimp-testmodels (files nobody
# here wrote), rendered by the tracer and by Blender Cycles through Blender's own importer
# (blender_compare.sh), one row a file: the whole image's mean ratio and the range of the
# 3 x 3 regions' ratios; a file the tracer refuses gets its message instead. Needs what
# blender_compare.sh needs. From the repository root, after bash ci/build.sh:
#   bash scenes/gltf/blender_peer_table.sh [SPP] [KEEP_DIR]
# KEEP_DIR keeps each file's two images in KEEP_DIR/NAME/ for a look.
set -uo pipefail
spp=${1:-256} keep=${2:-}
root=/usr/share/assimp/models/glTF2
echo "| file | tracer / Blender, whole image | regions | seconds |"
echo "| --- | --- | --- | --- |"
find "$root" -name '*.gltf' -o -name '*.glb' | sort | while read -r file; do
  name=${file#"$root"/}
  if ! why=$(build/tracer info "$file" 2>&1 >/dev/null); then
    why=${why#"error: "}
    why=${why#"$file": }
    echo "| \`$name\` | refused: ${why:0:140} | | |"
    continue
  fi
  start=$SECONDS
  out=$(bash "$(dirname "$0")/blender_compare.sh" "$file" "$spp" 160 120 ${keep:+"$keep/${name//\//_}"} 2>&1)
  whole=$(echo "$out" | sed -n 's/.*ratio \([0-9.]*\)$/\1/p')
  regions=$(echo "$out" | grep -o '= [0-9][0-9.]*' | awk '{print $2}' | sort -n | sed -n '1p;$p' | paste -sd- -)
  echo "| \`$name\` | ${whole:-failed: $(echo "$out" | tail -1 | cut -c1-100)} | ${regions} | $((SECONDS - start)) |"
done
