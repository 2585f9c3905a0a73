// Lab 8 — soft shadows: an area light as many point lights, spread over it on a jittered grid.
#include "whitted/labs.hpp"

namespace whitted {

Point3 point_on_light(const AreaLight& light, Vec2 uv) {
    // (0, 0) is the corner half an edge back along each edge from the centre.
    return light.center + (uv.x - 0.5) * light.edge_u + (uv.y - 0.5) * light.edge_v;
}

std::vector<PointLight> light_samples(const Tracer& tracer, const AreaLight& light) {
    const int count = light.samples;
    std::vector<PointLight> points;
    points.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) {
        const Vec2 u = sample_numbers(tracer.pixel_sample(), SampleUse::light, light.first_number + static_cast<std::uint32_t>(k));
        // Each point carries an equal share: together they give the light's whole colour.
        points.push_back(PointLight{point_on_light(light, stratified_sample(k, count, u)), light.color / static_cast<double>(count)});
    }
    return points;
}

} // namespace whitted
