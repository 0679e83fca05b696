#!/usr/bin/env bash
# The checks after the normal test run (scripts/run-tests.sh): a separate
# build folder (build-sanitize) with clang, AddressSanitizer +
# UndefinedBehaviorSanitizer and libFuzzer instrumentation; runs the unit
# tests of the input-facing libraries (common, io, eval) and the fuzz
# regression replays under ASan + UBSan, then every fuzz target for
# HSLAM_FUZZ_SECONDS (default 25) seconds. Fails on any sanitizer report,
# crash, leak or timeout. The subset (not the whole suite) keeps CI under 30
# minutes on 2 cores: see README "Tests".
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-sanitize
jobs=$(nproc)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g0" \
  -DCMAKE_CXX_COMPILER=clang++-14 -DHSLAM_FUZZ=ON -DHSLAM_BUILD_BENCHMARKS=OFF >/dev/null
# hslam-carmen2rawlog and hslam-evaluate: the bad-input tests of io / eval run
# them, so the apps' own input handling is checked under the sanitizers too.
targets=(test_common test_io test_eval hslam-carmen2rawlog hslam-evaluate fuzz_replay
         fuzz_carmen_line fuzz_ini_options fuzz_arcos_packets fuzz_rawlog_reader fuzz_tiled_map fuzz_tum_reader)
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The real-data CARMEN tests convert whole Radish logs (minutes under ASan;
# their code paths are the ones the small tests cover); the *App tests run
# app binaries (hslam-process ...) that this build does not make.
status=0
total=0
for t in test_common test_io test_eval; do
  set +e
  "$build/bin/$t" --gtest_filter='-*RealData*:*App.*' > "$build/$t.log" 2>&1
  rc=$?
  set -e
  n=$(grep -o '\[==========\] [0-9]* tests' "$build/$t.log" | tail -1 | grep -o '[0-9]*' || echo 0)
  total=$((total + n))
  echo "sanitize: $t: $n tests, exit $rc"
  if [ $rc -ne 0 ]; then tail -60 "$build/$t.log"; status=1; fi
done
for t in carmen_line ini_options arcos_packets rawlog_reader tiled_map tum_reader; do
  "$build/bin/fuzz_replay" "$t" tests/fuzz/corpus/$t tests/fuzz/regressions/$t || status=1
done
echo "sanitize: $total unit tests + 6 fuzz replays run under ASan + UBSan"
[ $status -eq 0 ] || { echo "sanitize: FAILED"; exit 1; }
bash scripts/fuzz.sh "$build" "${HSLAM_FUZZ_SECONDS:-25}"
