// Serving a call: the arguments decoded in order, the lab function linked into
// this program run on them, [tracer state][result] encoded for the reply.
#include "lab_link.hpp"

#include "whitted/labs.hpp"
#include "whitted/primitive_test_count.hpp"

#include <stdexcept>
#include <string>

namespace whitted::link {
namespace {

void end_of(Reader& in) {
    if (!in.at_end()) throw LinkError("a call with more arguments than its function takes");
}

/// intersect_sphere(), intersect_plane() or intersect_triangle(): (ray, shape of kind S, range).
template <class S>
void serve_intersect(std::optional<Hit> (*intersect_shape)(const Ray&, const S&, Interval), Reader& in,
                     Writer& out) {
    const Ray ray = in.get<Ray>();
    const Shape shape = in.get<Shape>();
    const S* s = std::get_if<S>(&shape);
    if (!s) throw LinkError("a call with the wrong kind of shape");
    const Interval range = in.get<Interval>();
    end_of(in);
    PrimitiveTestCount::note_test(); // the other side's walk tests a primitive here (lab 10's tests count them)
    out.put(intersect_shape(ray, *s, range));
}

/// A sample count for stratified_sample(), which a grid of cells needs to be at least 1 (and not beyond what
/// the grid's arithmetic holds).
int checked_sample_count(int count) {
    constexpr int kMostSamples = 1 << 20;
    if (count < 1 || count > kMostSamples)
        throw std::invalid_argument("stratified_sample() was given count " + std::to_string(count) +
                                    ": a pixel or a light has from 1 to " + std::to_string(kMostSamples) + " samples");
    return count;
}

/// The tracer and the hit of a shading call, the hit checked against the tracer's scene.
struct Shading {
    const Tracer& tracer;
    Hit hit;
};
Shading get_shading(Link& link, Op op, Reader& in) {
    const Tracer& tracer = link.incoming_tracer(in, op);
    const Hit hit = in.get<Hit>();
    link.check_hit(hit, tracer.scene());
    return {tracer, hit};
}

} // namespace

void serve_op(Link& link, Op op, Reader& in, Writer& out) {
    switch (op) {
    case Op::primary_ray: {
        const Camera camera = in.get<Camera>();
        const double x = in.get<double>();
        const double y = in.get<double>();
        end_of(in);
        return out.put(primary_ray(camera, x, y));
    }
    case Op::intersect_sphere: return serve_intersect(intersect_sphere, in, out);
    case Op::intersect_plane: return serve_intersect(intersect_plane, in, out);
    case Op::intersect_triangle: return serve_intersect(intersect_triangle, in, out);
    case Op::closest_hit: {
        const Ray ray = in.get<Ray>();
        std::vector<Primitive> primitives(in.count(41));
        for (Primitive& primitive : primitives) primitive = in.get<Primitive>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(closest_hit(ray, primitives, range));
    }
    case Op::scene_closest_hit: {
        const Scene& scene = link.incoming_scene(in);
        const Ray ray = in.get<Ray>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(scene.closest_hit(ray, range));
    }
    case Op::scene_occluded: {
        const Scene& scene = link.incoming_scene(in);
        const Ray ray = in.get<Ray>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(scene.occluded(ray, range));
    }
    case Op::spawn_ray: {
        const Hit hit = in.get<Hit>();
        const Vec3 direction = in.get<Vec3>();
        end_of(in);
        return out.put(spawn_ray(hit, direction));
    }
    case Op::is_lit: {
        const Shading s = get_shading(link, op, in);
        const PointLight light = in.get<PointLight>();
        end_of(in);
        const bool lit = is_lit(s.tracer, s.hit, light);
        out.put(s.tracer.state());
        return out.put(lit);
    }
    case Op::lambert: {
        const Shading s = get_shading(link, op, in);
        end_of(in);
        const Color color = lambert(s.tracer, s.hit);
        out.put(s.tracer.state());
        return out.put(color);
    }
    case Op::blinn_phong: {
        const Shading s = get_shading(link, op, in);
        const Vec3 wo = in.get<Vec3>();
        end_of(in);
        const Color color = blinn_phong(s.tracer, s.hit, wo);
        out.put(s.tracer.state());
        return out.put(color);
    }
    case Op::mirror_direction: {
        const Vec3 wo = in.get<Vec3>();
        const Vec3 n = in.get<Vec3>();
        end_of(in);
        return out.put(mirror_direction(wo, n));
    }
    case Op::reflection:
    case Op::refraction:
    case Op::fresnel_blend: {
        const Shading s = get_shading(link, op, in);
        const Vec3 wo = in.get<Vec3>();
        const int depth = in.get<int>();
        end_of(in);
        const Color color = op == Op::reflection   ? reflection(s.tracer, s.hit, wo, depth)
                            : op == Op::refraction ? refraction(s.tracer, s.hit, wo, depth)
                                                   : fresnel_blend(s.tracer, s.hit, wo, depth);
        out.put(s.tracer.state());
        return out.put(color);
    }
    case Op::refracted_direction: {
        const Vec3 wo = in.get<Vec3>();
        const Vec3 n = in.get<Vec3>();
        const double eta_i = in.get<double>();
        const double eta_t = in.get<double>();
        end_of(in);
        return out.put(refracted_direction(wo, n, eta_i, eta_t));
    }
    case Op::fresnel_reflectance: {
        const double cos_theta_i = in.get<double>();
        const double eta_i = in.get<double>();
        const double eta_t = in.get<double>();
        end_of(in);
        return out.put(fresnel_reflectance(cos_theta_i, eta_i, eta_t));
    }
    case Op::stratified_sample: {
        const int index = in.get<int>();
        const int count = checked_sample_count(in.get<int>());
        const Vec2 u = in.get<Vec2>();
        end_of(in);
        return out.put(stratified_sample(index, count, u));
    }
    case Op::stratified_cell: { // the checker's lab 7, for a worker's stratified_sample() (StratifiedCell)
        const int index = in.get<int>();
        const int count = checked_sample_count(in.get<int>());
        end_of(in);
        const std::optional<StratifiedCell> cell = stratified_cell_of(index, count);
        out.put(cell.has_value());
        if (cell) out.put(cell->cell), out.put(cell->grid);
        return;
    }
    case Op::pixel_color: {
        const Tracer& tracer = link.incoming_tracer(in, op);
        const int x = in.get<int>();
        const int y = in.get<int>();
        end_of(in);
        const Color color = pixel_color(tracer, x, y);
        out.put(tracer.state());
        return out.put(color);
    }
    case Op::point_on_light: {
        const AreaLight light = in.get<AreaLight>();
        const Vec2 uv = in.get<Vec2>();
        end_of(in);
        return out.put(point_on_light(light, uv));
    }
    case Op::tracer_trace: { // the checker runs the recursion on the tracer it lent
        const Tracer& tracer = link.incoming_tracer(in, op);
        const Ray ray = in.get<Ray>();
        const int depth = in.get<int>();
        const auto kind = in.raw<std::uint8_t>();
        const Color weight = in.get<Vec3>();
        end_of(in);
        if (kind > static_cast<std::uint8_t>(RayKind::refracted)) throw LinkError("a ray of an unknown kind");
        if (depth < 1) throw std::invalid_argument("trace() was given depth " + std::to_string(depth) + ": an eye ray is at depth 1, each bounce one deeper");
        const Color color = tracer.trace(ray, depth, static_cast<RayKind>(kind), weight);
        out.put(tracer.state());
        return out.put(color);
    }
    case Op::tracer_trace_sample: {
        const Tracer& tracer = link.incoming_tracer(in, op);
        PixelSample sample;
        sample.x = in.get<int>();
        sample.y = in.get<int>();
        sample.index = in.get<int>();
        const double x = in.get<double>();
        const double y = in.get<double>();
        end_of(in);
        const Color color = tracer.trace_sample(sample, x, y);
        out.put(tracer.state());
        return out.put(color);
    }
    case Op::tracer_trace_pixels: {
        const Tracer& tracer = link.incoming_tracer(in, op);
        std::vector<Vec2> positions(in.count(16));
        for (Vec2& position : positions) position = in.get<Vec2>();
        end_of(in);
        std::vector<Color> colors(positions.size());
        tracer.trace_pixels(positions, colors);
        out.put(tracer.state());
        for (const Color& color : colors) out.put(color);
        return;
    }
    case Op::light_samples: {
        const Tracer& tracer = link.incoming_tracer(in, op);
        const AreaLight light = in.get<AreaLight>();
        end_of(in);
        const std::vector<PointLight> points = light_samples(tracer, light);
        out.put(tracer.state());
        return out.put_all(points);
    }
    case Op::box_entry: {
        const Ray ray = in.get<Ray>();
        const Vec3 inv_direction = in.get<Vec3>();
        const Aabb box = in.get<Aabb>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(box_entry(ray, inv_direction, box, range));
    }
    case Op::build_bvh: {
        const std::vector<Aabb> boxes = in.get<std::vector<Aabb>>();
        end_of(in);
        return out.put(build_bvh(boxes));
    }
    case Op::bvh_closest_hit: {
        const Scene& scene = link.incoming_scene(in);
        const Ray ray = in.get<Ray>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(bvh_closest_hit(scene, ray, range));
    }
    case Op::bvh_occluded: {
        const Scene& scene = link.incoming_scene(in);
        const Ray ray = in.get<Ray>();
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(bvh_occluded(scene, ray, range));
    }
    case Op::intersect_shape: { // counted by lab 10's tests as intersect() counts it
        PrimitiveTestCount::note_test();
        const Ray ray = in.get<Ray>();
        const Shape shape = in.get<Shape>();
        const Interval range = in.get<Interval>();
        end_of(in);
        if (std::holds_alternative<Box>(shape)) return out.put(intersect_box(ray, std::get<Box>(shape), range));
        if (std::holds_alternative<Cone>(shape)) return out.put(intersect_cone(ray, std::get<Cone>(shape), range));
        throw LinkError("a call of intersect() for a shape of a lab");
    }
    case Op::scene_lab_bvh: {
        const Scene& scene = link.incoming_scene(in);
        end_of(in);
        return out.put(scene.lab_bvh());
    }
    case Op::concentric_disk: {
        const Vec2 u = in.get<Vec2>();
        end_of(in);
        return out.put(concentric_disk(u));
    }
    case Op::thin_lens_rays: { // the rays of the queries in order, up to the first that throws (LensRaysAhead)
        const Camera camera = in.get<Camera>();
        std::vector<LensRaysAhead::Query> queries(in.count(32));
        for (LensRaysAhead::Query& q : queries) q.x = in.get<double>(), q.y = in.get<double>(), q.lens_u = in.get<Vec2>();
        end_of(in);
        std::vector<Ray> rays;
        rays.reserve(queries.size());
        try {
            for (const LensRaysAhead::Query& q : queries) rays.push_back(thin_lens_ray(camera, q.x, q.y, q.lens_u));
        } catch (const LinkError&) {
            throw;
        } catch (...) { // asked again alone, it throws to the checker as it should
        }
        return out.put_all(rays);
    }
    case Op::thin_lens_ray: {
        const Camera camera = in.get<Camera>();
        const double x = in.get<double>();
        const double y = in.get<double>();
        const Vec2 lens_u = in.get<Vec2>();
        end_of(in);
        return out.put(thin_lens_ray(camera, x, y, lens_u));
    }
    }
    throw LinkError("a call of an unknown function");
}

} // namespace whitted::link
