#!/usr/bin/env bash
# Configures build-tsan/ (used by `scripts/sanitize.sh thread`): clang with ThreadSanitizer on
# every object, -O1 with line tables (reports name file and line), assertions on.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -f build-tsan/build.ninja ]; then
  CC=clang CXX=clang++ cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only" -DAWB_TSAN=ON
fi
