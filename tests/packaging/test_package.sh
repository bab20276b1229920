#!/usr/bin/env bash
# The Debian package, end to end: cpack builds it into a temporary folder (not build/, so that
# scripts/package.sh and this test never meet), dpkg-deb shows its files and dependencies, and
# the tree extracted with dpkg -x (nothing is installed) is checked and run: both programs'
# --version, attractor-cli check and render on a packaged example, desktop-file-validate,
# appstreamcli, the file type, the icons, the manual pages against the programs' --help.
#     test_package.sh BUILD_DIR SOURCE_DIR VERSION [CPACK]
set -euo pipefail
build=$1 source=$2 version=$3 cpack=${4:-cpack}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }
note() { echo "-- $*"; }

arch=$(dpkg --print-architecture)
deb=$tmp/out/attractor-workbench_${version}_${arch}.deb
(cd "$build" && "$cpack" -G DEB -B "$tmp/out" > "$tmp/cpack.log" 2>&1) \
    || { cat "$tmp/cpack.log"; exit 1; }
[ -f "$deb" ] || { cat "$tmp/cpack.log"; echo "FAIL: no $deb" >&2; exit 1; }
note "built $(basename "$deb"), $(stat -c %s "$deb") bytes"

# Control fields: dependencies from dpkg-shlibdeps, no invented homepage.
info=$(dpkg-deb -f "$deb")
field() { printf '%s\n' "$info" | sed -n "s/^$1: //p"; }
[ "$(field Package)" = attractor-workbench ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version $(field Version), expected $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture: $(field Architecture)"
[ "$(field Section)" = science ] || fail "Section: $(field Section)"
[[ "$(field Maintainer)" =~ ^[^\<]+\ \<[^@\>]+@[^\>]+\>$ ]] || fail "Maintainer: $(field Maintainer)"
[ -z "$(field Homepage)" ] || fail "Homepage given: $(field Homepage)"
[ "$(field Suggests)" = "ffmpeg, qt6-translations-l10n, fonts-noto-cjk | fonts-wqy-microhei, python3-matplotlib, python3-distributed" ] \
    || fail "Suggests: $(field Suggests)"
depends=$(field Depends)
for lib in libc6 libstdc++6 libqt6core6 libqt6gui6 libqt6widgets6 libqt6svg6 libqt6charts6 \
           libqt6printsupport6 libqt6opengl6 libqcustomplot2.1-qt6; do
    [[ ", $depends," == *", $lib "* || ", $depends," == *", $lib,"* ]] \
        || fail "Depends lacks $lib: $depends"
done
[[ ", $depends," == *", python3-numpy,"* ]] || fail "Depends lacks python3-numpy: $depends"
[ "$(printf '%s\n' "$info" | sed -n '/^Description:/,$p' | wc -l)" -gt 5 ] \
    || fail "no long description"

# Files.
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' > "$tmp/files"
expect=(/usr/bin/attractor-workbench /usr/bin/attractor-cli
        /usr/share/man/man1/attractor-workbench.1.gz /usr/share/man/man1/attractor-cli.1.gz
        /usr/share/applications/attractor-workbench.desktop
        /usr/share/metainfo/io.github.attractor_workbench.AttractorWorkbench.metainfo.xml
        /usr/share/mime/packages/attractor-workbench.xml
        /usr/share/icons/hicolor/scalable/apps/attractor-workbench.svg
        /usr/share/icons/hicolor/scalable/mimetypes/application-x-attractor-workbench.svg
        /usr/share/doc/attractor-workbench/copyright
        /usr/share/doc/attractor-workbench/changelog.gz)
for size in 16 24 32 48 64 128 256 512; do
    expect+=("/usr/share/icons/hicolor/${size}x${size}/apps/attractor-workbench.png"
             "/usr/share/icons/hicolor/${size}x${size}/mimetypes/application-x-attractor-workbench.png")
done
for f in "$source"/examples/*.awb; do
    expect+=("/usr/share/attractor-workbench/examples/$(basename "$f")")
done
for f in "$source"/packaging/screenshots/*.png; do
    expect+=("/usr/share/attractor-workbench/screenshots/$(basename "$f")")
done
for f in "${expect[@]}"; do
    grep -qxF "$f" "$tmp/files" || fail "the package lacks $f"
done
note "${#expect[@]} expected files present"

root=$tmp/root
dpkg -x "$deb" "$root"
bin=$root/usr/bin
data=$root/usr/share/attractor-workbench

for exe in attractor-cli attractor-workbench; do
    if readelf -S "$bin/$exe" | grep -q '\.debug_info'; then fail "$exe is not stripped"; fi
    if ldd "$bin/$exe" | grep -q 'not found'; then fail "$exe: $(ldd "$bin/$exe" | grep 'not found')"; fi
done
for size in 16 24 32 48 64 128 256 512; do
    png=$root/usr/share/icons/hicolor/${size}x${size}/apps/attractor-workbench.png
    read -r w h < <(od -An -tu1 -j16 -N8 "$png" \
                    | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}')
    [ "$w $h" = "$size $size" ] || fail "icon ${size}x${size} is ${w}x${h}"
done

# The extracted programs run on the system's Qt (no LD_LIBRARY_PATH).
export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=$tmp/runtime
mkdir -m 700 "$XDG_RUNTIME_DIR"
[ "$("$bin/attractor-cli" --version)" = "attractor-cli $version" ] \
    || fail "attractor-cli --version: $("$bin/attractor-cli" --version)"
[ "$("$bin/attractor-workbench" --version 2>/dev/null)" = "attractor-workbench $version" ] \
    || fail "attractor-workbench --version: $("$bin/attractor-workbench" --version 2>&1)"
example=$data/examples/000-fig11-sierpinski-with-control-points.awb
checked=$("$bin/attractor-cli" check "$example") || fail "check exited with $?"
[ "$checked" = "$example: OK, 2 items" ] || fail "check said: $checked"
"$bin/attractor-cli" render "$example" --out "$tmp/figure.png" --size 320x240 > /dev/null \
    || fail "render exited with $?"
[ -s "$tmp/figure.png" ] && [ "$(head -c 8 "$tmp/figure.png" | od -An -tx1 | tr -d ' ')" \
                               = 89504e470d0a1a0a ] || fail "render wrote no PNG"
note "attractor-cli check and render ran from the extracted package"

# The Python module, from the extracted dist-packages, with Debian's Python.
module=$(ls "$root"/usr/lib/python3/dist-packages/attractor_workbench/_native.*.so 2>/dev/null) \
    || fail "the package lacks the Python module in /usr/lib/python3/dist-packages"
[ -f "$root/usr/lib/python3/dist-packages/attractor_workbench/atlas.py" ] \
    || fail "the package lacks attractor_workbench/atlas.py"
if readelf -S "$module" | grep -q '\.debug_info'; then fail "the Python module is not stripped"; fi
PYTHONPATH=$root/usr/lib/python3/dist-packages /usr/bin/python3 - "$example" "$tmp/py.png" <<'PY' \
    || fail "the Python module did not run from the extracted package"
import sys
import attractor_workbench as awb
project = awb.open(sys.argv[1])
item = project.items[0]
item.control_points[0] = [0.1, 0.0]
assert project.can_undo
spectrum = item.maps()[0]["eigenvalues"]
assert abs(spectrum[0] - 1) < 1e-12, spectrum
item.render(sys.argv[2], size=(200, 160))
from attractor_workbench import atlas  # the Dask parts import (python3-distributed)
PY
[ -s "$tmp/py.png" ] || fail "the Python module rendered no PNG"
note "import attractor_workbench ran from the extracted package"

# Desktop entry, AppStream metadata, file type.
log=$(desktop-file-validate "$root/usr/share/applications/attractor-workbench.desktop" 2>&1) \
    || fail "desktop-file-validate: $log"
log=$(appstreamcli validate --no-net \
      "$root/usr/share/metainfo/io.github.attractor_workbench.AttractorWorkbench.metainfo.xml" 2>&1) \
    || fail "appstreamcli validate: $log"
# validate-tree also resolves the metainfo's launchable to the packaged desktop entry.
log=$(appstreamcli validate-tree --no-net "$root" 2>&1) || fail "appstreamcli validate-tree: $log"
note "desktop-file-validate, appstreamcli validate and validate-tree --no-net passed"
mkdir -p "$tmp/mime/packages"
cp "$root/usr/share/mime/packages/attractor-workbench.xml" "$tmp/mime/packages/"
mime_log=$(XDG_DATA_DIRS=$tmp update-mime-database "$tmp/mime" 2>&1) \
    || fail "update-mime-database: $mime_log"
[ -z "$mime_log" ] || fail "update-mime-database: $mime_log"
grep -qxF 'application/x-attractor-workbench:*.awb' "$tmp/mime/globs" || fail "no *.awb glob"
# Heavier than AMR-WB audio's *.awb (50): choosers that go by the name alone say ours.
grep -qxF '60:application/x-attractor-workbench:*.awb' "$tmp/mime/globs2" \
    || fail "the *.awb glob does not weigh 60: $(grep awb "$tmp/mime/globs2")"
grep -qxF 'application/x-attractor-workbench application/json' "$tmp/mime/subclasses" \
    || fail "not a sub-class of application/json"
grep -qa 'application/x-attractor-workbench' "$tmp/mime/magic" || fail "no magic"
grep -qa '"format": "attractor-workbench"' "$example" || fail "the magic misses $example"

# Every release is named: the newest entries of changelog and metainfo are this version.
top=$(zcat "$root/usr/share/doc/attractor-workbench/changelog.gz" | head -n 1)
[[ "$top" == "attractor-workbench ($version) "* ]] \
    || fail "packaging/debian/changelog starts with '$top': add an entry for $version"
release=$(grep -o '<release version="[^"]*"' "$root"/usr/share/metainfo/*.xml | head -n 1)
[ "$release" = "<release version=\"$version\"" ] \
    || fail "the metainfo's newest release is $release: add one for $version"

# Manual pages: no groff warnings, and every command and option of --help documented.
for page in attractor-workbench attractor-cli; do
    warnings=$(LC_ALL=C.UTF-8 MANROFFSEQ='' MANWIDTH=80 \
               man --warnings -E UTF-8 -l -Tutf8 -Z "$root/usr/share/man/man1/$page.1.gz" \
               2>&1 > /dev/null)
    [ -z "$warnings" ] || fail "$page.1: $warnings"
    zcat "$root/usr/share/man/man1/$page.1.gz" | sed 's/\\-/-/g' > "$tmp/$page.1"
done
options() { sed -n 's/^ \{1,4\}\(-[a-z], \)\{0,1\}\(--[a-z][a-z-]*\).*/\2/p'; }
"$bin/attractor-workbench" --help 2>/dev/null | options > "$tmp/gui-options"
[ "$(wc -l < "$tmp/gui-options")" -gt 10 ] || fail "could not read attractor-workbench --help"
while read -r option; do
    grep -qF -- "$option" "$tmp/attractor-workbench.1" \
        || fail "attractor-workbench.1 does not mention $option"
done < "$tmp/gui-options"
commands=$("$bin/attractor-cli" --help | sed -n 's/^  \([a-z][a-z-]\{1,\}\)  .*/\1/p')
[ "$(echo "$commands" | wc -w)" -ge 9 ] || fail "could not read attractor-cli --help"
for command in $commands; do
    grep -qx "\.SS $command" "$tmp/attractor-cli.1" || fail "attractor-cli.1 has no section $command"
    "$bin/attractor-cli" "$command" --help | options | while read -r option; do
        grep -qF -- "$option" "$tmp/attractor-cli.1" \
            || echo "attractor-cli.1 does not mention $command $option"
    done > "$tmp/missing"
    [ ! -s "$tmp/missing" ] || fail "$(cat "$tmp/missing")"
done

if [ "$failures" -gt 0 ]; then
    echo "$failures failure(s)" >&2
    exit 1
fi
echo "package OK: $(basename "$deb")"
