#!/usr/bin/env bash
# Sets everything up and runs the main job: renders the bundled paper figures with the CLI.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
out="$(pwd)/build/gallery"
./build/bin/attractor-cli examples --out "$out"
echo "The figures are in $out"
