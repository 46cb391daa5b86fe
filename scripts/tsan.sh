#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the tests of lutkit's threaded code with ThreadSanitizer and runs them.
# Usage: scripts/tsan.sh [BUILD_DIR]   (default build-tsan)
#
# What runs on several threads, and the test executable that drives it:
#   lut::parallelFor/parallelForDynamic: samplers, resampling, adjustments   lutlib_tests
#   the LUT maths (compose, smooth, invert, diff, heat maps), lutkit check   ops_tests
#   the preview pipeline's stages (bloom, grading, display)                  pipeline_tests
#   the game: compensation, authoring and its refinement, the error bounds   smash_tests
#   the parallel .cube row reader; image files (OIIO's own threads)          formats_tests
#   the round trip's fit                                                     roundtrip_tests (Fit.*)
#   lutkit match: samples, histograms, transport, table, measures            match_tests (the
#                                                                            smaller cases)
#   lutkit apply's batch, preview and convert of a folder (a ThreadSanitizer  cli_tests (CliApply.*,
#   -built lutkit)                                                           CliConvertBatch.*,
#                                                                            CliPreview.*)
#   the editor's document model and preview rendering                       gui_model_tests
#   lut::Progress (cancelled from another thread), diffs, heat maps and     lutlib_tests, ops_tests,
#   image reads and writes reporting progress and stopping                  formats_tests
# Not here: gui_preview_tests, gui_editor_tests and gui_editor_tasks_tests, which drive the
# editor's workers (gui/model: PreviewWorker, FileLoader, BackgroundTask). Each hands its task to a
# QThreadPool and its delivery back with a queued QMetaObject::invokeMethod; both hand-overs are
# synchronised inside Debian's libQt6Core, which is not built with ThreadSanitizer, so each is
# reported as a race (75 reports in gui_preview_tests, all on the task's functor, its captures
# and the delivery; none elsewhere).
# Annotating the two hand-overs (__tsan_release/__tsan_acquire on a static key) removes the reports
# on lutkit's data but leaves those on Qt's own objects (slot objects and QWaitConditions created
# and freed on different threads), so checking the worker needs a Qt built with ThreadSanitizer or
# a hand-over through std::thread and std::mutex.
# Only these executables are built (cmake --build --target), not the whole suite: that would not
# fit the CI time budget (CONTRIBUTING.md); their sources compile in batches (LUTKIT_UNITY_TESTS,
# tests/CMakeLists.txt), about half the CPU of one file at a time with an empty ccache. They run directly, not through ctest, two at a time.
# A data race stops the executable with exit code 66 and the report in BUILD_DIR/logs/<name>.log;
# a child process (the lutkit a CLI test runs) fails its test the same way.
# OpenImageIO is not built with ThreadSanitizer, which cannot see its own synchronisation (a
# lock-free string table, a thread pool): scripts/tsan.supp tells it not to track the memory calls
# OIIO makes (called_from_lib). lutkit's own code is always checked.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-tsan}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
jobs="$(nproc)"

# executable:gtest filter ("" = every test in it). Left out: tests that only cost time under
# ThreadSanitizer (the exhaustive lattice and float-parsing sweeps, the fit's 50 s coverage case,
# the 256^3 LUT maths, the check of every neutral size and every fixture: the same loops run on
# smaller LUTs in the tests that stay; the cases made once per OpenColorIO test file (Files/*:
# ~265 cases through convert and bake, 6-25 s each here, ~45 min of the stage), whose threaded
# sampling OcioCorpusRead.* and OcioCorpusBake.* drive on a few files).
runs=(
  "lutlib_tests:-AllMethods/Policy.LatticePointsReturnEntriesExactly/*:Lut3D.IdentityIsExactForEverySize"
  "ops_tests:-LargeLuts.Size256:CheckDefects.NeutralOfEverySizeHasNoFinding:CheckFiles.EveryFixtureAndOcioTestFileWithoutACrash"
  "pipeline_tests:"
  "smash_tests:"
  "formats_tests:-CubeRead.FloatParsingMatchesFromChars:Files/*"
  "roundtrip_tests:Fit.*-Fit.NaturalImageWarnsAboutCoverage"
  "match_tests:MatchStiff.*:MatchReport.*:HistogramMatch.*"
  "cli_tests:CliApply.*:CliPreview.*:CliConvertBatch.*"
)

start=$(date +%s)
# -O1 as in scripts/sanitize.sh: readable traces, tests still bearable under the ~5-15x slowdown.
cmake -S "$root" -B "$build" -DLUTKIT_SANITIZE_THREAD=ON -DLUTKIT_BUILD_BENCH=OFF -DLUTKIT_UNITY_TESTS=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" >/dev/null
targets=()
for r in "${runs[@]}"; do targets+=("${r%%:*}"); done
# The editor's tests exist when Qt 6 was found.
if cmake --build "$build" --target help | grep "gui_editor_tests" >/dev/null; then
  runs+=("gui_model_tests:")
  targets+=(gui_model_tests)
fi
cmake --build "$build" -j"$jobs" --target "${targets[@]}"
built=$(date +%s)
echo "tsan: build took $(( built - start )) s"

export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan.supp:${TSAN_OPTIONS:-}"
export QT_QPA_PLATFORM=offscreen
mkdir -p "$build/logs"

# Runs one executable (with its filter) and prints one line; the log keeps the rest.
run_one() {
  local name="${1%%:*}" filter="${1#*:}" t0 rc=0
  t0=$(date +%s)
  local args=()
  [ -n "$filter" ] && args+=("--gtest_filter=$filter")
  (cd "$build/bin" && "./$name" "${args[@]}") >"$build/logs/$name.log" 2>&1 || rc=$?
  if [ $rc -eq 0 ]; then
    echo "tsan: $name ok ($(( $(date +%s) - t0 )) s)"
  else
    echo "tsan: $name FAILED (exit $rc, $(( $(date +%s) - t0 )) s); from $build/logs/$name.log:"
    grep -A40 -m1 "WARNING: ThreadSanitizer\|\[  FAILED  \]" "$build/logs/$name.log" | head -60 || true
  fi
  return $rc
}

failed=()
pids=()
names=()
for r in "${runs[@]}"; do
  # Keep at most $jobs executables running.
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  run_one "$r" &
  pids+=($!)
  names+=("${r%%:*}")
done
for i in "${!pids[@]}"; do
  wait "${pids[$i]}" || failed+=("${names[$i]}")
done
echo "tsan: tests took $(( $(date +%s) - built )) s"
if [ ${#failed[@]} -ne 0 ]; then
  echo "tsan: FAILED: ${failed[*]} (logs in $build/logs/)"
  exit 1
fi
echo "tsan: no data races in ${#runs[@]} executables, $(( $(date +%s) - start )) s in total"
