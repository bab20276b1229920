#!/usr/bin/env bash
# Sets everything up and runs the main job: renders every example project of the gallery
# (examples/*.awb, one per paper figure) with the CLI, and the built-in figure strips.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
out="$(pwd)/build/gallery"
mkdir -p "$out"
for f in examples/*.awb; do
    ./build/bin/attractor-cli render "$f" --out "$out/$(basename "$f" .awb).png" --size 900x700
done
./build/bin/attractor-cli examples --out "$out/strips"
echo "The figures are in $out"
