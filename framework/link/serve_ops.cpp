// Serving a call: the arguments decoded in order, the lab function linked into
// this program run on them, [tracer state][result] encoded for the reply.
#include "lab_link.hpp"

#include "whitted/labs.hpp"

namespace whitted::link {
namespace {

template <class S>
S get_shape(Reader& in) {
    const Shape shape = in.get<Shape>();
    if (const S* s = std::get_if<S>(&shape)) return *s;
    throw LinkError("a call with the wrong kind of shape");
}

void end_of(Reader& in) {
    if (!in.at_end()) throw LinkError("a call with more arguments than its function takes");
}

void put_state(Writer& out, const Tracer& tracer) {
    const TracerState state = tracer.state();
    out.put(state.stats), out.put(state.path_weight), out.put(state.pixel_rays), out.put(state.pixel_cut_short);
}

/// The tracer and the hit of a shading call, the hit checked against the tracer's scene.
struct Shading {
    const Tracer& tracer;
    Hit hit;
};
Shading get_shading(Link& link, Reader& in) {
    const Tracer& tracer = link.incoming_tracer(in);
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
    case Op::intersect_sphere: {
        const Ray ray = in.get<Ray>();
        const Sphere sphere = get_shape<Sphere>(in);
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(intersect_sphere(ray, sphere, range));
    }
    case Op::intersect_plane: {
        const Ray ray = in.get<Ray>();
        const Plane plane = get_shape<Plane>(in);
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(intersect_plane(ray, plane, range));
    }
    case Op::intersect_triangle: {
        const Ray ray = in.get<Ray>();
        const Triangle triangle = get_shape<Triangle>(in);
        const Interval range = in.get<Interval>();
        end_of(in);
        return out.put(intersect_triangle(ray, triangle, range));
    }
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
        const Shading s = get_shading(link, in);
        const PointLight light = in.get<PointLight>();
        end_of(in);
        const bool lit = is_lit(s.tracer, s.hit, light);
        put_state(out, s.tracer);
        return out.put(lit);
    }
    case Op::lambert: {
        const Shading s = get_shading(link, in);
        end_of(in);
        const Color color = lambert(s.tracer, s.hit);
        put_state(out, s.tracer);
        return out.put(color);
    }
    case Op::blinn_phong: {
        const Shading s = get_shading(link, in);
        const Vec3 wo = in.get<Vec3>();
        end_of(in);
        const Color color = blinn_phong(s.tracer, s.hit, wo);
        put_state(out, s.tracer);
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
        const Shading s = get_shading(link, in);
        const Vec3 wo = in.get<Vec3>();
        const int depth = in.get<int>();
        end_of(in);
        const Color color = op == Op::reflection   ? reflection(s.tracer, s.hit, wo, depth)
                            : op == Op::refraction ? refraction(s.tracer, s.hit, wo, depth)
                                                   : fresnel_blend(s.tracer, s.hit, wo, depth);
        put_state(out, s.tracer);
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
    }
    throw LinkError("a call of an unknown function");
}

} // namespace whitted::link
