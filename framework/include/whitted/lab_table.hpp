// The labs of the course, in order: one row each.
//
// Why one table: a lab shows up in many places (the build's list of lab files,
// `whitted render --stage`, which labs are done, the tracer's recursion, the
// grader, the handout's scripts). They all take the labs from the rows below,
// so adding a lab is a row here plus its own files (labs/, solution/, tests/,
// docs/labs/, its section of instructor/rubric.json). CMake reads the rows too
// (cmake/WhittedLabs.cmake), so keep each row on one line, in this form.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace whitted {

/// What the tracer does at each stage: stage k uses the features of labs 1..k.
enum class Stage : int { ray_casting = 1, shadows, blinn_phong, reflection, refraction, fresnel, anti_aliasing, soft_shadows, depth_of_field, bvh };

/// One lab: the file the student writes and what it adds to the renderer.
struct LabInfo {
    int number;                 // 1, 2, ...: the order students do them in; `ctest -L lab<number>`
    std::string_view stem;      // "03_blinn_phong": labs/<stem>.cpp, tests/labs/<stem>/, docs/labs/<stem>.md
    std::string_view title;     // "Blinn-Phong"
    Stage stage;                // the feature `whitted render --stage <number>` adds
    std::string_view functions; // the functions of labs.hpp it asks for, separated by spaces
};

// clang-format off
inline constexpr std::array kLabs = {
    LabInfo{1, "01_ray_casting", "ray casting", Stage::ray_casting, "primary_ray intersect_sphere intersect_plane intersect_triangle closest_hit"},
    LabInfo{2, "02_shadows", "shadows", Stage::shadows, "spawn_ray is_lit lambert"},
    LabInfo{3, "03_blinn_phong", "Blinn-Phong", Stage::blinn_phong, "blinn_phong"},
    LabInfo{4, "04_reflection", "reflection", Stage::reflection, "mirror_direction reflection"},
    LabInfo{5, "05_refraction", "refraction", Stage::refraction, "refracted_direction refraction"},
    LabInfo{6, "06_fresnel", "Fresnel", Stage::fresnel, "fresnel_reflectance fresnel_blend"},
    LabInfo{7, "07_anti_aliasing", "anti-aliasing", Stage::anti_aliasing, "stratified_sample pixel_color"},
    LabInfo{8, "08_soft_shadows", "soft shadows", Stage::soft_shadows, "point_on_light light_samples"},
    LabInfo{9, "09_depth_of_field", "depth of field", Stage::depth_of_field, "concentric_disk thin_lens_ray"},
    LabInfo{10, "10_bvh", "bounding volume hierarchy", Stage::bvh, "box_entry build_bvh bvh_closest_hit bvh_occluded"},
};
// clang-format on

/// How many labs there are; also the last stage.
inline constexpr int kLabCount = static_cast<int>(kLabs.size());

/// The stage number of `stage`, to compare with RenderSettings::stage.
constexpr int stage_number(Stage stage) { return static_cast<int>(stage); }

/// The lab numbered `number` (1..kLabCount).
constexpr const LabInfo& lab(int number) { return kLabs.at(static_cast<std::size_t>(number - 1)); }

/// "1 ray casting, 2 shadows, ...": the stages for help texts.
std::string stage_list();

/// The functions a lab asks for, from its row of the table.
std::vector<std::string_view> lab_functions(const LabInfo& lab);

namespace detail {
constexpr bool rows_in_order() {
    for (int i = 0; i < kLabCount; ++i) {
        const LabInfo& row = kLabs[static_cast<std::size_t>(i)];
        if (row.number != i + 1 || stage_number(row.stage) != row.number || row.stem.size() < 4) return false;
        // The stem starts with the two-digit number and an underscore: "07_anti_aliasing".
        if (row.stem[0] - '0' != row.number / 10 || row.stem[1] - '0' != row.number % 10 || row.stem[2] != '_') return false;
    }
    return true;
}
static_assert(rows_in_order(), "kLabs: lab k is row k, its stage is Stage k, its stem starts with k as two digits");
} // namespace detail

} // namespace whitted
