#!/usr/bin/env bash
# Renders a glTF file with the tracer and with Blender Cycles (blender_render.py: Blender's own
# glTF importer, KHR_lights_punctual as W = 4 pi cd) at the same size, samples and depth, and
# prints both images' means over a 3 x 3 grid of regions and their ratio (docs/gltf.md,
# "Checked against Blender"). Both see the tracer's neutral sky (radiance 1); a file without a
# camera is seen by Blender through the camera the tracer frames it with (`tracer info`; it
# depends on the aspect ratio only, 4:3 there and at the default size here).
# Needs Debian's blender, python3-numpy and python3-openimageio.
# From the repository root, after bash ci/build.sh:
#   bash scenes/gltf/blender_compare.sh FILE.glb [SPP] [WIDTH] [HEIGHT] [KEEP_DIR] [SKY] [REGION]
# KEEP_DIR, when given (or ""), keeps tracer.exr and blender.exr there. SKY R,G,B replaces the
# neutral sky in both (0,0,0: the file's own lights alone); SKY an image file (.exr, .hdr) lights
# both by that equirectangular map (the tracer's --environment, Blender's Environment Texture).
# REGION X0,Y0,X1,Y1 (pixels, X1 and Y1 excluded, top row 0) prints that rectangle's means too.
set -euo pipefail
file=$1 spp=${2:-1024} width=${3:-160} height=${4:-120} keep=${5:-} sky=${6:-1,1,1} region=${7:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case "$sky" in
  *.exr | *.hdr) ours=(--environment "$sky") theirs=(--environment "$(realpath "$sky")") ;;
  *) ours=(--background "$sky") theirs=(--world "$sky") ;;
esac
build/tracer render "$file" --spp "$spp" --width "$width" --height "$height" "${ours[@]}" --quiet \
  -o "$work/tracer.exr" >/dev/null
# "camera (none in the file: one framing the model) from X,Y,Z to X,Y,Z up X,Y,Z vfov DEGREES"
camera=$(build/tracer info "$file" |
  sed -n 's/.*one framing the model) from \([^ ]*\) to \([^ ]*\) up \([^ ]*\) vfov \([^ ]*\).*/--camera-from=\1 --camera-to=\2 --camera-up=\3 --vfov=\4/p')
blender -b -noaudio --factory-startup --python "$(dirname "$0")/blender_render.py" -- "$file" "$work/blender.exr" \
  --spp "$spp" --width "$width" --height "$height" --lighting COMPAT "${theirs[@]}" $camera >"$work/blender.log" 2>&1 ||
  { tail -20 "$work/blender.log"; exit 1; }
[ -n "$keep" ] && mkdir -p "$keep" && cp "$work/tracer.exr" "$work/blender.exr" "$keep/"
/usr/bin/python3 - "$work/tracer.exr" "$work/blender.exr" "$region" <<'PY'
import sys
import OpenImageIO as oiio
ours, theirs = (oiio.ImageBuf(f).get_pixels(oiio.FLOAT)[:, :, :3] for f in sys.argv[1:3])
h, w = ours.shape[:2]
print("whole image: tracer %.4f, Blender %.4f, ratio %.3f" % (ours.mean(), theirs.mean(), ours.mean() / theirs.mean()))
print("regions (tracer / Blender = ratio), top row first:")
for i in range(3):
    cells = []
    for j in range(3):
        a = ours[i * h // 3:(i + 1) * h // 3, j * w // 3:(j + 1) * w // 3].mean()
        b = theirs[i * h // 3:(i + 1) * h // 3, j * w // 3:(j + 1) * w // 3].mean()
        cells.append("%.4f / %.4f = %s" % (a, b, "%.4f" % (a / b) if b > 0 else "-"))
    print("  " + "   ".join(cells))
if sys.argv[3]:
    x0, y0, x1, y1 = (int(v) for v in sys.argv[3].split(","))
    if not (0 <= x0 < x1 <= w and 0 <= y0 < y1 <= h):
        sys.exit("region %s lies outside the %dx%d image" % (sys.argv[3], w, h))
    a, b = ours[y0:y1, x0:x1].mean(), theirs[y0:y1, x0:x1].mean()
    print("region %s: tracer %.4f, Blender %.4f, ratio %.3f" % (sys.argv[3], a, b, a / b))
PY
