// Lab 1 answered by the other side of the grading link (lab_link.hpp): its
// functions, and the scene's two queries, which are made of its code.
#include "lab_link.hpp"
#include "whitted/engine/remote_queries.hpp"

#include "whitted/labs.hpp"

namespace whitted {

using link::Link;
using link::Op;

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

} // namespace

const RemoteSceneQueries* remote_scene_queries() {
    // A checker whose lab 1 the worker answers asks the worker only for the scene's queries.
    static constexpr RemoteSceneQueries checker{remote_closest_hit, remote_occluded, nullptr, nullptr};
    static constexpr RemoteSceneQueries worker{remote_closest_hit, remote_occluded, remote_lab_bvh, remote_intersect_shape};
    return Link::current().role() == link::Role::worker ? &worker : &checker;
}

} // namespace whitted
