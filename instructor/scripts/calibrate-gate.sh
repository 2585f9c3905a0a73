#!/usr/bin/env bash
# Instructors: measure how far correct variants of the reference drift from it,
# to set the image gate (framework/include/whitted/image_compare.hpp) a few
# times above the largest difference. Variants: -O0, clang, a secondary-ray
# offset 100 times larger and smaller, and lab 1 computed in float
# (instructor/tests/calibration/). Renders every lab scene, hidden scene and the classic
# scene with each, and compares with `whitted diff`. Takes several minutes.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
work=${WORK:-$root/build-calibration}
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
mkdir -p "$work"

build() { # name, extra cmake arguments...
    local name=$1; shift
    test -f "$work/$name/CMakeCache.txt" || cmake -S "$root" -B "$work/$name" -DBUILD_TESTING=OFF "$@" > /dev/null
    cmake --build "$work/$name" -j"$jobs" --target whitted whitted-student > "$work/$name.log" 2>&1
}
variant_labs() { # name, offset, [float lab 1]
    mkdir -p "$work/labs-$1"
    cp solution/*.cpp "$work/labs-$1/"
    sed -i "s/kRelativeOffset = 1e-7/kRelativeOffset = $2/" "$work/labs-$1/02_shadows.cpp"
    [ $# -lt 3 ] || cp instructor/tests/calibration/float_01_ray_casting.cpp "$work/labs-$1/01_ray_casting.cpp"
}

build reference -DCMAKE_BUILD_TYPE=Release
build O0 -DCMAKE_BUILD_TYPE=Debug
CXX=clang++ build clang -DCMAKE_BUILD_TYPE=Release
variant_labs offset_x100 1e-5 && build offset_x100 -DWHITTED_LABS_DIR="$work/labs-offset_x100"
variant_labs offset_div100 1e-9 && build offset_div100 -DWHITTED_LABS_DIR="$work/labs-offset_div100"
variant_labs float 1e-4 float && build float -DWHITTED_LABS_DIR="$work/labs-float"

declare -A binary=([reference]=reference/whitted [O0]=O0/whitted [clang]=clang/whitted
                   [offset_x100]=offset_x100/whitted-student [offset_div100]=offset_div100/whitted-student
                   [float]=float/whitted-student)
render_all() { # variant
    local out="$work/images-$1"; mkdir -p "$out"
    for scene in scenes/[0-9][0-9]_*.p3f instructor/tests/hidden/scenes/*.p3f; do
        local name; name=$(basename "$scene" .p3f)
        local size="--width 160 --height 120"
        [[ $name == *hidden ]] && size="--width 200 --height 150"
        "$work/${binary[$1]}" render "$scene" --stage "$((10#${name:0:2}))" $size -o "$out/$name.pfm" -q
    done
    "$work/${binary[$1]}" render scenes/whitted_1980.p3f --width 128 --height 128 -o "$out/whitted_1980.pfm" -q
}
for v in "${!binary[@]}"; do render_all "$v"; done

for v in O0 clang offset_x100 offset_div100 float; do
    echo "== $v"
    for image in "$work"/images-reference/*.pfm; do
        name=$(basename "$image" .pfm)
        printf '  %-24s ' "$name"
        "$work/reference/whitted" diff "$image" "$work/images-$v/$name.pfm" || true
    done
done
