#!/usr/bin/env bash
# Renders every picture that the lab handouts (docs/labs/*.md) show:
#   - each lab's goal picture: its scene at its stage, rendered by the reference;
#   - each gallery entry: a scene rendered by the reference with one catalogued
#     mistake (instructor/tests/mistakes/<lab>/<name>.patch), plus the correct picture of that
#     scene and stage when it is not already a goal picture, plus a difference
#     picture for the mistakes that are hard to see.
# Instructors only: it needs solution/ and instructor/tests/mistakes/. Rerun it after any
# change to the reference, the scenes or the mistakes, and commit the pictures.
#
#   instructor/scripts/render-gallery.sh            # build dir build-gallery, 2 jobs
#   BUILD=build-x JOBS=2 instructor/scripts/render-gallery.sh
set -euo pipefail
cd "$(dirname "$0")/../.."

if [ ! -f solution/01_ray_casting.cpp ] || [ ! -d instructor/tests/mistakes ]; then
    echo "render-gallery: needs the instructor tree (solution/ and instructor/tests/mistakes/)" >&2
    exit 2
fi

build=${BUILD:-build-gallery}
jobs=${JOBS:-2}
out=docs/labs/images
size=(--width 320 --height 240)

# The gallery: lab, mistake, scene, stage, and "diff" when the picture should
# come with a difference picture (mistakes that are hard to see by eye).
gallery=(
    "01_ray_casting y_flipped                 01_ray_casting 1"
    "01_ray_casting aspect_ignored            01_ray_casting 1"
    "01_ray_casting direction_not_normalised  01_ray_casting 1"
    "01_ray_casting plane_hits_behind         01_ray_casting 1"
    "01_ray_casting barycentric_sum_unchecked 01_ray_casting 1"
    "01_ray_casting normal_not_facing_ray     05_refraction  5"
    "02_shadows     no_offset                 02_shadows     2"
    "02_shadows     no_shadow_feeler          02_shadows     2"
    "02_shadows     light_vector_not_normalised 02_shadows   2"
    "02_shadows     kd_without_checker        04_reflection  2"
    "02_shadows     offset_always_outwards    05_refraction  5"
    "03_blinn_phong halfway_not_normalised    03_blinn_phong 3"
    "03_blinn_phong exponent_ignored          03_blinn_phong 3"
    "03_blinn_phong phong_instead_of_blinn    03_blinn_phong 3"
    "03_blinn_phong wo_flipped                03_blinn_phong 3"
    "03_blinn_phong ambient_missing           01_ray_casting 3"
    "04_reflection  glsl_sign                 04_reflection  4"
    "04_reflection  missing_factor_two        04_reflection  4"
    "04_reflection  no_spawn_ray              04_reflection  4"
    "04_reflection  weight_one                04_reflection  4 diff"
    "05_refraction  eta_upside_down           05_refraction  5"
    "05_refraction  always_entering           05_refraction  5"
    "05_refraction  normal_sign               05_refraction  5"
    "05_refraction  tangent_not_normalised    05_refraction  5"
    "05_refraction  no_spawn_ray              05_refraction  5"
    "05_refraction  specular_weight           05_refraction  5"
    "06_fresnel     no_tir_check              06_fresnel     6"
    "06_fresnel     weights_swapped           06_fresnel     6"
    "06_fresnel     sum_not_halved            06_fresnel     6"
    "06_fresnel     snell_upside_down         06_fresnel     6"
    "06_fresnel     always_entering           06_fresnel     6"
    "06_fresnel     schlick                   06_fresnel     6 diff"
    "07_anti_aliasing sum_not_averaged        07_anti_aliasing 7"
    "07_anti_aliasing jitter_ignored          07_anti_aliasing 7 diff"
    "07_anti_aliasing pixel_centre_added      07_anti_aliasing 7"
    "08_soft_shadows  colour_not_shared       08_soft_shadows  8"
    "08_soft_shadows  centre_only             08_soft_shadows  8"
    "08_soft_shadows  jitter_ignored          08_soft_shadows  8 diff"
    "08_soft_shadows  corner_at_the_centre    08_soft_shadows  8"
    "09_depth_of_field focus_on_the_view_plane 09_depth_of_field 9"
    "09_depth_of_field origin_at_the_eye      09_depth_of_field 9"
    "09_depth_of_field radius_is_the_aperture 09_depth_of_field 9"
    "09_depth_of_field naive_polar_map        09_depth_of_field 9 diff"
    "10_bvh           first_hit_is_nearest    10_bvh           10"
    "10_bvh           nearer_child_only       10_bvh           10"
    "10_bvh           slabs_not_swapped       10_bvh           10"
)

# Build the reference renderer and only the mistake renderers the gallery uses.
if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DWHITTED_MISTAKE_RENDERERS=ON -DBUILD_TESTING=ON > /dev/null
fi
targets=(whitted)
for entry in "${gallery[@]}"; do
    read -r lab name _ <<< "$entry"
    targets+=("whitted-mistake-$lab-$name")
done
cmake --build "$build" -j"$jobs" --target "${targets[@]}"

mkdir -p "$out"
render() { # renderer scene stage output
    "$1" render "scenes/$2.p3f" --stage "$3" "${size[@]}" --quiet -o "$4"
}

# Goal pictures: each lab's scene at its stage (the lab table).
while IFS=$'\t' read -r number lab _; do
    render "$build/whitted" "$lab" "$number" "$out/${lab}_goal.png"
done < <("$build/whitted" labs --tsv)

