#!/usr/bin/env bash
# Checks `whitted completion bash` as bash meets it: the script parses, and,
# sourced, it completes commands and options.
#   bash completion_check.sh path/to/whitted
set -euo pipefail
whitted=$1
"$whitted" completion bash | bash -n || { echo "completion_check: bash -n rejects the script" >&2; exit 1; }
# shellcheck disable=SC1090
source <("$whitted" completion bash)
function_name=_$(basename "$whitted" | tr -c 'A-Za-z0-9\n' '_')

# What Tab offers after the words given (the last one being completed).
offered() {
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    "$function_name"
    echo "${COMPREPLY[*]}"
}
expect() {
    local want=$1
    shift
    local found
    found=$(offered "$@")
    [ "$found" = "$want" ] || { echo "completion_check: '$*' offers '$found', expected '$want'" >&2; exit 1; }
}
expect render whitted ren
expect "--width" whitted render scene.p3f --wid
expect "--amplified" whitted diff a.png --am
expect "--version" whitted --vers
expect "--tsv" whitted labs --t
expect "" whitted render sce # file names, from bash itself (complete -o default)
echo "completion_check: ok"
