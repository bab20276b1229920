#!/usr/bin/env bash
# The sanitizer builds (clang), each in its own folder, each running its part of the CTest
# suite; any report fails the run.
#   scripts/sanitize.sh [address] [CTEST ARGUMENTS...]
#       AddressSanitizer + UndefinedBehaviorSanitizer (-fno-sanitize-recover=all: the first
#       report ends the test with a failure) and LeakSanitizer in build-asan/, with the
#       suppressions of tests/sanitizers/lsan.supp (third-party libraries only, each with its
#       reason): every test below the GUI -- the core, the model, the CLI, the fuzz replays --
#       which is where files and numbers come in. AWB_ASAN_GUI=1 adds the GUI's and the
#       window's tests (and builds the window): run it when a change touches the window's code.
#       CI leaves them to the normal suite (issue 43's 35-minute budget: 7 of its minutes on the
#       2-core machine, the window's build and tests under AddressSanitizer). The same build
#       holds the fuzz targets of scripts/fuzz.sh.
#   scripts/sanitize.sh thread [CTEST ARGUMENTS...]
#       ThreadSanitizer in build-tsan/: the tests labelled `threads` (the tests that start a
#       thread) below the GUI -- the engine's workers and merges, the chaos streams, the flame
#       game, cancellation, the CLI's threads -- with tests/sanitizers/tsan.supp (third-party
#       only). AWB_TSAN_GUI=1 adds the GUI's and the window's (render, mesh, frame and analysis
#       workers, playback): run it when a change touches the window's threads. CI leaves them
#       to the AddressSanitizer suite and the normal one (issue 43: 4 min of the 35-minute
#       budget, the GUI's build and tests under TSan).
# CTest arguments narrow the run, e.g. `scripts/sanitize.sh thread -R gui_` .
# Prints the build's and the tests' times; scripts/check-tests.py checks that every test the
# tree defines for the build ran (unless CTest arguments narrow it).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=address
case "${1:-}" in
  address|thread) mode="$1"; shift ;;
esac
bash scripts/setup.sh --packages-only
start=$(date +%s)
if [ "$mode" = thread ]; then
  dir=build-tsan kind=tsan
  bash scripts/configure-tsan.sh
  # Only what the tests labelled `threads` run: their test executables and the programs they
  # start; the model's tests and the fuzz replays start no thread. A test <layer>_test_<name>
  # runs <layer>_tests (tests/CMakeLists.txt). The names, not the commands: before the first
  # build CTest's list has no command for an executable that does not exist yet.
  tsan_select=(-L threads)
  programs=(attractor-cli)
  if [ "${AWB_TSAN_GUI:-0}" = 1 ]; then
    programs+=(attractor-workbench)
  else
    tsan_select+=(-E '^(gui|i18n)_')
  fi
  targets=$(ctest --test-dir "$dir" "${tsan_select[@]}" --show-only=json-v1 | python3 -c '
import json, sys
tests = json.load(sys.stdin)["tests"]
if not tests:
    sys.exit("no test is labelled threads")
print(" ".join(sorted({t["name"].split("_test_")[0] + "_tests" for t in tests})))')
  cmake --build "$dir" --parallel "$(nproc)" --target $targets "${programs[@]}"
else
  dir=build-asan kind=asan
  bash scripts/configure-asan.sh
  asan_select=()
  if [ "${AWB_ASAN_GUI:-0}" = 1 ]; then
    cmake --build "$dir" --parallel "$(nproc)"
  else
    # The layers' test executables and the fuzz replays the selected tests run, and the CLI
    # they start (as for ThreadSanitizer: by the tests' names, which exist before the build).
    asan_select=(-E '^(gui|i18n)_')
    targets=$(ctest --test-dir "$dir" "${asan_select[@]}" --show-only=json-v1 | python3 -c '
import json, sys
names = set()
for t in json.load(sys.stdin)["tests"]:
    n = t["name"]
    if "_test_" in n:
        names.add(n.split("_test_")[0] + "_tests")
    elif n.startswith("fuzz_replay_"):
        names.add(n)
print(" ".join(sorted(names)))')
    cmake --build "$dir" --parallel "$(nproc)" --target $targets attractor-cli
  fi
fi
built=$(date +%s)
source scripts/sanitizer-env.sh
status=0
log="$dir/ctest.log"
# Instrumented code runs several times slower: tests get 1800 s each (tests/CMakeLists.txt).
selection=()
[ "$mode" = thread ] && selection=("${tsan_select[@]}")
[ "$mode" = address ] && selection=("${asan_select[@]}")
ctest --test-dir "$dir" --output-on-failure --parallel "$(nproc)" "${selection[@]}" "$@" 2>&1 \
  | tee "$log" || status=$?
if [ $# -eq 0 ]; then
  python3 scripts/check-tests.py "$dir" --kind "$kind" --log "$log" || status=1
fi
end=$(date +%s)
echo "sanitize ($mode): build $((built - start)) s, tests $((end - built)) s, exit status $status"
exit $status
