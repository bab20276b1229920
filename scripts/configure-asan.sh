#!/usr/bin/env bash
# Configures build-asan/ (used by scripts/sanitize.sh and scripts/fuzz.sh): clang with
# AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage on every object,
# -O1 with line tables (stack traces name file and line; compiles about as fast as the normal
# build), assertions on (Eigen's bounds checks, Q_ASSERT).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build-asan/build.ninja ]; then
  CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DAWB_FUZZ=ON
fi
