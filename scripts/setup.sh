#!/usr/bin/env bash
# Installs what the project needs (Debian 12 packages), configures and builds into build/.
# Idempotent: a second run with nothing changed only checks the packages and runs an incremental build.
set -euo pipefail
cd "$(dirname "$0")/.."

# What building and running the two programs needs (the main job: `setup.sh --programs`).
PROGRAM_PACKAGES=(
  build-essential cmake ninja-build pkg-config
  ccache lld  # compile cache and fast linker, picked up by cmake/BuildSpeed.cmake
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-charts-dev qt6-svg-dev
  qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n libqcustomplot-dev
  libeigen3-dev zlib1g-dev
  libtinyobjloader-dev  # the OBJ reader of the core's mesh files (src/core/mesh/MeshFiles.cpp)
  libopenexr-dev  # raw density out: render --out F.exr (src/render/DensityExr.cpp)
  libxkbcommon-dev libgl1-mesa-dev fonts-dejavu-core adwaita-icon-theme
  # the Python module attractor_workbench (src/python) and the window's console
  python3-dev pybind11-dev python3-numpy
  python3-distributed  # Dask: the regularity atlas and huge renders on a cluster (issue 48)
  fonts-wqy-microhei  # a CJK font: the Chinese translation on screen and in figures
)
# What the tests, the sanitizers, the fuzzers, the benchmarks and the package checks need
# besides (the README's test command: `setup.sh`). Not installed by the main job.
TEST_PACKAGES=(
  libosd-dev  # OpenSubdiv 3.5: the reference of the mesh tests (tests/core/test_mesh_opensubdiv.cpp)
  flam3-utils  # flam3-render and flam3-genome: the judges of the .flame tests (tests/cli)
  libflam3-dev  # libflam3's apply_xform: the reference of the variations (tests/core/test_flame_variations.cpp)
  xvfb xauth x11-apps imagemagick poppler-utils
  libxtst-dev xdotool  # attractor-bench-window: pointer moves through XTest, as a person drags
  python3-pytest python3-matplotlib  # the module's tests and example scripts
  assimp-utils python3-meshio ffmpeg  # other tools' meshes, animations to MP4/GIF
  clang libclang-rt-14-dev  # the sanitizer and fuzzing builds
  # the Debian package (packaging/, scripts/package.sh, tests/packaging): icons, dpkg-shlibdeps, checks
  librsvg2-bin dpkg-dev lintian desktop-file-utils appstream shared-mime-info man-db
)
PACKAGES=("${PROGRAM_PACKAGES[@]}")
if [ "${1:-}" != "--programs" ]; then
  PACKAGES+=("${TEST_PACKAGES[@]}")
fi

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

# `setup.sh --packages-only`: the packages (all of them), no build (the sanitizer and fuzzing
# scripts build in their own folders).
if [ "${1:-}" = "--packages-only" ]; then
  exit 0
fi

BUILD_TYPE="${AWB_BUILD_TYPE:-RelWithDebInfo}"
# The main job configures without the tests and benchmarks (their packages are not installed
# then); the full setup turns them on, in the same build folder.
TESTS=ON
if [ "${1:-}" = "--programs" ]; then
  TESTS=OFF
fi
if [ ! -f build/build.ninja ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DAWB_TESTS="$TESTS"
elif [ "$TESTS" = ON ] && grep -q '^AWB_TESTS:BOOL=OFF' build/CMakeCache.txt; then
  cmake -S . -B build -DAWB_TESTS=ON
fi
# `setup.sh --programs`: only the two programs (scripts/main.sh: the first picture without
# waiting for the tests and benchmarks to compile), `--programs --cli-only` only the
# command-line tool (the main job without a display); otherwise everything.
if [ "${1:-}" = "--programs" ] && [ "${2:-}" = "--cli-only" ]; then
  cmake --build build --parallel "$(nproc)" --target attractor-cli
elif [ "${1:-}" = "--programs" ]; then
  cmake --build build --parallel "$(nproc)" --target attractor-cli attractor-workbench
else
  cmake --build build --parallel "$(nproc)"
fi
