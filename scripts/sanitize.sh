#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UBSan (docs/robustness.md):
# configures build-asan (RelWithDebInfo, STENCIL_SANITIZE=ON: every target of
# the project instrumented, system libraries not), builds it and runs every
# ctest, the fuzz-corpus replays included. Any test failure or sanitizer
# report makes the exit status nonzero.
#
#   scripts/sanitize.sh                  everything
#   scripts/sanitize.sh -L fuzz-corpus   extra arguments go to ctest
set -euo pipefail
cd "$(dirname "$0")/.."
jobs="${JOBS:-$(nproc)}"

# Stop at the first report, with its stack; leaks count. Set here unless the
# caller chose its own.
export ASAN_OPTIONS="${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"

start=$(date +%s)
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTENCIL_SANITIZE=ON > /dev/null
cmake --build build-asan -j"$jobs"
built=$(date +%s)
status=0
ctest --test-dir build-asan --output-on-failure -j"$jobs" "$@" || status=$?
done_at=$(date +%s)
echo "sanitize: build $((built - start)) s, tests $((done_at - built)) s: $([ "$status" -eq 0 ] && echo clean || echo FAILED)"
exit "$status"
