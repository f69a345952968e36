#!/usr/bin/env bash
# The whole test suite, as CI runs it (.ci/run):
#   1. packages + Release build with -Werror (scripts/setup.sh), the style checks
#      (scripts/check_style.sh: clang-format, pyflakes), then every test except the `slow` label;
#   2. the fuzzers (scripts/fuzz.sh: libFuzzer with clang, 25 s for each target it lists);
#   3. an AddressSanitizer + UndefinedBehaviorSanitizer build of the same tests (without the
#      `slow` and `no_sanitizer` labels).
# Options: SLIPFRONT_SKIP_FUZZ=1 skips step 2, SLIPFRONT_SKIP_SANITIZE=1 step 3;
# SLIPFRONT_SLOW=1 adds the `slow` tests.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)

SLIPFRONT_CMAKE_ARGS="-DSLIPFRONT_WERROR=ON" bash scripts/setup.sh
bash scripts/check_style.sh
# As root (CI) the SLURM tests must start their single-host cluster, not skip.
if [ "$(id -u)" -eq 0 ]; then export SLIPFRONT_REQUIRE_SLURM=1; fi
exclude="slow"
[ "${SLIPFRONT_SLOW:-0}" = "1" ] && exclude="^$"
ctest --test-dir build --output-on-failure -j2 -LE "$exclude" --timeout 900

if [ "${SLIPFRONT_SKIP_FUZZ:-0}" != "1" ]; then
  bash scripts/fuzz.sh
fi

if [ "${SLIPFRONT_SKIP_SANITIZE:-0}" != "1" ]; then
  cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSLIPFRONT_SANITIZE=ON \
    -DSLIPFRONT_WERROR=ON >&2
  cmake --build build-sanitize -j"$(nproc)" >&2
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-sanitize --output-on-failure -j2 -LE "slow|no_sanitizer" --timeout 1800
fi
echo "test.sh: all suites passed in $(( $(date +%s) - start )) s"
