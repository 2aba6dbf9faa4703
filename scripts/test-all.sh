#!/usr/bin/env bash
# Everything CI checks (.ci/run), in three stages that stop at the first failure:
#   1. the sources as clang-format writes them (scripts/check-format.sh), then the Release build
#      with the default compiler (gcc) and every test;
#   2. a second tree built with clang under AddressSanitizer + UndefinedBehaviorSanitizer, with
#      libFuzzer linked into the fuzz targets, and every test again (zero findings allowed);
#   3. a short fuzz run of each target in that tree: its corpus and regressions replayed, then
#      RTPRO_FUZZ_SECONDS (default 12) of fuzzing per target, two targets at a time.
# RTPRO_TEST_STAGES=1 (or 1,2) runs fewer stages. Sanitizer options and the documented leak
# suppressions are compiled into the sanitizer build (cmake/sanitizer_options.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
stages=",${RTPRO_TEST_STAGES:-1,2,3},"
fuzz_seconds="${RTPRO_FUZZ_SECONDS:-12}"

# Each stage's start, and at the end the seconds each took: CI's budget is 30 minutes in all.
timings=""
stage_started=$SECONDS
stage() {
  [[ -z ${stage_name:-} ]] || timings+="  ${stage_name}: $((SECONDS - stage_started)) s"$'\n'
  stage_name="$1"
  stage_started=$SECONDS
  printf '\n==== rtpro test stage %s (%s) ====\n' "$1" "$(date +%T)"
}

if [[ $stages == *,1,* ]]; then
  stage "1: format check and gcc Release build"
  scripts/check-format.sh
  cmake -S . -B build -G Ninja
  cmake --build build
  stage "1: Release tests"
  ctest --test-dir build -j2 --output-on-failure
fi

if [[ $stages == *,2,* || $stages == *,3,* ]]; then
  stage "2: clang ASan+UBSan build"
  CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DRTPRO_SANITIZE=address,undefined -DRTPRO_FUZZ=ON -DRTPRO_BUILD_BENCHMARKS=OFF
  cmake --build build-asan
  # Two at a time: under the sanitizers most tests use one core; tests/CMakeLists.txt runs the
  # ones that kill, cap or start ranks alone (SERIAL). The χ² suites (*Chi2*, and
  # Microfacet's *MatchesItsPdf*) are left to stage 1: they draw millions of samples to test
  # distributions, half the sanitizer run's time, through sample() and pdf() code that the renders
  # and the other BSDF and light tests run here too.
  [[ $stages != *,2,* ]] || stage "2: ASan+UBSan tests"
  [[ $stages != *,2,* ]] || GTEST_FILTER='-*Chi2*:*MatchesItsPdf*' ctest --test-dir build-asan -j2 --output-on-failure
fi

if [[ $stages == *,3,* ]]; then
  stage "3: fuzz smoke run, ${fuzz_seconds} s per target"
  for pair in "scene obj" "ply gltf" "image journal" "vdb hair"; do
    # shellcheck disable=SC2086
    scripts/fuzz.sh --build build-asan --seconds "$fuzz_seconds" --parallel $pair
  done
fi
stage "done"
printf 'seconds per stage:\n%s  in all: %s s\n' "$timings" "$SECONDS"
