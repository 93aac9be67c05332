#!/usr/bin/env bash
# Fetches the Khronos glTF validator (npm gltf-validator, pinned) into
# scenes/generated/gltf-validator/, where GltfValidFiles.TheKhronosValidatorFindsNoErrorInThem
# judges the reader's test files with it (tests/support/gltf_validate.js). Not committed.
# Needs node and npm (ci/install-deps.sh installs them). Without the registry the test is
# skipped with its reason: this script then says so and exits 0.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/scenes/generated/gltf-validator"
version=2.0.0-dev.3.10
[ -f "$out/index.js" ] && grep -q "\"version\": \"$version\"" "$out/package.json" && exit 0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && timeout 120 npm pack --silent "gltf-validator@$version" >/dev/null 2>&1 &&
      tar xzf "gltf-validator-$version.tgz"); then
  echo "ci/fetch-gltf-validator.sh: could not fetch gltf-validator@$version from the npm registry;" \
       "the validator's test will be skipped" >&2
  exit 0
fi
rm -rf "$out"
mkdir -p "$(dirname "$out")"
mv "$work/package" "$out"
echo "ci/fetch-gltf-validator.sh: gltf-validator $version in $out"
