// The reference renderer's fast queries: the BVH walk with distance-only tests
// inlined into it (distances.hpp, the labs' exact arithmetic), one primitive at
// a time; and the choice between these and the AVX ones (leaf_kernels_avx.cpp).
//
// Why here and not in framework/: these are the answers to lab 1, and the
// student handout ships framework/ but not solution/.
#include "kernel_sets.hpp"
#include "queries.hpp"

namespace whitted {
namespace {

// Tests a leaf's primitives one by one.
struct PlainLeaf {
    explicit PlainLeaf(const Ray&) {}

    double nearest(const Ray& ray, const Primitive* primitives, std::uint32_t first, std::uint32_t count, double t_min,
                   double t_max, std::optional<std::uint32_t>& nearest_index) const {
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (const double t = distance(ray, primitives[i], Interval{t_min, t_max}); t != kMiss) {
                t_max = t;
                nearest_index = i;
            }
        }
        return t_max;
    }

    bool any(const Ray& ray, const Primitive* primitives, std::uint32_t first, std::uint32_t count, double t_min,
             double t_max) const {
        for (std::uint32_t i = first; i < first + count; ++i)
            if (distance(ray, primitives[i], Interval{t_min, t_max}) != kMiss) return true;
        return false;
    }
};

constexpr LeafKernels kPlainKernels{closest_query<PlainLeaf>, occluded_query<PlainLeaf>};

bool cpu_has_avx() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_cpu_init(); // needed when first asked during static initialisation (test registration)
    return __builtin_cpu_supports("avx");
#else
    return false;
#endif
}

} // namespace

const LeafKernels* plain_leaf_kernels() { return &kPlainKernels; }

std::vector<NamedLeafKernels> runnable_leaf_kernels() {
    std::vector<NamedLeafKernels> sets{{"plain", plain_leaf_kernels()}};
    if (avx_leaf_kernels() && cpu_has_avx()) sets.push_back({"avx", avx_leaf_kernels()});
    return sets;
}

const LeafKernels* linked_leaf_kernels() {
    static const LeafKernels* const best = runnable_leaf_kernels().back().kernels;
    return best;
}

} // namespace whitted
