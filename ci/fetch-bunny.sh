#!/usr/bin/env bash
# Fetches the Stanford bunny from the npm registry (package `bunny`: positions and cells,
# 3,674 triangles) and converts it to scenes/generated/bunny.obj with spherical uvs about its
# centre (for textures). It is not committed.
# Needs node and npm (installed from Debian's packages when missing). Run as root.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/scenes/generated/bunny.obj"
[ -f "$out" ] && { echo "ci/fetch-bunny.sh: $out exists"; exit 0; }
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq --no-install-recommends nodejs npm >/dev/null
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack --silent bunny@1.0.1 >/dev/null && tar xzf bunny-1.0.1.tgz)
mkdir -p "$(dirname "$out")"
node -e '
  const b = require(process.argv[1]);
  const lines = ["# Stanford bunny, from the npm package bunny@1.0.1, with spherical uvs about its centre"];
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (const p of b.positions) for (let k = 0; k < 3; ++k) lo[k] = Math.min(lo[k], p[k]), hi[k] = Math.max(hi[k], p[k]);
  const c = [0, 1, 2].map(k => (lo[k] + hi[k]) / 2);
  for (const p of b.positions) lines.push("v " + p.join(" "));
  for (const p of b.positions) {
    const d = [p[0] - c[0], p[1] - c[1], p[2] - c[2]], r = Math.hypot(d[0], d[1], d[2]) || 1;
    lines.push("vt " + (0.5 + Math.atan2(d[2], d[0]) / (2 * Math.PI)).toFixed(6) + " " + (0.5 + Math.asin(d[1] / r) / Math.PI).toFixed(6));
  }
  for (const f of b.cells) lines.push("f " + f.map(i => (i + 1) + "/" + (i + 1)).join(" "));
  require("fs").writeFileSync(process.argv[2] + ".tmp", lines.join("\n") + "\n");
  require("fs").renameSync(process.argv[2] + ".tmp", process.argv[2]);
' "$work/package/index.js" "$out"
echo "ci/fetch-bunny.sh: wrote $out"
