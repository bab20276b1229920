#!/usr/bin/env bash
# Takes the screenshots of packaging/screenshots/ again from the built application (build/bin),
# through its own batch option, without a display. Look at them before committing.
#     bash packaging/take-screenshots.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
app="${1:-build}/bin/attractor-workbench"
out=packaging/screenshots
mkdir -p "$out"
shot() { # example name -> screenshot name
    QT_QPA_PLATFORM=offscreen "$app" "examples/$1.awb" --screenshot "$out/$2.png" \
        --window-size 1400x900 2> >(grep -v 'propagateSizeHints' >&2)
    echo "$out/$2.png"
}
shot 000-fig11-sierpinski-with-control-points sierpinski-with-control-points
shot 000-fig05-four-point-from-segment four-point-curve
shot 000-fig06-bicubic-patch bicubic-surface
shot 004-fig3.4-complex-decasteljau complex-de-casteljau
