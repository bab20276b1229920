#!/usr/bin/env bash
# The build-time figures of the README ("Development"), measured as CI meets them: a fresh
# clone of HEAD in a temporary folder, an empty ccache, nothing built.
#   scripts/build-times.sh [main] [edit] [asan] [tsan]     (default: all four)
#     main   `AWB_NO_GUI=1 bash scripts/main.sh`: packages checked, configure, build of the two
#            programs, the gallery
#     edit   then, the whole tree built, one core file edited (a comment added to
#            src/core/analysis/Spectrum.cpp): `cmake --build build` recompiles it and relinks
#            everything that uses it (programs, tests, benchmarks)
#     asan   the instrumented build of scripts/sanitize.sh and scripts/fuzz.sh (build-asan/)
#     tsan   the ThreadSanitizer build of `scripts/sanitize.sh thread` (build-tsan/)
# Prints each time and the ten longest compile steps of the normal build (.ninja_log).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
what=("$@")
[ ${#what[@]} -gt 0 ] || what=(main edit asan tsan)
work="$(mktemp -d /tmp/awb-build-times.XXXXXX)"
export CCACHE_DIR="$work/ccache"
git clone -q "$src" "$work/src"
cd "$work/src"
results=()
timed() {
  local name="$1"; shift
  local t0 t1
  t0=$(date +%s.%N)
  "$@" > "$work/$name.log" 2>&1 || { echo "build-times: $name failed, see $work/$name.log"; exit 1; }
  t1=$(date +%s.%N)
  results+=("$(awk -v n="$name" -v a="$t0" -v b="$t1" -v c="$*" 'BEGIN { printf "%-6s %8.1f s  %s", n, b - a, c }')")
  echo "${results[-1]}"
}
for w in "${what[@]}"; do
  case "$w" in
    main) AWB_NO_GUI=1 timed main bash scripts/main.sh ;;
    edit)
      [ -f build/build.ninja ] || timed setup bash scripts/setup.sh
      cmake --build build > /dev/null  # the tests too (main.sh builds the programs only)
      echo "// $(date +%s) an edit (scripts/build-times.sh)" >> src/core/analysis/Spectrum.cpp
      timed edit cmake --build build
      git checkout -q src/core/analysis/Spectrum.cpp ;;
    asan)
      bash scripts/configure-asan.sh > /dev/null
      timed asan cmake --build build-asan --parallel "$(nproc)" ;;
    tsan)
      bash scripts/configure-tsan.sh > /dev/null
      timed tsan cmake --build build-tsan --parallel "$(nproc)" ;;
  esac
done
if [ -f build/.ninja_log ]; then
  echo "longest compile steps of build/ (seconds, two at a time on $(nproc) cores):"
  awk 'NR > 1 { printf "%7.1f  %s\n", ($2 - $1) / 1000, $4 }' build/.ninja_log | sort -k2 -u \
    | sort -rn | head -10
fi
printf '%s\n' "${results[@]}"
echo "build-times: the clone and its builds are in $work (remove it when done)"
