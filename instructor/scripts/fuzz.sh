#!/usr/bin/env bash
# Fuzzes the scene loaders and the image reader with libFuzzer (clang, ASan + UBSan).
#
#   instructor/scripts/fuzz.sh [--minutes N] [--jobs J] [--save-corpus] [TARGET...]
#
# TARGET is nff, p3f or image (default: all three, one after the other, N
# minutes each; default N = 10). The working corpus in build-fuzz/corpus/
# persists between runs, so minutes add up. Every finding (crash, leak,
# timeout, out-of-memory) is saved in build-fuzz/findings/TARGET/ and makes the
# script exit 1; replay one with build-fuzz/instructor/tests/fuzz/fuzz_TARGET FILE.
# --save-corpus adds the inputs that reach new code to instructor/tests/fuzz/corpus/, the
# saved corpus that CTest replays. Each run appends a line to
# build-fuzz/fuzz-runs.tsv: date, target, seconds, executions, corpus size, findings.
set -euo pipefail
cd "$(dirname "$0")/../.."
minutes=10 jobs=1 save=0 targets=()
while [ $# -gt 0 ]; do
    case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --save-corpus) save=1; shift ;;
    nff | p3f | image) targets+=("$1"); shift ;;
    *) echo "fuzz.sh: unknown argument '$1' (targets: nff p3f image)"; exit 2 ;;
    esac
done
[ ${#targets[@]} -gt 0 ] || targets=(nff p3f image)
[[ "$minutes" =~ ^[0-9]+$ ]] && [ "$minutes" -ge 1 ] || { echo "fuzz.sh: --minutes must be a whole number >= 1"; exit 2; }
command -v clang++ > /dev/null || { echo "fuzz.sh: needs clang++ (apt-get install clang)"; exit 2; }

build=build-fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWHITTED_FUZZ=ON > /dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/fuzz_}" > "$build/fuzz-build.log" 2>&1 ||
    { tail -30 "$build/fuzz-build.log"; exit 1; }

status=0
for target in "${targets[@]}"; do
    corpus="$build/corpus/$target" findings="$build/findings/$target" log="$build/logs/$target-$(date +%Y%m%d-%H%M%S).log"
    mkdir -p "$corpus" "$findings" "$build/logs"
    cp -n instructor/tests/fuzz/corpus/"$target"/* "$corpus"/ 2> /dev/null || true
    before=$(find "$findings" -type f | wc -l)
    echo "fuzzing $target for $minutes min with $jobs job(s); log: $log"
    started=$SECONDS
    # Exit codes of libFuzzer are findings; they are counted below.
    "$build/instructor/tests/fuzz/fuzz_$target" "$corpus" -dict="instructor/tests/fuzz/$target.dict" -max_total_time=$((minutes * 60)) \
        -timeout=10 -rss_limit_mb=3072 -malloc_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$findings/" $([ "$jobs" -gt 1 ] && echo "-jobs=$jobs -workers=$jobs") > "$log" 2>&1 || true
    # With -jobs, each job writes fuzz-N.log in the working folder.
    for job_log in fuzz-*.log; do [ -f "$job_log" ] && { cat "$job_log" >> "$log"; rm "$job_log"; }; done
    execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
    seconds=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | head -1 | awk '{print $2}')
    found=$(($(find "$findings" -type f | wc -l) - before))
    size=$(find "$corpus" -type f | wc -l)
    # The time it really ran: a finding stops libFuzzer early.
    printf '%s\t%s\t%d\t%d\t%d\t%d\n' "$(date -u +%Y-%m-%dT%H:%M:%SZ)" "$target" $((SECONDS - started)) "$execs" "$size" "$found" \
        >> "$build/fuzz-runs.tsv"
    echo "  $execs executions (${seconds:-?}/s per job), corpus $size inputs, $found new finding(s)"
    if [ "$found" -gt 0 ]; then
        status=1
        find "$findings" -type f -newer "$log" -o -type f -cnewer "$log" | sed 's/^/  finding: /' | sort -u
        grep -m3 -E 'ERROR: |fuzz property broken|runtime error' "$log" | sed 's/^/  /'
    fi
    if [ "$save" = 1 ]; then
        added=$("$build/instructor/tests/fuzz/fuzz_$target" -merge=1 "instructor/tests/fuzz/corpus/$target" "$corpus" 2>&1 |
                    grep -o 'added [0-9]* new units' || echo "added 0 new units")
        echo "  instructor/tests/fuzz/corpus/$target: $added"
    fi
done
echo "all runs so far (build-fuzz/fuzz-runs.tsv):"
awk -F'\t' '{m[$2] += $3; e[$2] += $4; f[$2] += $6} END {for (t in m) printf "  %-6s %6.1f min  %12d executions  %d finding(s)\n", t, m[t] / 60, e[t], f[t]}' \
    "$build/fuzz-runs.tsv"
exit $status
