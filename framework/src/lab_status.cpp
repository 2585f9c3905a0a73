#include "whitted/lab_status.hpp"

#include "lab_call.hpp"

#include "whitted/labs.hpp"

#include <functional>
#include <map>
#include <stdexcept>

namespace whitted {
namespace {

// A scene with one material, one light and no shapes, so probing never needs
// another lab's intersection code.
SceneData probe_scene() {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 0.0, 5.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 45.0, 4, 4);
    data.materials = {Material{}};
    data.lights = {PointLight{Point3(0.0, 5.0, 0.0), Color(1.0)}};
    return data;
}

// The lab number a stub message names ("labs/04_reflection.cpp:..." -> 4), or 0.
int lab_named_in(const std::string& message) {
    for (const LabInfo& row : kLabs)
        if (message.find("labs/" + std::string(row.stem) + ".cpp") != std::string::npos) return row.number;
    return 0;
}

} // namespace

std::map<std::string_view, std::function<void()>> lab_probes(const Scene& scene, const Tracer& tracer) {
    const Ray ray{Point3(0.0, 0.0, 5.0), Vec3(0.0, 0.0, -1.0)};
    const Hit hit = make_hit(ray, 5.0, Vec3(0.0, 0.0, 1.0));
    const Vec3 wo(0.0, 0.0, 1.0), n(0.0, 0.0, 1.0);
    if (scene.point_lights().empty()) throw std::invalid_argument("lab_probes: the scene needs a light");
    const PointLight& light = scene.point_lights()[0];
    const AreaLight area_light{light.position, light.color, Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0), 1, 0};
    return {
        {"primary_ray", [&scene] { primary_ray(scene.camera(), 0.5, 0.5); }},
        {"intersect_sphere", [=] { intersect_sphere(ray, Sphere{Point3(0.0), 1.0}, Interval{}); }},
        {"intersect_plane", [=] { intersect_plane(ray, Plane{Point3(0.0), n}, Interval{}); }},
        {"intersect_triangle", [=] { intersect_triangle(ray, Triangle{Point3(-1, -1, 0), Point3(1, -1, 0), Point3(0, 1, 0)}, Interval{}); }},
        {"closest_hit", [=, &scene] { closest_hit(ray, scene.primitives(), Interval{}); }},
        {"spawn_ray", [=] { spawn_ray(hit, wo); }},
        {"is_lit", [=, &tracer, &light] { is_lit(tracer, hit, light); }},
        {"lambert", [=, &tracer] { lambert(tracer, hit); }},
        {"blinn_phong", [=, &tracer] { blinn_phong(tracer, hit, wo); }},
        {"mirror_direction", [=] { mirror_direction(wo, n); }},
        {"reflection", [=, &tracer] { reflection(tracer, hit, wo, 1); }},
        {"refracted_direction", [=] { refracted_direction(wo, n, 1.0, 1.5); }},
        {"refraction", [=, &tracer] { refraction(tracer, hit, wo, 1); }},
        {"fresnel_reflectance", [] { fresnel_reflectance(1.0, 1.0, 1.5); }},
        {"fresnel_blend", [=, &tracer] { fresnel_blend(tracer, hit, wo, 1); }},
        {"stratified_sample", [] { stratified_sample(0, 1, Vec2(0.5)); }},
        {"pixel_color", [&tracer] { pixel_color(tracer, 0, 0); }},
        {"point_on_light", [=] { point_on_light(area_light, Vec2(0.5)); }},
        {"light_samples", [=, &tracer] { light_samples(tracer, area_light); }},
        {"concentric_disk", [] { concentric_disk(Vec2(0.5)); }},
        {"box_entry", [=] { box_entry(ray, Vec3(1.0), Aabb{Point3(-1.0), Point3(1.0)}, Interval{}); }},
        {"build_bvh", [] { build_bvh({}); }},
        {"bvh_closest_hit", [=, &scene] { bvh_closest_hit(scene, ray, Interval{}); }},
        {"bvh_occluded", [=, &scene] { bvh_occluded(scene, ray, Interval{}); }},
        {"thin_lens_ray", [&scene] { thin_lens_ray(scene.camera(), 0.5, 0.5, Vec2(0.5)); }},
    };
}

std::vector<LabStatus> probe_labs() {
    std::vector<LabStatus> labs;
    for (const LabInfo& row : kLabs) labs.push_back(LabStatus{row.number, std::string(row.stem), std::string(row.title), true, {}});
    const Scene scene(probe_scene());
    const RenderSettings settings;
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    const auto probes = lab_probes(scene, tracer);
    for (const LabInfo& row : kLabs)
        for (const std::string_view function : lab_functions(row)) {
            const auto probe = probes.find(function);
            if (probe == probes.end()) throw std::logic_error("lab_status.cpp has no probe for " + std::string(function));
            try {
                const detail::LabCall running(probe->first.data()); // the map's keys are string literals
                probe->second();
            } catch (const NotImplemented& missing) {
                // Blame the lab the message names: lab 4 may stop in lab 2's spawn_ray.
                const int lab = lab_named_in(missing.what());
                LabStatus& status = labs[static_cast<std::size_t>((lab ? lab : row.number) - 1)];
                if (status.done) status.message = missing.what();
                status.done = false;
            } catch (...) {
                // Other errors are the lab's own business; the render will report them.
            }
        }
    return labs;
}
int highest_complete_stage(const std::vector<LabStatus>& labs) {
    int stage = 0;
    while (stage < static_cast<int>(labs.size()) && labs[stage].done) ++stage;
    return stage;
}

} // namespace whitted
