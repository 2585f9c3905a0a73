#!/usr/bin/env bash
# The mingw target's emulator (CMAKE_CROSSCOMPILING_EMULATOR in mingw.cmake): runs a Windows program under Wine.
# Wine 8 on Debian 12 now and then fails a process at its start or its very end, when the machine is busy: glibc's
# loader stops Wine's exit ("Inconsistency detected by ld.so: dl-fini.c: 87: _dl_fini: Assertion ... failed!") after
# the program printed PASSED, the connection to the Wine server breaks ("wine client error:574: sendmsg: Bad file
# descriptor"), or the process ends with a failure before the program printed anything. A CI run failed on the first.
# Such a run (a failure with one of Wine's messages, or with no output at all: every program here says why it fails)
# is run again, twice at most, saying so on stderr; any other result is the program's own and passes through
# unchanged. The program's stdout passes as it writes it; its stderr after it ends (it is read for Wine's messages).
# Measured beside three busy loops: of 8,760 runs of passing tests, 2 failed without a word, and passed run again.
# Wine has also hung once listing a test program's tests (GoogleTest's discovery at build time, which takes a second;
# tests/CMakeLists.txt gives it 60 s in all): a listing is stopped after 12 s and run again; its output is printed at
# the end, once.
# WINE_RUN_LOG=FILE: each failed run's exit status, output size, command and Wine's messages are added to FILE.
set -uo pipefail
output=$(mktemp)
errors=$(mktemp)
trap 'rm -f "$output" "$errors"' EXIT
limit=()
case " $* " in *" --gtest_list_tests "*) limit=(timeout -k 2 12) ;; esac
for attempt in 1 2 3; do
    if [ ${#limit[@]} -gt 0 ]; then
        "${limit[@]}" /usr/lib/wine/wine64 "$@" 2> "$errors" > "$output"
        status=$?
    else
        /usr/lib/wine/wine64 "$@" 2> "$errors" | tee "$output"
        status=${PIPESTATUS[0]}
    fi
    [ -z "${WINE_RUN_LOG:-}" ] || [ "$status" -eq 0 ] ||
        echo "$status out=$(wc -c < "$output") $* :: $(head -c 300 "$errors" | tr '\n' ' ')" >> "$WINE_RUN_LOG"
    if [ "$status" -ne 0 ] && [ "$attempt" -lt 3 ]; then
        if [ ${#limit[@]} -gt 0 ] && { [ "$status" -eq 124 ] || [ "$status" -eq 137 ]; }; then # 137: killed
            echo "wine-run: listing $1's tests took over 12 s, which Wine does when it hangs; running it again" >&2
            continue
        elif grep -qE "Inconsistency detected by ld.so|wine client error:" "$errors"; then
            echo "wine-run: Wine failed running $1 ($(grep -m1 -oE "Inconsistency detected by ld.so[^!]*|wine client error:.*" "$errors")); running it again" >&2
            continue
        elif [ ! -s "$output" ] && [ ! -s "$errors" ]; then
            echo "wine-run: $1 failed (exit status $status) without a word, which Wine does when busy; running it again" >&2
            continue
        fi
    fi
    [ ${#limit[@]} -eq 0 ] || cat "$output"
    cat "$errors" >&2
    exit "$status"
done
