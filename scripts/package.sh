#!/usr/bin/env bash
# Builds the Debian package build/attractor-workbench_<version>_<arch>.deb (packaging/) and
# checks it with lintian. Sets up and builds first (scripts/setup.sh). Install it with
#     sudo apt-get install ./build/attractor-workbench_<version>_<arch>.deb
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
log=$(cpack -G DEB)
echo "$log"
deb=$(printf '%s\n' "$log" | sed -n 's/^CPack: - package: \(.*\.deb\) generated\.$/\1/p')
if [ ! -f "$deb" ]; then
    echo "package: cpack made no .deb" >&2
    exit 1
fi
echo "package: $deb ($(du -h "$deb" | cut -f1), $(stat -c %s "$deb") bytes)"
# Errors fail the script; warnings and infos are listed (packaging/README.md says why each
# one that remains is there).
lintian --display-info "$deb"
echo "package: lintian found no errors"
