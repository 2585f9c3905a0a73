#!/usr/bin/env bash
# The CPU time each side of the link uses in the reference's image tests, idle
# or beside N busy loops: how much a busy machine adds to what the CPU limit
# judges (instructor/docs/grading.md, "Time is judged in CPU time").
#   instructor/scripts/image-test-cpu.sh [BUSY_LOOPS]   (default 0; build/ built)
set -euo pipefail
cd "$(dirname "$0")/../.."
tests=${BUILD_DIR:-build}/instructor/tests
busy=${1:-0}
work=$(mktemp -d)
loops=()
cleanup() {
    [ ${#loops[@]} -eq 0 ] || kill "${loops[@]}" 2> /dev/null || true
    rm -rf "$work"
}
trap cleanup EXIT
for _ in $(seq 1 "$busy"); do
    sh -c 'while :; do :; done' &
    loops+=($!)
done
printf '%-20s %8s %8s %8s  (seconds; %d busy loops)\n' lab worker checker wall "$busy"
for checker in "$tests"/check_[0-9]*; do
    lab=${checker##*/check_}
    worker=$(realpath "$tests/worker_${lab}_reference")
    # The worker's own CPU time, through a wrapper the checker starts as its worker.
    printf '#!/bin/sh\nexec /usr/bin/time -o %s -f "%%U %%S" %s "$@"\n' "$work/worker.txt" "$worker" > "$work/worker.sh"
    chmod +x "$work/worker.sh"
    /usr/bin/time -o "$work/pair.txt" -f "%U %S %e" "$checker" --worker="$work/worker.sh" --gtest_filter='Lab*Image.*' > /dev/null 2>&1 || true
    read -r wu ws < "$work/worker.txt"
    read -r pu ps pe < "$work/pair.txt"
    python3 -c "print('%-20s %8.2f %8.2f %8.2f' % ('$lab', $wu + $ws, $pu + $ps - $wu - $ws, $pe))"
done
