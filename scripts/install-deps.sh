#!/usr/bin/env bash
# Installs the Debian 12 packages airis builds and tests with. Idempotent: packages already present are
# skipped, so a second run costs one dpkg query. Uses sudo only when not root. (The npm packages of the
# MAVLink conformance test go into the build folder when CMake configures: scripts/install-node-deps.sh.)
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config git
  python3                  # cmake/check_layers.py (the build's layer check)
  python3-numpy            # the tests read .npy streams back with NumPy; the Python module's arrays
  python3-dev pybind11-dev # the Python module (tools/python)
  python3-pytest python3-pil  # its tests (pytest) and airis.Dataset's PNG reader
  python3-torch            # examples/train_hover.py and airis.Dataset(...).torch()
  clang-format             # the format check of the test suite (cmake/check_format.sh)
  libeigen3-dev            # all vector and matrix math
  libbullet-dev            # collision detection (broadphase, narrowphase, contacts)
  libembree-dev            # ray casts for rangefinder and lidar
  libassimp-dev            # mesh files named in scenes
  libyaml-cpp-dev          # scene, vehicle and mission files
  libgdal-dev              # terrain from elevation models (GeoTIFF and GDAL's other rasters)
  nlohmann-json3-dev       # JSON output (env --json, manifests, COCO)
  libcli11-dev             # command line
  libpng-dev libdeflate-dev libjpeg62-turbo-dev  # PNG images, PNG/JPEG textures (engine/core/image_codec.h)
  libopencv-core-dev libopencv-imgproc-dev  # colour maps of previews (not all of libopencv-dev)
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri  # headless EGL + GLES3, llvmpipe when there is no GPU
  libgtest-dev libgmock-dev libbenchmark-dev           # tests and benchmarks
  nodejs npm               # MAVLink conformance test (node-mavlink: install-node-deps.sh)
  clang-14 libclang-rt-14-dev  # the sanitized build and libFuzzer's runtime (docs/fuzzing.md)
)

# True when package $1 is installed. A Node.js from another source (NodeSource's nodejs package bundles
# npm and conflicts with Debian's) counts as providing npm when an npm command exists.
installed() {
  if dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; then return 0; fi
  [ "$1" = npm ] && command -v npm >/dev/null 2>&1
}

missing=()
for p in "${PACKAGES[@]}"; do
  if ! installed "$p"; then missing+=("$p"); fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
