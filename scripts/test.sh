#!/usr/bin/env bash
# The README's test command and what CI runs (.ci/run), in stages:
#   suite     Release build (build/), every ctest; the fuzz targets replay their
#             corpus and regression inputs (label fuzz-corpus)
#   fuzz      each libFuzzer target, built with ASan + UBSan, replays its corpus
#             and regression inputs and fuzzes for $FUZZ_SECONDS seconds
#             (default 20), nproc at once (scripts/fuzz.sh, build-fuzz/)
#   sanitize  the whole suite built with ASan + UBSan (scripts/sanitize.sh,
#             build-asan/): about 75 min on 2 cores, so not part of CI's
#             90-minute run; run it as `scripts/test.sh sanitize` before a stop
# No argument runs suite and fuzz in that order, stopping at the first failure;
# `scripts/test.sh suite` is the quick everyday check. Times on 2 cores:
# docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."

stages=("$@")
[ ${#stages[@]} -gt 0 ] || stages=(suite fuzz)
for stage in "${stages[@]}"; do
  case "$stage" in
    suite|sanitize|fuzz) ;;
    *) echo "test.sh: unknown stage '$stage' (stages: suite sanitize fuzz)" >&2; exit 2 ;;
  esac
done

bash scripts/install-deps.sh
# The tests' scratch files go to a directory of our own, emptied after every
# stage, so that no stage depends on (or fills) the machine's /tmp.
scratch="$PWD/.test-tmp"
trap 'rm -rf "$scratch"' EXIT
for stage in "${stages[@]}"; do
  start=$(date +%s)
  echo "=== test.sh: stage $stage"
  rm -rf "$scratch" && mkdir -p "$scratch"
  export TMPDIR="$scratch"
  case "$stage" in
    suite)
      cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
      cmake --build build -j"$(nproc)"
      ctest --test-dir build --output-on-failure -j"$(nproc)"
      ;;
    sanitize) bash scripts/sanitize.sh ;;
    fuzz) bash scripts/fuzz.sh --seconds "${FUZZ_SECONDS:-20}" --jobs "$(nproc)" ;;
  esac
  rm -rf "$scratch"
  echo "=== test.sh: stage $stage passed in $(($(date +%s) - start)) s"
done
