#!/usr/bin/env bash
# Sets everything up (packages, configure, build) and runs the whole test suite with CTest, then
# checks that it ran every test the source tree defines (scripts/check-tests.py: a missing test
# binary or a layer dropped by a CMake condition fails the run by name).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/setup.sh
built=$(date +%s)
log=build/ctest.log
status=0
ctest --test-dir build --output-on-failure --parallel "$(nproc)" 2>&1 | tee "$log" || status=$?
python3 scripts/check-tests.py build --log "$log" || status=1
end=$(date +%s)
echo "test: setup and build $((built - start)) s, tests $((end - built)) s, exit status $status"
exit $status
