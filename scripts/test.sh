#!/usr/bin/env bash
# The README's test command and what CI runs (.ci/run), in stages:
#   suite     Release build (build/), every ctest; the fuzz targets replay their
#             corpus and regression inputs (label fuzz-corpus)
#   sanitize  the same suite built with ASan + UBSan (scripts/sanitize.sh, build-asan/)
#   fuzz      each libFuzzer target for $FUZZ_SECONDS seconds (default 20), nproc at once
#             (scripts/fuzz.sh, build-fuzz/)
# No argument runs all three in that order, stopping at the first failure;
# `scripts/test.sh suite` is the quick everyday check. Times on 2 cores:
# docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."

stages=("$@")
[ ${#stages[@]} -gt 0 ] || stages=(suite sanitize fuzz)
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
