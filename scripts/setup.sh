#!/usr/bin/env bash
# Installs what the project needs (Debian 12 packages), configures and builds into build/.
# Idempotent: a second run with nothing changed only checks the packages and runs an incremental build.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  ccache lld  # compile cache and fast linker, picked up by cmake/BuildSpeed.cmake
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-charts-dev qt6-svg-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n libqcustomplot-dev
  libeigen3-dev zlib1g-dev
  libosd-dev  # OpenSubdiv 3.5: the reference of the mesh tests (tests/core/test_mesh_opensubdiv.cpp)
  libtinyobjloader-dev  # the OBJ reader of the core's mesh files (src/core/mesh/MeshFiles.cpp)
  libopenexr-dev  # raw density out: render --out F.exr (src/render/DensityExr.cpp)
  flam3-utils  # flam3-render and flam3-genome: the judges of the .flame tests (tests/cli)
  libxkbcommon-dev xvfb xauth libgl1-mesa-dev x11-apps imagemagick fonts-dejavu-core poppler-utils
  libxtst-dev xdotool  # attractor-bench-window: pointer moves through XTest, as a person drags
  # the Python module attractor_workbench (src/python) and its console, tests and examples
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
  fonts-wqy-microhei  # a CJK font: the Chinese translation on screen and in figures
  assimp-utils python3-meshio adwaita-icon-theme ffmpeg clang libclang-rt-14-dev
  # the Debian package (packaging/, scripts/package.sh, tests/packaging): icons, dpkg-shlibdeps, checks
  librsvg2-bin dpkg-dev lintian desktop-file-utils appstream shared-mime-info man-db
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends \
    -o DPkg::Lock::Timeout=300 "${missing[@]}"
fi

# `setup.sh --packages-only`: the packages, no build (the sanitizer and fuzzing scripts build
# in their own folders).
if [ "${1:-}" = "--packages-only" ]; then
  exit 0
fi

BUILD_TYPE="${AWB_BUILD_TYPE:-RelWithDebInfo}"
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE"
fi
# `setup.sh --programs`: only the two programs (scripts/main.sh: the first picture without
# waiting for the tests and benchmarks to compile); otherwise everything.
if [ "${1:-}" = "--programs" ]; then
  cmake --build build --parallel "$(nproc)" --target attractor-cli attractor-workbench
else
  cmake --build build --parallel "$(nproc)"
fi
