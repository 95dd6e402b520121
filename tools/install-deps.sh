#!/usr/bin/env bash
# Installs the Debian 12 packages that areagraph needs.
#   tools/install-deps.sh          what the build and the whole test suite need
#   tools/install-deps.sh build    only what configuring and building need
#                                  (tools/demo.sh: no browser, GDAL or Slurm)
# Idempotent: when everything is present it only checks (one dpkg-query) and
# exits.
set -euo pipefail

BUILD_PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  libcgal-dev libeigen3-dev
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libprotobuf-dev protobuf-compiler
  libsqlite3-dev libzstd-dev libpng-dev zlib1g-dev  # their .a: cmake/FastStart.cmake
  nettle-dev  # SHA-256 of the store (store/digest.cc), without OpenSSL's provider start-up
  libyaml-cpp-dev libcli11-dev
  liblcm-dev liblcm-bin libglib2.0-dev
  libgtest-dev libgmock-dev  # CMake configures the tests even when they are not built
)
TEST_PACKAGES=(
  clang-format  # tools/check-format.sh
  sqlite3  # the tests read stores with its shell
  time  # /usr/bin/time: peak memory in tools/bench-speed.sh
  iproute2  # ip: multicast on loopback for the cross-process LCM tests
  # The Python package (python/, tools/install-python.sh): pybind11 builds it
  # for Debian's python3; it hands out numpy, shapely, networkx and protobuf
  # objects, and reads stores; its tests make venvs.
  python3-dev pybind11-dev python3-pybind11
  python3-numpy python3-shapely python3-networkx python3-protobuf python3-zstandard python3-venv
  # Test dependencies: ag-export's files opened with the users' own tools
  # (tests/tools/export/ecosystem_test.cc): GDAL's ogr2ogr/ogrinfo, shapely.
  gdal-bin
  josm  # JOSM's validator run headless on the osmAG of real maps (tests/tools/export/josm_validation_test.cc)
  chromium  # headless browser for the HTML viewer's tests (tests/tools/export, tests/tools/report)
  # Test dependencies: the one-node Slurm cluster of tools/slurm-local.sh, on
  # which tests/examples/cluster runs examples/cluster's Slurm scripts.
  slurm-wlm munge
)

case "${1:-}" in
  build) PACKAGES=("${BUILD_PACKAGES[@]}") ;;
  "") PACKAGES=("${BUILD_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  *) echo "install-deps: unknown argument '$1' (build, or nothing)" >&2; exit 2 ;;
esac

# One query for all: a package that is not known at all is missing too.
installed=$(dpkg-query -W -f='${Package} ${Status}\n' "${PACKAGES[@]}" 2>/dev/null |
  awk '$NF == "installed" { print $1 }' || true)
missing=()
for package in "${PACKAGES[@]}"; do
  if ! grep -qx "$package" <<<"$installed"; then missing+=("$package"); fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${#missing[@]} Debian packages (on a fresh machine a few minutes): ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
