#!/usr/bin/env bash
# Sets everything up and runs the main job. With a display: the desktop application on an
# example of the gallery. Without one (or with AWB_NO_GUI=1): renders every example project of
# the gallery (examples/*.awb, one per paper figure) with the CLI to build/gallery/.
set -euo pipefail
cd "$(dirname "$0")/.."
# The job builds what it runs: the window with a display, the command-line tool without one.
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -z "${AWB_NO_GUI:-}" ]; then
    bash scripts/setup.sh --programs
    exec ./build/bin/attractor-workbench examples/000-fig11-sierpinski-with-control-points.awb
fi
bash scripts/setup.sh --programs --cli-only
out="$(pwd)/build/gallery"
mkdir -p "$out"
for f in examples/*.awb; do
    ./build/bin/attractor-cli render "$f" --out "$out/$(basename "$f" .awb).png" --size 900x700
done
# 000 Fig. 9 holds both sides of the figure: the 4-of-6 fractal (first item) and the surface.
./build/bin/attractor-cli render examples/000-fig09-box-spline-subset.awb \
    --item "000 Fig. 9 (left): six maps" --out "$out/000-fig09-box-spline-subset-left.png" \
    --size 900x700
./build/bin/attractor-cli examples --out "$out/strips"
echo "No display: the gallery was rendered to $out"