# Lab 7's scene with one ray through each pixel centre, beside its goal.
"$build/whitted" render scenes/07_anti_aliasing.p3f --stage 7 --spp 0 "${size[@]}" --quiet -o "$out/07_anti_aliasing_one_ray.png"
# Lab 9's scene through a pinhole (stage 8), beside its goal.
"$build/whitted" render scenes/09_depth_of_field.p3f --stage 8 "${size[@]}" --quiet -o "$out/09_depth_of_field_pinhole.png"

# Lab 8's scene lit by a point light at the lamp's centre (stage 7), and its shadow pass.
"$build/whitted" render scenes/08_soft_shadows.p3f --stage 7 "${size[@]}" --quiet -o "$out/08_soft_shadows_point_light.png"
"$build/whitted" render scenes/08_soft_shadows.p3f --stage 8 --pass shadow "${size[@]}" --quiet -o "$out/08_soft_shadows_shadow_pass.png"

# Gallery pictures.
for entry in "${gallery[@]}"; do
    read -r lab name scene stage extra <<< "$entry"
    picture="$out/${lab}_${name}.png"
    # A picture with NaN pixels (magenta) makes the renderer exit with 1 after
    # writing it: that is the symptom some galleries show, so only a missing
    # picture is an error.
    rm -f "$picture"
    render "$build/mistakes/whitted-mistake-$lab-$name" "$scene" "$stage" "$picture" 2> /dev/null || test -f "$picture"
    if [ "$stage" = "$((10#${scene:0:2}))" ]; then
        correct="$out/${scene}_goal.png"
    else
        correct="$out/${scene}_stage${stage}.png"
        render "$build/whitted" "$scene" "$stage" "$correct"
    fi
    if [ "${extra:-}" = diff ]; then
        "$build/whitted" diff "$correct" "$picture" --amplified "$out/${lab}_${name}_diff.png" > /dev/null || true
    fi
done
# The debugging tools (docs/labs/debugging.md, and the walkthroughs of labs 2
# and 5): the shadow pass with and without shadow acne; the ray tree of one
# pixel of the lab 5 test picture with eta upside down and with the reference
# (their text goes to $build/gallery-text, to paste into the handouts); every
# pass of the reference on the classic scene.
text="$build/gallery-text"
mkdir -p "$text"
acne="$build/mistakes/whitted-mistake-02_shadows-no_offset"
bent="$build/mistakes/whitted-mistake-05_refraction-eta_upside_down"
"$build/whitted" render scenes/02_shadows.p3f --stage 2 --pass shadow --quiet -o "$out/02_shadows_shadow_pass.png"
"$acne" render scenes/02_shadows.p3f --stage 2 --pass shadow --quiet -o "$out/02_shadows_no_offset_shadow_pass.png"
"$build/whitted" diff "$out/02_shadows_shadow_pass.png" "$out/02_shadows_no_offset_shadow_pass.png" > "$text/02_acne_diff.txt" || true
acne_pixel=$(sed -n 's/.*at pixel (\([0-9]*\), \([0-9]*\)).*/\1 \2/p' "$text/02_acne_diff.txt")
# shellcheck disable=SC2086 # two numbers
"$acne" trace scenes/02_shadows.p3f --stage 2 --pixel $acne_pixel > "$text/02_acne_trace.txt"
test_size=(--stage 5 --width 160 --height 120)
"$bent" render scenes/05_refraction.p3f "${test_size[@]}" --quiet -o "$text/05_mine.png"
"$build/whitted" diff tests/labs/05_refraction/05_refraction.png "$text/05_mine.png" -o "$out/05_refraction_eta_upside_down_heat.png" > "$text/05_diff.txt" || true
bent_pixel=$(sed -n 's/.*at pixel (\([0-9]*\), \([0-9]*\)).*/\1 \2/p' "$text/05_diff.txt")
# shellcheck disable=SC2086
"$bent" trace scenes/05_refraction.p3f "${test_size[@]}" --pixel $bent_pixel > "$text/05_worst_trace.txt"
"$bent" trace scenes/05_refraction.p3f "${test_size[@]}" --pixel 55 70 --picture "$out/05_refraction_eta_upside_down_trace.png" > "$text/05_bent_trace.txt"
"$build/whitted" trace scenes/05_refraction.p3f "${test_size[@]}" --pixel 55 70 --picture "$out/05_refraction_trace.png" > "$text/05_reference_trace.txt"
# Passes that show a catalogued mistake: lab, mistake, scene, stage, pass; with
# the reference's pass of that scene beside it.
pass_gallery=(
    "04_reflection weight_one        04_reflection 4 reflectance"
    "06_fresnel    weights_swapped   06_fresnel    6 reflectance"
    "06_fresnel    sum_not_halved    06_fresnel    6 fresnel"
    "06_fresnel    snell_upside_down 06_fresnel    6 fresnel"
)
for entry in "${pass_gallery[@]}"; do
    read -r lab name scene stage pass <<< "$entry"
    "$build/mistakes/whitted-mistake-$lab-$name" render "scenes/$scene.p3f" --stage "$stage" --pass "$pass" "${size[@]}" --quiet -o "$out/${lab}_${name}_${pass}_pass.png"
    "$build/whitted" render "scenes/$scene.p3f" --stage "$stage" --pass "$pass" "${size[@]}" --quiet -o "$out/${scene}_${pass}_pass.png"
done
for pass in normal depth albedo shadow reflectance fresnel ray-depth object-id cost; do
    "$build/whitted" render scenes/whitted_1980.p3f --pass "$pass" --width 256 --height 192 --quiet -o "$out/pass_$pass.png"
done
echo "render-gallery: $(ls "$out"/*.png | wc -l) pictures in $out; the tools' text in $text"
