// Lab 1 answered by the other side of the grading link (lab_link.hpp): its
// functions, and the scene's two queries, which are made of its code.
#include "lab_link.hpp"
#include "whitted/engine/remote_queries.hpp"

#include "whitted/labs.hpp"

namespace whitted {

using link::Link;
using link::Op;
using link::Reader;
using link::every_lab;

Ray primary_ray(const Camera& camera, double x, double y) {
    Link::Call call(Link::current(), Op::primary_ray);
    call.args().put(camera), call.args().put(x), call.args().put(y);
    return call.result<Ray>();
}

namespace {
std::optional<Hit> intersect_shape(Op op, const Ray& ray, const Shape& shape, Interval t_range) {
    Link::Call call(Link::current(), op);
    call.args().put(ray), call.args().put(shape), call.args().put(t_range);
    return call.result<std::optional<Hit>>();
}
} // namespace

std::optional<Hit> intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range) {
    return intersect_shape(Op::intersect_sphere, ray, sphere, t_range);
}
std::optional<Hit> intersect_plane(const Ray& ray, const Plane& plane, Interval t_range) {
    return intersect_shape(Op::intersect_plane, ray, plane, t_range);
}
std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle, Interval t_range) {
    return intersect_shape(Op::intersect_triangle, ray, triangle, t_range);
}

std::optional<Hit> closest_hit(const Ray& ray, std::span<const Primitive> primitives, Interval t_range) {
    Link::Call call(Link::current(), Op::closest_hit);
    call.args().put(ray), call.primitives(primitives), call.args().put(t_range);
    return call.result<std::optional<Hit>>();
}

namespace {

std::optional<Hit> remote_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    Link& link = Link::current();
    Link::Call call(link, Op::scene_closest_hit);
    call.scene(scene), call.args().put(ray), call.args().put(t_range);
    const std::optional<Hit> hit = call.result<std::optional<Hit>>();
    if (hit) link.check_hit(*hit, scene);
    return hit;
}

bool remote_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    Link::Call call(Link::current(), Op::scene_occluded);
    call.scene(scene), call.args().put(ray), call.args().put(t_range);
    return call.result<bool>();
}

/// The checker's tree for lab 10's walk: both sides walk one tree, the checker's.
BvhTree remote_lab_bvh(const Scene& scene) {
    Link::Call call(Link::current(), Op::scene_lab_bvh);
    call.scene(scene);
    return call.result<BvhTree>();
}

/// A box or cone tested by the checker: the framework's slab test stays out of the worker's hands.
std::optional<Hit> remote_intersect_shape(const Ray& ray, const Shape& shape, Interval t_range) {
    Link::Call call(Link::current(), Op::intersect_shape);
    call.args().put(ray), call.args().put(shape), call.args().put(t_range);
    return call.result<std::optional<Hit>>();
}

/// A block of pixels traced by a worker that holds every lab (the integration tests).
void remote_trace_pixels(const Tracer& tracer, std::span<const Vec2> positions, std::span<Color> colors) {
    Link::Call call(Link::current(), Op::tracer_trace_pixels);
    call.tracer(tracer);
    call.args().put(static_cast<std::uint64_t>(positions.size()));
    for (const Vec2& position : positions) call.args().put(position);
    Reader& in = call.send();
    for (Color& color : colors) color = in.get<Vec3>();
    call.done();
}

} // namespace

const RemoteSceneQueries* remote_scene_queries() {
    // A checker whose lab 1 the worker answers asks the worker only for the scene's queries; one whose worker
    // holds every lab asks it for whole blocks of pixels too.
    static constexpr RemoteSceneQueries checker{remote_closest_hit, remote_occluded, nullptr, nullptr, nullptr};
    static constexpr RemoteSceneQueries every_lab_over_there{remote_closest_hit, remote_occluded, nullptr, nullptr,
                                                             remote_trace_pixels};
    static constexpr RemoteSceneQueries worker{remote_closest_hit, remote_occluded, remote_lab_bvh,
                                               remote_intersect_shape, nullptr};
    const Link& link = Link::current();
    if (link.role() == link::Role::worker) return &worker;
    return link.remote_labs() == every_lab() ? &every_lab_over_there : &checker;
}

} // namespace whitted
