#!/usr/bin/env python3
"""Checks that a CTest run ran every test the source tree defines (issue 29: a missing test
binary, or a CMake condition that silently drops a layer's tests, must not pass).

The tree defines, independently of CMake's conditions:
  - one test per tests/<layer>/test_*.cpp, named <layer>_test_<name>;
  - the literal `add_test(NAME <name>` of tests/CMakeLists.txt;
  - fuzz_replay_<target> for each `awb_fuzz_target(<target>` of tests/fuzz/CMakeLists.txt.
Each build kind leaves out what it documents: the instrumented builds the Debian package test
(`packaging_test_package`); the AddressSanitizer build the Python suite and the OpenGL view
(AWB_ASAN_LEFT_OUT in tests/CMakeLists.txt), and the GUI's and the window's unless AWB_ASAN_GUI=1;
the ThreadSanitizer build runs the tests labelled `threads` only
(AWB_THREADED_TESTS in tests/CMakeLists.txt, kept complete by scripts/threaded-tests.py) below
the GUI -- the GUI's and the window's too with AWB_TSAN_GUI=1 -- and each of those must exist.

  check-tests.py BUILD_DIR [--kind normal|asan|tsan] [--log CTEST_OUTPUT]

With --log, the `... tests failed out of N` line of the run must count every expected test.
Exits 1 with the missing names otherwise.
"""
import argparse
import os
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
LAYERS = ["core", "cli", "model", "gui", "i18n"]
LEFT_OUT = {
    "normal": set(),
    # tests/CMakeLists.txt's AWB_ASAN_LEFT_OUT: the Python suite, the OpenGL view and the
    # Regularity Atlas window (it runs the Python module)
    "asan": {"packaging_test_package", "python_test_module", "gui_test_surface_view_gl",
             "gui_test_regularity_atlas_window"},
    "tsan": {"packaging_test_package"},
}


def tree_tests():
    names = set()
    for layer in LAYERS:
        for f in sorted((ROOT / "tests" / layer).glob("test_*.cpp")):
            names.add(f"{layer}_{f.stem}")
    cmake = (ROOT / "tests" / "CMakeLists.txt").read_text()
    names.update(re.findall(r"add_test\(NAME\s+([A-Za-z0-9_]+)\s", cmake))
    fuzz = (ROOT / "tests" / "fuzz" / "CMakeLists.txt").read_text()
    names.update("fuzz_replay_" + t for t in re.findall(r"^awb_fuzz_target\(([A-Za-z0-9_]+)", fuzz, re.M))
    return names


def build_tests(build_dir, label=None):
    args = ["ctest", "--test-dir", str(build_dir), "--show-only=json-v1"]
    if label:
        args += ["-L", label]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return {t["name"] for t in json.loads(out)["tests"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build_dir")
    ap.add_argument("--kind", choices=sorted(LEFT_OUT), default="normal")
    ap.add_argument("--log")
    a = ap.parse_args()

    expected = tree_tests() - LEFT_OUT[a.kind]
    defined = build_tests(a.build_dir)
    problems = []
    if a.kind == "tsan":
        # The ThreadSanitizer build compiles the threaded tests' files only (tests/CMakeLists.txt,
        # awb_add_tests): it must define every one of them, and need not define the others
        # (the fuzz replays, defined in every build, stay, unrun).
        cmake = (ROOT / "tests" / "CMakeLists.txt").read_text()
        threaded = set(re.search(r"set\(AWB_THREADED_TESTS([^)]*)\)", cmake).group(1).split())
        expected = {t for t in expected
                    if t in threaded or not re.match(r"(core|cli|model|gui|i18n)_test_", t)}
    missing = sorted(expected - defined)
    if missing:
        problems.append(f"the tree defines {len(missing)} test(s) that {a.build_dir} does not: "
                        + ", ".join(missing)
                        + " (a test binary or a package its CMake condition needs is missing)")
    if a.kind == "tsan":
        cmake = (ROOT / "tests" / "CMakeLists.txt").read_text()
        listed = set(re.search(r"set\(AWB_THREADED_TESTS([^)]*)\)", cmake).group(1).split())
        expected = build_tests(a.build_dir, "threads")
        unlabelled = sorted(listed - expected)
        if unlabelled:
            problems.append("AWB_THREADED_TESTS names tests that do not carry the label "
                            "'threads' in " + a.build_dir + ": " + ", ".join(unlabelled))
        # scripts/sanitize.sh thread runs the GUI's and the window's only with AWB_TSAN_GUI=1.
        if os.environ.get("AWB_TSAN_GUI", "0") != "1":
            expected = {t for t in expected if not re.match(r"(gui|i18n)_", t)}
    # scripts/sanitize.sh (address) runs the GUI's and the window's only with AWB_ASAN_GUI=1.
    if a.kind == "asan" and os.environ.get("AWB_ASAN_GUI", "0") != "1":
        expected = {t for t in expected if not re.match(r"(gui|i18n)_", t)}
    if a.log:
        text = pathlib.Path(a.log).read_text(errors="replace")
        m = re.findall(r"tests passed, (\d+) tests? failed out of (\d+)", text)
        ran = int(m[-1][1]) if m else 0
        if ran < len(expected):
            problems.append(f"the run ran {ran} tests, the tree defines {len(expected)}")
    if problems:
        for p in problems:
            print(f"check-tests: FAILED: {p}", file=sys.stderr)
        return 1
    print(f"check-tests: {len(expected)} tests defined by the tree, all in {a.build_dir}"
          + (" and all run" if a.log else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
