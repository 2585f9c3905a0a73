// Lab 10 written to crash, for the tests of the crash report (whitted/crash_report.hpp):
// WHITTED_TEST_CRASH says how bvh_closest_hit() crashes once a render asks it about a
// scene with shapes (the lab probes' scene has none, so `whitted` starts normally):
//   segfault  writes through a null pointer
//   divide    divides an integer by zero
//   abort     calls std::abort()
//   overflow  recurses without end, on a thread of the render other than the first
// Otherwise (and on the first thread for overflow) it tests every bounded primitive.
// The tree is one leaf; box_entry() is never called.
#include "whitted/labs.hpp"

#include <cstdlib>
#include <numeric>
#include <string>
#include <thread>

namespace whitted {
namespace {

const std::thread::id kFirstThread = std::this_thread::get_id(); // main()'s: the render's thread 0
volatile int g_zero = 0, g_one = 1; // unknown to the compiler: 1 / x would become a comparison

int recurse(int depth) {
    volatile char frame[512] = {};
    frame[depth % 512] = 1;
    if (g_zero < 0) return depth; // never: the compiler may not prove the recursion endless
    return recurse(depth + 1) + frame[0];
}

void crash_as_asked() {
    const char* mode_env = std::getenv("WHITTED_TEST_CRASH");
    const std::string mode = mode_env ? mode_env : "";
    if (mode == "segfault") {
        volatile int* nowhere = nullptr;
        *nowhere = 1;
    } else if (mode == "divide") {
        volatile int quotient = g_one / g_zero;
        (void)quotient;
    } else if (mode == "abort") {
        std::abort();
    } else if (mode == "overflow" && std::this_thread::get_id() != kFirstThread) {
        recurse(0);
    }
}

} // namespace

std::optional<double> box_entry(const Ray&, const Vec3&, const Aabb&, Interval) { return std::nullopt; }

BvhTree build_bvh(std::span<const Aabb> boxes) {
    BvhTree tree;
    if (boxes.empty()) return tree;
    Aabb bounds;
    for (const Aabb& box : boxes) bounds.expand(box);
    tree.nodes.push_back(BvhNode{bounds, 0, static_cast<std::uint32_t>(boxes.size())});
    tree.order.resize(boxes.size());
    std::iota(tree.order.begin(), tree.order.end(), 0u);
    return tree;
}

std::optional<Hit> bvh_closest_hit(const Scene& scene, const Ray& ray, Interval t_range) {
    if (!scene.bounded_primitives().empty()) crash_as_asked();
    return closest_hit(ray, scene.bounded_primitives(), t_range);
}

bool bvh_occluded(const Scene& scene, const Ray& ray, Interval t_range) {
    return closest_hit(ray, scene.bounded_primitives(), t_range).has_value();
}

} // namespace whitted
