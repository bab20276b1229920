#!/usr/bin/env bash
# Sets everything up (packages, configure, build) and runs the whole test suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure --parallel 2
