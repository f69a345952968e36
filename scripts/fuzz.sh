#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz (clang, ASan + UBSan) in build-fuzz/ and runs
# each for a fixed time, starting from its committed seeds (tests/fuzz/corpus/<target>; the
# inputs it finds go to build-fuzz/corpus/<target>, crashes to build-fuzz/findings/<target>).
# Exits non-zero on the first finding.
#   bash scripts/fuzz.sh                                  # CI budget: 25 s per target
#   FUZZ_SECONDS=3600 bash scripts/fuzz.sh job_parser     # a longer run of one target
#   FUZZ_JOBS=2 FUZZ_SECONDS=1800 bash scripts/fuzz.sh    # two processes per target
# Targets: job_parser study_request query_string byte_range length_fit_record tar_reader.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds="${FUZZ_SECONDS:-25}"
jobs="${FUZZ_JOBS:-1}"
build="${FUZZ_BUILD_DIR:-build-fuzz}"
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(job_parser study_request query_string byte_range length_fit_record tar_reader)

CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSLIPFRONT_FUZZ=ON -DSLIPFRONT_NATIVE=OFF >&2
cmake --build "$build" -j"$(nproc)" --target fuzz_targets >&2

for t in "${targets[@]}"; do
  case "$t" in
    job_parser | study_request) dict=tests/fuzz/job.dict max_len=4096 ;;
    query_string | byte_range) dict=tests/fuzz/query.dict max_len=512 ;;
    length_fit_record) dict=tests/fuzz/record.dict max_len=8192 ;;
    tar_reader) dict=tests/fuzz/tar.dict max_len=8192 ;;
    *) echo "fuzz: unknown target $t" >&2; exit 2 ;;
  esac
  work="$build/corpus/$t"
  findings="$build/findings/$t"
  log="$build/fuzz_$t.log"
  mkdir -p "$work" "$findings"
  options=(-max_total_time="$seconds" -max_len="$max_len" -dict="$dict" -timeout=10
           -rss_limit_mb=2048 -artifact_prefix="$findings/" -print_final_stats=1)
  [ "$jobs" -gt 1 ] && options+=(-fork="$jobs")
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/tests/fuzz/fuzz_$t" "${options[@]}" "$work" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
    tail -n 60 "$log" >&2
    echo "fuzz: $t found a failure (input in $findings/; log $log)" >&2
    exit 1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
  echo "fuzz: $t: ${runs:-?} executions in ${seconds} s, no finding (corpus $(ls "$work" | wc -l) inputs)"
done
