#!/usr/bin/env bash
# The test suite under sanitizers (docs/reliability.md), one build each:
#   scripts/sanitize.sh asan       ASan + UBSan build of everything, every ctest (scenario.* too, unless
#                                  CTEST_EXCLUDE is set, e.g. CTEST_EXCLUDE='^scenario\.')
#   scripts/sanitize.sh asan-unit  the same build, only what CI runs: the unit tests of the readers and
#                                  their neighbours (unit_sdk, unit_config, unit_plugins, unit_io,
#                                  unit_eval) and the fuzz regression replays (not fuzz.bt, which needs the
#                                  map library): the targets that build in a few minutes
#   scripts/sanitize.sh tsan       TSan build of the threaded tests (map thread, background optimiser,
#                                  particle-filter threads, mapper, a recording converted as it is read):
#                                  unit_map, unit_graph, unit_matching, unit_pipeline, unit_io's
#                                  LiveConversionTest
#   scripts/sanitize.sh all        asan then tsan (the default)
# Any sanitizer report fails the test that caused it (halt_on_error; UBSan does not recover).
# Build folders: ASAN_DIR (build-asan), TSAN_DIR (build-tsan).
set -euo pipefail
cd "$(dirname "$0")/.."
MODE="${1:-all}"
ASAN_DIR="${ASAN_DIR:-build-asan}"
TSAN_DIR="${TSAN_DIR:-build-tsan}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)

configure() {  # configure DIR FLAGS
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUNIMAP_WERROR=OFF "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS="$2" -DCMAKE_C_FLAGS="$2" -DCMAKE_EXE_LINKER_FLAGS="$2" \
    -DCMAKE_SHARED_LINKER_FLAGS="$2" -DCMAKE_MODULE_LINKER_FLAGS="$2" >/dev/null
}

asan() {  # asan [ctest args...]
  configure "$ASAN_DIR" "-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  if [ "$MODE" = asan-unit ]; then
    # The CI subset, the fuzz replays and what they load (plugins, test plugins).
    cmake --build "$ASAN_DIR" -j2 --target unimap_payload_fixed_3d unimap_payload_rotating_3d \
      unimap_payload_rotating_2d unimap_payload_fixed_2d unimap_broken_plugins unit_sdk unit_config unit_plugins unit_io unit_eval unit_api \
      $(cd "$ASAN_DIR" && make help | sed -n 's/^\.\.\. \(fuzz_replay_[a-z0-9_]*\)$/\1/p' | grep -v '^fuzz_replay_bt$')
  else
    cmake --build "$ASAN_DIR" -j2
  fi
  export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:strict_string_checks=1"
  export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizer-suppressions/lsan.txt"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  ctest --test-dir "$ASAN_DIR" --output-on-failure -j2 "$@"
}

tsan() {
  configure "$TSAN_DIR" "-fsanitize=thread -fno-omit-frame-pointer"
  # (set before the build: gtest_discover_tests runs the test binaries)
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/scripts/sanitizer-suppressions/tsan.txt"
  cmake --build "$TSAN_DIR" -j2 --target unimap_payload_rotating_2d unimap_payload_fixed_3d \
    unimap_payload_rotating_3d unit_map unit_graph unit_matching unit_pipeline unit_io
  # Left out: the one test that runs the particle filter on several oneTBB threads. Debian's libtbb is
  # not instrumented, so TSan cannot see the hand-over of a split range to a worker and reports races
  # inside TBB's own parallel_for / partitioner headers (docs/reliability.md); suppressing those
  # frames would also hide races in the loop bodies they run.
  ctest --test-dir "$TSAN_DIR" --output-on-failure -j2 -R '^unit_(map|graph|matching|pipeline)\.|^unit_io\.LiveConversionTest\.' \
    -E 'GaussianParticleFilter\.DeterministicForASeedAndThreadCount'
}

case "$MODE" in
  asan) if [ -n "${CTEST_EXCLUDE:-}" ]; then asan -E "$CTEST_EXCLUDE"; else asan; fi ;;
  asan-unit) asan -R '^(unit_(sdk|config|plugins|io|eval|api)\.|fuzz\.)' -E '^fuzz\.bt$' ;;
  tsan) tsan ;;
  all) if [ -n "${CTEST_EXCLUDE:-}" ]; then asan -E "$CTEST_EXCLUDE"; else asan; fi; tsan ;;
  *) echo "usage: $0 [asan|asan-unit|tsan|all]" >&2; exit 2 ;;
esac
