#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs. Idempotent: when all are present it
# changes nothing and does not touch the network. Run as root.
#   bash ci/install-deps.sh build   what building and running the renderer needs (ci/quickstart.sh)
#   bash ci/install-deps.sh         that, and what the tests and the extra CI jobs need (ci/test.sh)
set -euo pipefail
build_packages=(
  cmake g++ make
  lld                                     # the linker the build picks when it is there (a tenth of GNU ld's time)
  libopenimageio-dev openimageio-tools    # image I/O and comparison (OIIO's CMake package names the tools)
  libtinyobjloader-dev                    # OBJ meshes
  libtinygltf-dev                         # glTF 2.0 files
  libglm-dev                              # the kernel's vectors and matrices
  nlohmann-json3-dev                      # scene files
  libcli11-dev                            # the command line
  libcpp-httplib-dev pkg-config          # tracer view's HTTP server (found through pkg-config)
  libgtest-dev                            # the test suite (configuring the build asks for it)
  git                                     # the commit `tracer --version` names; golden update's check for uncommitted edits
)
test_packages=(
  chromium                                # opens the golden report headless in a test
  strace                                  # stops a command at its Nth rename with a signal (commit tests)
  python3                                 # ci/mutation.py, the mutation campaign
  assimp-testmodels                       # glTF files, broken ones included: the glTF reader's corpus test
  nodejs npm                              # the Khronos glTF validator, the bunny; skipped where node and npm run already
  fonts-dejavu-core                       # the font of the bench converge plot
  libembree-dev                           # the Embree row of bench rays (benchmark only)
  clang libomp-dev libclang-rt-14-dev     # the second compiler, its OpenMP runtime, libFuzzer and sanitizers (ci/extra.sh sanitize)
)
case "${1:-all}" in
  build) packages=("${build_packages[@]}") ;;
  all) packages=("${build_packages[@]}" "${test_packages[@]}") ;;
  *) echo "usage: ci/install-deps.sh [build|all]" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  # A machine whose Node.js comes from elsewhere (NodeSource's nodejs bundles npm, and Debian's npm
  # package conflicts with it) already has what the validator needs.
  case "$p" in nodejs | npm) command -v node >/dev/null && command -v npm >/dev/null && continue ;; esac
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "ci/install-deps.sh: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "ci/install-deps.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
