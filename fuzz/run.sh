#!/usr/bin/env bash
# Builds the fuzz targets (build-fuzz/, clang with libFuzzer, ASan and UBSan), fuzzes each for FUZZ_SECONDS (default
# 60) from generated seed corpora, then runs every regression input in a process of its own (stb_image keeps its
# failure reason across calls, so one input must not mask what the next would do). Exits non-zero if anything
# crashed; crashing inputs are left in build-fuzz/crashes/<target>/, logs in build-fuzz/logs/.
# Environment: FUZZ_SECONDS, FUZZ_TARGETS (a subset, space-separated), JOBS (build parallelism, default 2),
# PBR_ASSETS (default ../shared/assets).
set -uo pipefail
cd "$(dirname "$0")/.."

seconds=${FUZZ_SECONDS:-60}
targets=(${FUZZ_TARGETS:-scene_json_fuzzer gltf_fuzzer radiance_hdr_fuzzer texture_fuzzer})
build=build-fuzz
assets=${PBR_ASSETS:-../shared/assets}

scripts/install-deps.sh --fuzz || exit 1
mkdir -p "$build/logs"
if ! { CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DPBR_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
         -DPBR_WERROR=OFF && cmake --build "$build" -j "${JOBS:-2}" --target "${targets[@]}"; } \
     >"$build/logs/build.log" 2>&1; then
  tail -40 "$build/logs/build.log"
  exit 1
fi
python3 fuzz/make_corpus.py . "$assets" "$build/corpus" || exit 1
python3 fuzz/make_regressions.py "$build/regressions" || exit 1

export UBSAN_OPTIONS=print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan.supp
# Each target process writes its inputs in a folder of its own under PBR_FUZZ_TMP (fuzz/temp_input.cpp); one that
# crashes or times out cannot remove it, so the whole tree goes at the end of the run.
PBR_FUZZ_TMP=$(mktemp -d /dev/shm/pbr-fuzz.XXXXXX 2>/dev/null || mktemp -d) || exit 1
export PBR_FUZZ_TMP
trap 'rm -rf "$PBR_FUZZ_TMP"' EXIT

failed=0
# One line per failure and its log, repeated at the end with the log's report: a CI log's tail is what its reader
# sees first.
crashes=()
crash_logs=()
for t in "${targets[@]}"; do
  mkdir -p "$build/crashes/$t"
  dict=()
  [[ $t == scene_json_fuzzer || $t == gltf_fuzzer ]] && dict=(-dict=fuzz/json.dict)
  echo "fuzz: $t for ${seconds}s"
  # Every input runs in well under a second on an idle machine; 30 s leaves room for a busy one (an input counted
  # as a hang at 10 s ran in 0.4 s alone) while a real endless loop is still caught.
  if ! "$build/fuzz/$t" "$build/corpus/$t" "${dict[@]}" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
      -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$build/crashes/$t/" >"$build/logs/$t.log" 2>&1; then
    crashes+=("fuzz: $t CRASHED: $(grep -m1 -E 'ERROR: |runtime error|deadly signal|timeout after|out-of-memory' \
      "$build/logs/$t.log") (input: $(ls "$build/crashes/$t" | head -1))")
    crash_logs+=("$build/logs/$t.log")
    echo "${crashes[-1]}"
    failed=1
  fi
  grep -E '^#[0-9]+[[:space:]]+DONE|^stat::number_of_executed_units' "$build/logs/$t.log" | sed "s/^/fuzz: $t /"
done

for t in "${targets[@]}"; do
  for input in fuzz/regressions/"$t"/* "$build"/regressions/"$t"/*; do
    [[ -f $input ]] || continue
    log="$build/logs/regression-$t-$(basename "$input").log"
    if "$build/fuzz/$t" -timeout=10 "$input" >"$log" 2>&1; then
      echo "regression: $t $input: ok"
    else
      crashes+=("regression: $t $input: CRASHED: $(grep -m1 -E 'ERROR: |runtime error|deadly signal|timeout after' \
        "$log")")
      crash_logs+=("$log")
      echo "${crashes[-1]}"
      failed=1
    fi
  done
done
for i in "${!crashes[@]}"; do
  echo "${crashes[$i]}"
  grep -m1 -A40 -E '==[0-9]+==ERROR|runtime error|deadly signal|timeout after|out-of-memory' "${crash_logs[$i]}"
done
exit $failed
