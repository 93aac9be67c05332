#!/usr/bin/env bash
# Fetches the Stanford bunny from the npm registry (package `bunny`: positions and cells,
# about 5,000 triangles) and converts it to scenes/generated/bunny.obj. It is not committed.
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
  const lines = ["# Stanford bunny, from the npm package bunny@1.0.1"];
  for (const p of b.positions) lines.push("v " + p.join(" "));
  for (const c of b.cells) lines.push("f " + c.map(i => i + 1).join(" "));
  require("fs").writeFileSync(process.argv[2] + ".tmp", lines.join("\n") + "\n");
  require("fs").renameSync(process.argv[2] + ".tmp", process.argv[2]);
' "$work/package/index.js" "$out"
echo "ci/fetch-bunny.sh: wrote $out"
