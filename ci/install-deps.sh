#!/usr/bin/env bash
# Installs every Debian 12 package the build and the tests need. Idempotent: when all
# packages are present it changes nothing and does not touch the network. Run as root.
set -euo pipefail
packages=(
  cmake g++ make
  libopenimageio-dev openimageio-tools   # image I/O and comparison (iv, idiff, oiiotool)
  libtinyobjloader-dev                    # OBJ meshes
  libglm-dev                              # vector maths on the host side
  nlohmann-json3-dev                      # scene files
  libcli11-dev                            # the command line
  libgtest-dev                            # the test suite
  chromium                                # opens the golden report headless in a test
  git                                     # golden update's check for uncommitted edits
  strace                                  # stops a command at its Nth rename with a signal (commit tests)
  python3                                 # ci/mutation.py, the mutation campaign
  fonts-dejavu-core                       # the font of the bench converge plot
  libembree-dev                           # the Embree row of bench rays (benchmark only)
  clang libomp-dev libclang-rt-14-dev     # the second compiler, its OpenMP runtime, libFuzzer and sanitizers (ci/extra.sh)
)
missing=()
for p in "${packages[@]}"; do
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
