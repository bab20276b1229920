# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: the sanitizers' run-time options.
# halt_on_error: the first report ends the process with a failure status. (No
# strict_string_checks: it reports libxkbcommon's legitimate strndup of an unterminated name.)
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:detect_stack_use_after_return=0:check_initialization_order=1:allocator_may_return_null=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
# Qt Test stops a test function after 5 minutes; instrumented code may need longer.
export QTEST_FUNCTION_TIMEOUT=1700000
# The tests' wall-clock limits (waiting for a render or a worker) scaled for instrumented code.
export AWB_TEST_TIME_SCALE=10
# ThreadSanitizer (scripts/sanitize.sh thread): the first report fails the test; suppressions
# for third-party code only (tests/sanitizers/tsan.supp, each with its reason).
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:history_size=4:suppressions=$PWD/tests/sanitizers/tsan.supp"
