#!/usr/bin/env bash
# CI: the benchmark tools (make bench's whitted-bench, the POV-Ray scene writer,
# the Embree harness when Embree is installed) build and pass their own tests.
# They stay out of `make test` to keep it quick; this builds them in build-bench/.
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BENCH_BUILD_DIR:-build-bench}
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BENCH=ON > /dev/null
cmake --build "$BUILD" -j"$JOBS" --target bench_all > "$BUILD.log" 2>&1 || { tail -40 "$BUILD.log"; exit 1; }
(cd "$BUILD" && ctest -L bench -j"$JOBS" --output-on-failure) | tail -5
# One real, tiny benchmark run end to end (POV-Ray and Embree when present).
"$BUILD"/whitted-bench --flake 2 --size 64 --runs 1 --warmup 0 --out "$BUILD/bench-results" > "$BUILD/bench.log" 2>&1 \
  || { cat "$BUILD/bench.log"; exit 1; }
for file in results.md results.json chart.svg; do
  test -s "$BUILD/bench-results/$file" || { echo "test-bench: whitted-bench wrote no $file"; exit 1; }
done
grep -q '^| flake2 ' "$BUILD/bench-results/results.md" || { echo "test-bench: no flake2 row in results.md"; exit 1; }
echo "bench tools: built, tested, and a tiny benchmark ran"
# How long a scene with a course-sized skybox takes to load (printed; a figure, not a pass or fail).
BUILD_DIR=$BUILD JOBS=$JOBS bash instructor/scripts/skybox-load.sh | tail -1
