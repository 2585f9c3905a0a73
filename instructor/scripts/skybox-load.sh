#!/usr/bin/env bash
# How long a scene with a course-sized skybox takes to load: scenes/course_depth_of_field.p3f with six
# 2048 x 2048 JPEG faces (instructor/bench/skybox_faces_main.cpp), parsed RUNS times (5 by default) by
# `whitted render --stats-json`; prints each parse time and their median. BUILD_DIR: build/ by default.
#   bash instructor/scripts/skybox-load.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build}
runs=${RUNS:-5}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BENCH=ON > /dev/null # as make bench: the bench tools
cmake --build "$build" -j"${JOBS:-2}" --target whitted whitted-skybox-faces > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/whitted-skybox-faces" "$work/sky"
sed 's/^env .*/env sky/' scenes/course_depth_of_field.p3f > "$work/course_dof.p3f"
for run in $(seq "$runs"); do
    "$build/whitted" render "$work/course_dof.p3f" --width 32 --height 24 -q -o "$work/course_dof.png" \
        --stats-json "$work/stats-$run.json"
done
python3 - "$work" "$runs" <<'PY'
import json, os, statistics, sys
work, runs = sys.argv[1], int(sys.argv[2])
faces = sum(os.path.getsize(os.path.join(work, "sky", name)) for name in os.listdir(os.path.join(work, "sky")))
seconds = [json.load(open(f"{work}/stats-{run}.json"))["parse_seconds"] for run in range(1, runs + 1)]
print(f"skybox-load: six 2048x2048 JPEG faces, {faces / 1e6:.1f} MB; parse " + ", ".join(f"{s:.3f}" for s in seconds) + " s")
print(f"skybox-load: median {statistics.median(seconds):.3f} s on {os.cpu_count()} CPUs")
PY
