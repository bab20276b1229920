#!/usr/bin/env bash
# Fuzzing (issue 14): builds the libFuzzer targets of tests/fuzz with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-asan/ (the build of scripts/sanitize.sh), and runs each for
# SECONDS (default 60):
#   fuzz_project_loader  any bytes as a project file: refused with a message, or saved, loaded
#                        and saved again to the same bytes
#   fuzz_item_ifs        the same, and every attractor item's IFS built or refused with a reason
#                        (the item readers and the schemes on the loaded fields)
#   fuzz_png_project     any bytes as a PNG figure with its project (text chunks, zTXt and
#                        iTXt inflated within 64 MB): refused with a message, or the project
#                        through fuzz_project_loader's checks
#   fuzz_svg_project     the same for an SVG figure (its <metadata>, the XML reader)
#   fuzz_cli_arguments   the command line of `attractor-cli points` (start sets, addresses,
#                        depths, names) on a real example
#   fuzz_mesh_obj, fuzz_mesh_off, fuzz_mesh_ply
#                        any bytes as a mesh file of that format (core/mesh/MeshFiles.h):
#                        refused with a message, or a mesh that writeObj and readMesh give back
#                        unchanged; small readers, so 20 s each (AWB_FUZZ_MESH_SECONDS) in the
#                        run of all targets, SECONDS when named
#   fuzz_fractint_ifs    any bytes as a Fractint .ifs library: every entry kept (and given back
#                        by the writer) or named with its place; 20 s like the mesh readers
#   fuzz_flame           any bytes as a flam3 genome: every flame imported (and given back by
#                        the writer) or named with its place, every loss a warning; 20 s
# Seeds: the examples, the bad files of the tests (tests/fuzz/seeds/) and the crashes found so
# far (tests/fuzz/regressions/, also loaded by the normal test suite). One input may take at
# most 1 s, 1.5 GB (the bound every bad input must keep, issue 45); leaks are reported. A crash, a hang or a leak fails the run and leaves its
# input in build-asan/artifacts/<target>/.
# The mutations follow a fixed seed (AWB_FUZZ_SEED, default 1), so a run is repeatable: CI's
# 60-second smoke explores the same inputs as `scripts/fuzz.sh 60` here, up to the machine's
# speed. Long campaigns should vary it (AWB_FUZZ_SEED=0: libFuzzer picks one and logs it).
# Targets run side by side, one per core (AWB_FUZZ_JOBS).
#   scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
SECS="${1:-60}"
SEED="${AWB_FUZZ_SEED:-1}"
shift || true
TARGETS=("$@")
ALL=0
if [ ${#TARGETS[@]} -eq 0 ]; then
  ALL=1
  TARGETS=(fuzz_project_loader fuzz_item_ifs fuzz_png_project fuzz_svg_project
           fuzz_cli_arguments fuzz_mesh_obj fuzz_mesh_off fuzz_mesh_ply fuzz_fractint_ifs
           fuzz_flame)
fi
MESH_SECS="${AWB_FUZZ_MESH_SECONDS:-20}"
bash scripts/setup.sh --packages-only
bash scripts/configure-asan.sh
cmake --build build-asan --parallel "$(nproc)" --target "${TARGETS[@]}"
source scripts/sanitizer-env.sh
export QT_QPA_PLATFORM=offscreen
# One target per core at a time (each fuzzer is one process), in the order listed: on 2 cores
# the five targets of 60 s take 3 minutes, and the three mesh targets of 20 s each run one
# after the other beside the fifth, so that all end together. AWB_FUZZ_JOBS overrides.
jobs="${AWB_FUZZ_JOBS:-$(nproc)}"
fuzz_one() {
  local t="$1" secs="$SECS"
  if [ "$ALL" = 1 ] \
     && [[ "$t" == fuzz_mesh_* || "$t" == fuzz_fractint_ifs || "$t" == fuzz_flame ]] \
     && [ "$MESH_SECS" -lt "$SECS" ]; then
    secs="$MESH_SECS"
  fi
  local corpus="build-asan/corpus/$t" artifacts="build-asan/artifacts/$t/"
  mkdir -p "$corpus" "$artifacts"
  local seeds=()
  case "$t" in
    fuzz_project_loader|fuzz_item_ifs)
      seeds=(examples tests/fuzz/seeds/loader tests/fuzz/regressions/loader) ;;
    fuzz_png_project) seeds=(tests/fuzz/seeds/png tests/fuzz/regressions/png) ;;
    fuzz_svg_project) seeds=(tests/fuzz/seeds/svg tests/fuzz/regressions/svg) ;;
    fuzz_cli_arguments) seeds=(tests/fuzz/seeds/cli tests/fuzz/regressions/cli) ;;
    fuzz_mesh_*|fuzz_fractint_ifs|fuzz_flame)
      seeds=(tests/fuzz/seeds/${t#fuzz_} tests/fuzz/regressions/${t#fuzz_}) ;;
  esac
  local existing=() s
  for s in "${seeds[@]}"; do [ -d "$s" ] && existing+=("$s"); done
  local log="build-asan/$t.log" rc=0
  echo "fuzz: $t for $secs s, seed $SEED"
  "build-asan/bin/$t" -seed="$SEED" -max_total_time="$secs" -timeout=1 -rss_limit_mb=1536 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" \
    "$corpus" "${existing[@]}" > "$log" 2>&1 || rc=1
  local runs
  runs=$(grep -a -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
  if [ $rc -ne 0 ]; then
    echo "fuzz: $t FAILED; the input is in $artifacts, the log in $log"
    grep -a -E "ERROR|SUMMARY|Test unit written" "$log" | head -5 || true
  fi
  echo "fuzz: $t: $runs executions in $secs s, corpus $(ls "$corpus" | wc -l) inputs"
  return $rc
}
status=0
running=0
for t in "${TARGETS[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
