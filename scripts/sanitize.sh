#!/usr/bin/env bash
# Builds the project with AddressSanitizer and UndefinedBehaviorSanitizer (clang,
# -fno-sanitize-recover=all: the first report ends the test with a failure) in build-asan/ and
# runs the whole CTest suite there. Any report fails the run; leaks are reported too
# (LeakSanitizer), with the suppressions of tests/sanitizers/lsan.supp (third-party libraries
# only, each with its reason). The same build holds the fuzz targets of scripts/fuzz.sh.
#   scripts/sanitize.sh [CTEST ARGUMENTS...]     e.g. -R model_ to run part of the suite
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --packages-only
start=$(date +%s)
bash scripts/configure-asan.sh
cmake --build build-asan --parallel "$(nproc)"
built=$(date +%s)
source scripts/sanitizer-env.sh
cd build-asan
status=0
# Instrumented code runs several times slower: tests get 1800 s each (tests/CMakeLists.txt).
ctest --output-on-failure --parallel "$(nproc)" "$@" || status=$?
end=$(date +%s)
echo "sanitize: build $((built - start)) s, tests $((end - built)) s, exit status $status"
exit $status
