#!/usr/bin/env bash
# Proves that the lab tests test something (instructors and CI):
#   - the reference solution passes every test (make test does this too);
#   - every untouched stub fails every test of its own lab, and only of labs that use it;
#   - lab files whose every function returns a constant (nothing, something, an input handed
#     back: instructor/scripts/lib/constant-labs.py) fail every test of their lab;
#   - every catalogued mistake in instructor/tests/mistakes/ is caught by its lab's tests,
#     and by its public tests alone (a hidden-only catch is a gap in what students can run).
# Builds in build-proofs/ with -DWHITTED_PROOFS=ON; prints "mistakes caught: N/N".
# BUILD_DIR=build uses make's build instead (CI, after make test: only the proofs'
# own programs compile), and turns the proofs off there again at the end.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build-proofs}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

if [ -f "$build/CMakeCache.txt" ] && grep -q '^WHITTED_PROOFS:BOOL=OFF$' "$build/CMakeCache.txt"; then
    cmake -S . -B "$build" -DWHITTED_PROOFS=ON > /dev/null
    trap "cmake -S '$PWD' -B '$(realpath "$build")' -DWHITTED_PROOFS=OFF > /dev/null" EXIT
fi
test -f "$build/CMakeCache.txt" || cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DWHITTED_PROOFS=ON > /dev/null
cmake --build "$build" -j"$jobs" > "$build.log" 2>&1 || { tail -40 "$build.log"; exit 1; }

cd "$build"
status=0
ctest -j"$jobs" -L 'stub|independence|mistake|constant' --output-junit proofs.xml > proofs.log 2>&1 || status=1
count() { grep -cE "$1" proofs.log || true; }
stub_total=$(count 'Test +#[0-9]+: stub\.')
stub_failed=$(grep -E 'Test +#[0-9]+: stub\.' proofs.log | grep -cv ' Passed ' || true)
indep_total=$(count 'Test +#[0-9]+: independence\.')
indep_failed=$(grep -E 'Test +#[0-9]+: independence\.' proofs.log | grep -cv ' Passed ' || true)
constant_total=$(count 'Test +#[0-9]+: constant\.')
constant_failed=$(grep -E 'Test +#[0-9]+: constant\.' proofs.log | grep -cv ' Passed ' || true)
# missed PREFIX: the tests PREFIX.* that did not pass (a mistake that no test caught).
missed() { grep -E "Test +#[0-9]+: $1\\." proofs.log | grep -v ' Passed ' | sed -E "s/.*: ($1\\.[^ ]+).*/\\1/" || true; }
mistakes_total=$(count 'Test +#[0-9]+: mistake\.')
mistakes_missed=$(missed mistake)
mistakes_caught=$((mistakes_total - $(printf '%s' "$mistakes_missed" | grep -c . || true)))
public_total=$(count 'Test +#[0-9]+: mistake_public\.')
public_missed=$(missed mistake_public)
public_caught=$((public_total - $(printf '%s' "$public_missed" | grep -c . || true)))

echo "stub tests that fail as they must: $((stub_total - stub_failed))/$stub_total"
echo "labs unaffected by later stubs: $((indep_total - indep_failed))/$indep_total"
echo "constant-answer lab files failing every test of their lab: $((constant_total - constant_failed))/$constant_total"
echo "mistakes caught: $mistakes_caught/$mistakes_total"
if [ -n "$mistakes_missed" ]; then
    echo "not caught:"
    printf '  %s\n' $mistakes_missed
fi
echo "mistakes caught by the public tests alone: $public_caught/$public_total"
if [ -n "$public_missed" ]; then
    echo "caught only by hidden tests (add a public test that catches each):"
    printf '  %s\n' $public_missed
fi
if [ "$status" -ne 0 ]; then
    grep -E '\*\*\*|Failed' proofs.log | head -40
    exit 1
fi
