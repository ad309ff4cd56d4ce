#!/usr/bin/env bash
# Coverage-guided fuzzing of every parser (docs/robustness.md): builds the
# libFuzzer targets in build-fuzz (clang, STENCIL_FUZZ=ON: ASan + UBSan), then
# runs each target for S seconds from a scratch copy of its corpus and
# regression inputs (the repository is never written). Findings go to
# build-fuzz/crashes/<target>/; each target's result and time is printed and
# appended to build-fuzz/fuzz-history.tsv. Exit status nonzero on any finding.
#
#   scripts/fuzz.sh [--seconds S] [--jobs J] [--keep-going] [target...]
#     --seconds S    per target (default 600)
#     --jobs J       targets run at once (default 1)
#     --keep-going   fork mode: go on after a finding, to collect several
#     target...      default: all (build-fuzz/fuzz/fuzz_targets.txt)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=600
max_jobs=1
keep_going=0
requested=()
while (($#)); do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --jobs) max_jobs="$2"; shift 2 ;;
    --keep-going) keep_going=1; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) requested+=("$1"); shift ;;
  esac
done
[[ "$seconds" =~ ^[0-9]+$ && "$seconds" -gt 0 ]] || { echo "fuzz.sh: --seconds needs a positive integer" >&2; exit 2; }
[[ "$max_jobs" =~ ^[0-9]+$ && "$max_jobs" -gt 0 ]] || { echo "fuzz.sh: --jobs needs a positive integer" >&2; exit 2; }
command -v clang++ > /dev/null || { echo "fuzz.sh: needs clang++ with libFuzzer (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }

build=build-fuzz
# Sanitizer reports with their stacks (libFuzzer itself stops at the first).
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTENCIL_FUZZ=ON -DBUILD_TESTING=OFF > /dev/null
cmake --build "$build" --target fuzz_targets -j"${JOBS:-$(nproc)}"
mapfile -t all < "$build/fuzz/fuzz_targets.txt"
targets=("${requested[@]:-${all[@]}}")
for t in "${targets[@]}"; do
  [[ " ${all[*]} " == *" $t "* ]] || { echo "fuzz.sh: no target '$t' (targets: ${all[*]})" >&2; exit 2; }
done

# Extra libFuzzer flags per target: a dictionary, and room for deeply nested formulas.
target_flags() {
  case "$1" in
    obj_mesh) echo "-dict=fuzz/dict/obj.dict" ;;
    off_mesh) echo "-dict=fuzz/dict/off.dict" ;;
    quad_json_table|quad_json_regular|curve_table_json|surface_table_verify) echo "-dict=fuzz/dict/json_tables.dict" ;;
    curve_scheme|quad_scheme|triangle_scheme) echo "-dict=fuzz/dict/scheme.dict" ;;
    scheme_param) echo "-dict=fuzz/dict/scheme.dict -max_len=65536" ;;
    expression|expression_real) echo "-dict=fuzz/dict/expression.dict -max_len=65536" ;;
    parameter) echo "-dict=fuzz/dict/expression.dict" ;;
  esac
}

# Runs one target; its summary line goes to $build/work/<target>/result.
run_target() {
  local t="$1" work="$build/work/$1" crashes="$build/crashes/$1"
  rm -rf "$work"
  mkdir -p "$work/corpus" "$work/tmp" "$crashes"
  cp -r "fuzz/corpus/$t/." "$work/corpus/"
  [ -d "fuzz/regressions/$t" ] && cp -r "fuzz/regressions/$t/." "$work/corpus/"
  local mode=()
  ((keep_going)) && mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  local start status=0 before
  before=$(find "$crashes" -type f | wc -l)
  start=$(date +%s)
  # shellcheck disable=SC2046  # target_flags is a word list
  TMPDIR="$PWD/$work/tmp" "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$crashes/" $(target_flags "$t") "${mode[@]}" "$work/corpus" \
    > "$work/log" 2>&1 || status=$?
  local took=$(($(date +%s) - start))
  local runs
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$work/log" | grep -o '[0-9]*$' | tail -1 || true)
  [ -n "$runs" ] || runs=$(grep -o '^#[0-9]*' "$work/log" | tail -1 | tr -d '#' || true)
  local found=$(($(find "$crashes" -type f | wc -l) - before))
  local result
  if [ "$status" -eq 0 ] && [ "$found" -eq 0 ]; then
    result="clean"
  else
    result="FINDING ($found new file(s) in $crashes; log $work/log)"
  fi
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%Y-%m-%dT%H:%MZ)" "$(hostname)" "$t" "$took" "${runs:-?}" "${result%% *}" >> "$build/fuzz-history.tsv"
  echo "$t: $result, $took s, ${runs:-?} runs, corpus $(find "$work/corpus" -type f | wc -l) inputs" > "$work/result"
  rm -rf "$work/tmp"
}

echo "fuzz.sh: ${#targets[@]} target(s), $seconds s each, $max_jobs at a time"
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$max_jobs" ]; do wait -n || true; done
  run_target "$t" &
done
wait
status=0
for t in "${targets[@]}"; do
  cat "$build/work/$t/result"
  grep -q ": clean," "$build/work/$t/result" || status=1
done
exit "$status"
