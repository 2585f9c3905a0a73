#!/usr/bin/env bash
# Runs every test and prints how far each lab is: tests passed, and which
# functions are still stubs. Exits non-zero while any test fails.
set -uo pipefail
build=${1:-build}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
source_dir=$(pwd)
cd "$build" || exit 1

ctest -j"$jobs" > Testing/progress.log 2>&1
status=$?
log=Testing/Temporary/LastTest.log

echo
echo "Lab progress"
echo "------------"
unfinished=""
# The labs of the lab table (framework/include/whitted/lab_table.hpp): number, stem, title.
lab_rows=$(./whitted labs --tsv) || { echo "lab-progress: $build/whitted labs failed" >&2; exit 1; }
while IFS=$'\t' read -r n stem title _; do
    lines=$(grep -E "Test +#[0-9]+: lab$n\." Testing/progress.log)
    total=$(printf '%s\n' "$lines" | grep -c . || true)
    passed=$(printf '%s\n' "$lines" | grep -c ' Passed ' || true)
    if [ "$total" -eq 0 ]; then continue; fi
    mark="  "
    [ "$passed" -eq "$total" ] && mark="ok"
    printf '%s lab %d (%s): %d/%d tests pass\n' "$mark" "$n" "$title" "$passed" "$total"
    if [ "$passed" -ne "$total" ]; then
        lab_file="$source_dir/labs/$stem.cpp"
        left=0
        [ -f "$lab_file" ] && left=$(grep -cE "^[[:space:]]*not_implemented\(\);" "$lab_file" || true)
        [ "${left:-0}" -gt 0 ] && echo "     $left function(s) in labs/$stem.cpp still call not_implemented()"
        stubs=$(grep -oE "labs/$stem\.cpp:[0-9]+: [a-z_]+\(\) is not implemented yet" "$log" 2>/dev/null | sort -u)
        if [ -n "$stubs" ]; then
            printf '%s\n' "$stubs" | sed 's/^/     /'
        elif [ -n "$unfinished" ]; then
            echo "     its tests use lab $unfinished, which is not done yet"
        else
            echo "     some results are wrong: make test LAB=$n"
        fi
        [ -n "$unfinished" ] || unfinished=$n
    fi
done <<< "$lab_rows"
# The failed tests whose output says a lab function is not implemented yet: they wait for a lab, they are not broken.
waiting=$(awk '/^[0-9]+\/[0-9]+ Test: / { name = $3 } /is not implemented yet/ && name != "" { print name; name = "" }' "$log" 2>/dev/null | sort -u)
for group in framework integration cli; do
    lines=$(grep -E "Test +#[0-9]+: $group\." Testing/progress.log)
    total=$(printf '%s\n' "$lines" | grep -c . || true)
    passed=$(printf '%s\n' "$lines" | grep -c ' Passed ' || true)
    # A skipped test (one that cannot run here, e.g. a file-permission check as root) is no failure.
    skipped=$(printf '%s\n' "$lines" | grep -c '\*\*\*Skipped' || true)
    [ "$total" -gt 0 ] || continue
    failed_names=$(printf '%s\n' "$lines" | grep -vE ' Passed |\*\*\*Skipped' | sed -E 's/.*Test +#[0-9]+: ([^ ]+) .*/\1/')
    wait_count=0
    [ -n "$waiting" ] && [ -n "$failed_names" ] && wait_count=$(printf '%s\n' "$failed_names" | grep -cxF -f <(printf '%s\n' "$waiting") || true)
    mark="  "
    [ $((passed + skipped)) -eq "$total" ] && mark="ok"
    note=""
    [ "$skipped" -gt 0 ] && note=", $skipped skipped here"
    [ "$wait_count" -gt 0 ] && note="$note, $wait_count wait for a lab that is not done yet"
    [ -n "$note" ] && note="$note (ctest -R '^$group\.' lists them)"
    printf '%s %s: %d/%d tests pass%s\n' "$mark" "$group" "$passed" "$total" "$note"
done
echo
if [ $status -ne 0 ]; then
    echo "Details of a lab's failures: make test LAB=3   (for lab 3)"
    echo "Failed image tests leave yours/reference/diff pictures in $build/test-output/."
fi
exit $status
