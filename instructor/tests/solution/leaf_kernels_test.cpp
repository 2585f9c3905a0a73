// The reference renderer's fast path (float eight-wide BVH, distance-only leaf
// kernels) must answer exactly as the labs' code testing every primitive does,
// and render the very same image, bit for bit.
#include "whitted/labs.hpp"
#include "whitted/engine/hit_distances.hpp"
#include "whitted/engine/leaf_kernels.hpp"
#include "whitted/engine/ray_packet.hpp"
#include "whitted/render.hpp"
#include "whitted/scene_loader.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <tuple>

using namespace whitted;


namespace {

// True when both images hold the very same bits.
bool same_pixels(const Image& a, const Image& b) {
    return a.pixels.size() == b.pixels.size() && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

// Which shapes a random scene holds: all four kinds interleaved (leaves of
// mixed kinds), or spheres only, or triangles only.
enum class Layout { mixed, spheres, triangles };

// Random spheres, triangles (some flat in an axis plane: boxes of zero
// thickness), boxes and a plane, all moved by `offset`, so that far-away
// coordinates stress the float boxes' rounding.
SceneData random_scene(unsigned seed, int count, Vec3 offset, double scale, Layout layout = Layout::mixed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(-10.0, 10.0), size(0.05, 1.5);
    SceneData data;
    data.materials.push_back(Material{});
    for (int i = 0; i < count; ++i) {
        const Point3 c = offset + scale * Point3(position(rng), position(rng), position(rng));
        const double a = scale * size(rng), b = scale * size(rng), h = scale * size(rng);
        const int kind = layout == Layout::mixed ? i % 4 : layout == Layout::spheres ? 0 : 1 + i % 2;
        switch (kind) {
        case 0: data.primitives.push_back({Sphere{c, a}}); break;
        case 1: data.primitives.push_back({Triangle{c, c + Vec3(a, 0.0, h), c + Vec3(0.0, b, h)}}); break;
        case 2: data.primitives.push_back({Triangle{c, c + Vec3(a, 0.0, 0.0), c + Vec3(0.0, b, 0.0)}}); break;
        default: data.primitives.push_back({Box{c, c + Vec3(a, b, h)}}); break;
        }
    }
    data.primitives.push_back({Plane{offset + Point3(0.0, -12.0 * scale, 0.0), Vec3(0.0, 1.0, 0.0)}});
    return data;
}

// Rays from anywhere around the cloud; one in three has a zero direction
// component and one in five runs exactly along an axis.
Ray random_ray(std::mt19937& rng, Vec3 offset, double scale) {
    std::uniform_real_distribution<double> position(-15.0, 15.0), unit(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 14);
    Vec3 d;
    do d = Vec3(unit(rng), unit(rng), unit(rng));
    while (glm::length(d) < 0.1);
    const int kind = pick(rng);
    if (kind % 3 == 0) d[kind % 2] = 0.0;
    if (kind % 5 == 0) d = Vec3(0.0), d[kind % 3] = kind > 7 ? 1.0 : -1.0;
    return Ray{offset + scale * Point3(position(rng), position(rng), position(rng)), glm::normalize(d)};
}

struct Setting {
    const char* name;
    Vec3 offset;
    double scale;
};

// Names a setting in test listings and messages (instead of its bytes).
void PrintTo(const Setting& setting, std::ostream* out) { *out << setting.name; }

const char* name(Layout layout) {
    return layout == Layout::mixed ? "mixed" : layout == Layout::spheres ? "spheres" : "triangles";
}

class FastPath : public ::testing::TestWithParam<std::tuple<Setting, Layout>> {};

} // namespace

TEST_P(FastPath, ClosestHitAndOcclusionAgreeWithTestingEveryPrimitive) {
    const auto [setting, layout] = GetParam();
    const Scene labs(random_scene(3, 2000, setting.offset, setting.scale, layout));
    const Scene fast(random_scene(3, 2000, setting.offset, setting.scale, layout), linked_leaf_kernels());
    ASSERT_NE(linked_leaf_kernels(), nullptr);
    std::mt19937 rng(5);
    int hits = 0, blocked = 0;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray = random_ray(rng, setting.offset, setting.scale);
        const auto expected = closest_hit(ray, labs.primitives(), Interval{});
        for (const Scene* scene : {&labs, &fast}) {
            const auto found = scene->closest_hit(ray);
            ASSERT_EQ(expected.has_value(), found.has_value()) << "ray " << i << (scene == &fast ? " (kernels)" : "");
            if (!expected) continue;
            EXPECT_EQ(expected->t, found->t) << "ray " << i;
            EXPECT_EQ(expected->primitive, found->primitive) << "ray " << i;
            EXPECT_EQ(expected->normal, found->normal) << "ray " << i;
        }
        hits += expected.has_value();
        const Interval shadow_range{0.0, 6.0 * setting.scale};
        const bool expected_blocked = closest_hit(ray, labs.primitives(), shadow_range).has_value();
        ASSERT_EQ(expected_blocked, labs.occluded(ray, shadow_range)) << "ray " << i;
        ASSERT_EQ(expected_blocked, fast.occluded(ray, shadow_range)) << "ray " << i << " (kernels)";
        blocked += expected_blocked;
    }
    EXPECT_GT(hits, 700);    // the comparison means something only if many rays hit
    EXPECT_GT(blocked, 150); // ... and many, but not all, feelers are blocked
    EXPECT_LT(blocked, 2850);
}

INSTANTIATE_TEST_SUITE_P(Scales, FastPath,
                         ::testing::Combine(::testing::Values(Setting{"unit", Vec3(0.0), 1.0},
                                                              Setting{"far_away", Vec3(3e6, -2e6, 1e6), 1.0},
                                                              Setting{"tiny", Vec3(1e-3), 1e-5},
                                                              Setting{"huge", Vec3(0.0), 1e9}),
                                            ::testing::Values(Layout::mixed, Layout::spheres, Layout::triangles)),
                         [](const auto& info) { return std::string(std::get<0>(info.param).name) + "_" + name(std::get<1>(info.param)); });

// A Distance says what the std::optional<double> it stands in for would say:
// none, or a distance, any but +infinity (0, -0, negative, huge, -infinity).
TEST(FastPath, ADistanceSaysWhatAnOptionalDoubleSays) {
    const Distance none = std::nullopt;
    EXPECT_FALSE(none);
    EXPECT_EQ(none.value_or(7.0), 7.0);
    EXPECT_FALSE(Distance{});
    for (const double t : {0.0, -0.0, -3.5, 2.25, 1e300, -std::numeric_limits<double>::infinity()}) {
        const Distance found = t;
        ASSERT_TRUE(found) << t;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(*found), std::bit_cast<std::uint64_t>(t));
        EXPECT_EQ(found.value_or(7.0), t);
    }
    // A unit sphere 5 ahead: met at t = 4 (its near side); a ray beside it misses.
    const Sphere sphere{Point3(0.0, 0.0, -5.0), 1.0};
    const Interval ahead{0.0, kInfinity};
    const Distance hit = sphere_distance(Ray{Point3(0.0), Vec3(0.0, 0.0, -1.0)}, sphere, ahead);
    ASSERT_TRUE(hit);
    EXPECT_EQ(*hit, 4.0);
    EXPECT_FALSE(sphere_distance(Ray{Point3(2.0, 0.0, 0.0), Vec3(0.0, 0.0, -1.0)}, sphere, ahead));
}

TEST(FastPath, EqualDistancesGoToTheFirstPrimitiveAsInTheLabs) {
    // Copies of one triangle and of one sphere, side by side in one leaf: every
    // copy is hit at the same t, and the labs' loop (a strictly nearer hit
    // replaces the one kept) answers with the first copy. So must the kernels.
    SceneData data;
    data.materials.push_back(Material{});
    const Triangle triangle{Point3(-1.0, -1.0, 0.0), Point3(1.0, -1.0, 0.0), Point3(0.0, 1.0, 0.0)};
    const Sphere sphere{Point3(0.0, 0.0, 5.0), 1.0};
    for (int i = 0; i < 3; ++i) data.primitives.push_back({sphere});
    for (int i = 0; i < 4; ++i) data.primitives.push_back({triangle});
    const Scene labs(data);
    const Scene fast(data, linked_leaf_kernels());
    for (const Ray& ray : {Ray{Point3(0.1, 0.0, -3.0), Vec3(0.0, 0.0, 1.0)}, Ray{Point3(0.1, 0.0, 9.0), Vec3(0.0, 0.0, -1.0)}}) {
        const auto expected = closest_hit(ray, labs.primitives(), Interval{});
        const auto found = fast.closest_hit(ray);
        ASSERT_TRUE(expected && found);
        EXPECT_EQ(expected->primitive, found->primitive);
        EXPECT_EQ(expected->t, found->t);
    }
}

TEST(FastPath, ExactEdgesCountAsInTheLabs) {
    // Two copies of a triangle (one leaf) with corners p0 = (-1,-1,0), p1 = (1,-1,0), p2 = (0,1,0). Aimed along +z at p1
    // from (1,-1,-3): e1 = (2,0,0), e2 = (1,2,0), p = d x e2 = (-2,1,0),
    // det = -4, s = (2,0,-3), b1 = -4 / -4 = 1 exactly, q = s x e1 = (0,-6,0),
    // b2 = 0, t = e2.q / det = 3: every number exact, and the corner is a hit
    // (the test rejects only b1 > 1). A shadow feeler whose range ends at
    // exactly t = 3 is not blocked (ranges are open).
    SceneData data;
    data.materials.push_back(Material{});
    const Triangle triangle{Point3(-1.0, -1.0, 0.0), Point3(1.0, -1.0, 0.0), Point3(0.0, 1.0, 0.0)};
    for (int i = 0; i < 2; ++i) data.primitives.push_back({triangle});
    const Ray ray{Point3(1.0, -1.0, -3.0), Vec3(0.0, 0.0, 1.0)};
    const Scene fast(data, linked_leaf_kernels());
    const auto found = fast.closest_hit(ray);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->t, 3.0);
    EXPECT_EQ(found->primitive, 0u);
    EXPECT_TRUE(fast.occluded(ray, Interval{0.0, 3.5}));
    EXPECT_FALSE(fast.occluded(ray, Interval{0.0, 3.0}));
    EXPECT_FALSE(fast.occluded(ray, Interval{3.0, 4.0}));
}

TEST(FastPath, RendersTheSameImageAsTheLabsForEveryShippedScene) {
    // Every shape kind appears in these: spheres (inward too), planes, triangles, boxes, cones.
    std::vector<std::filesystem::path> files;
    for (const char* folder : {WHITTED_SOURCE_DIR "/scenes", WHITTED_SOURCE_DIR "/instructor/tests/hidden/scenes"})
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == ".p3f" || entry.path().extension() == ".nff") files.push_back(entry.path());
    ASSERT_GE(files.size(), 8u);
    for (const auto& file : files) {
        LoadedScene loaded = load_scene(file.string());
        loaded.data.camera = loaded.data.camera.with_resolution(48, 36);
        const RenderSettings settings;
        const Scene labs(loaded.data);
        const Scene fast(loaded.data, linked_leaf_kernels());
        const Image a = render(labs, settings, 2).image;
        const Image b = render(fast, settings, 2).image;
        EXPECT_TRUE(same_pixels(a, b)) << file;
    }
}

TEST(FastPath, ImageIsBitIdenticalForAnyThreadCount) {
    LoadedScene loaded = load_scene(WHITTED_SOURCE_DIR "/scenes/whitted_1980.p3f");
    loaded.data.camera = loaded.data.camera.with_resolution(64, 48);
    const Scene scene(loaded.data, linked_leaf_kernels());
    const Image one = render(scene, RenderSettings{}, 1).image;
    for (int threads : {2, 3, 8}) {
        const Image many = render(scene, RenderSettings{}, threads).image;
        EXPECT_TRUE(same_pixels(one, many)) << threads;
    }
}

TEST(FastPath, RaysGrazingFarAwayBoxesFromNearTheOriginStillHitThem) {
    // Boxes a million units away, rays from near the origin aimed a hair
    // (1e-9 of the box size) inside a corner: the float boxes' rounding is far
    // larger than that hair, so only boxes widened beyond their rounding keep
    // these hits (the ray's own margin, 2^-20 |origin|, is tiny here).
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> position(-1.0, 1.0), size(0.5, 3.0);
    SceneData data;
    data.materials.push_back(Material{});
    std::vector<Box> boxes;
    for (int i = 0; i < 500; ++i) {
        const Point3 low = Point3(1e6, 2e6, -1.5e6) + 1e4 * Point3(position(rng), position(rng), position(rng));
        boxes.push_back(Box{low, low + Vec3(size(rng), size(rng), size(rng))});
        data.primitives.push_back({boxes.back()});
    }
    const Scene labs(data);
    const Scene fast(data, linked_leaf_kernels());
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        const Box& box = boxes[i % boxes.size()];
        const int corner = i / static_cast<int>(boxes.size()) * 3 + i;
        const Point3 c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                       (corner & 4) ? box.max.z : box.min.z);
        const Point3 target = c + 1e-9 * (0.5 * (box.min + box.max) - c);
        const Point3 origin = 1e-3 * Point3(position(rng), position(rng), position(rng));
        const Ray ray{origin, glm::normalize(target - origin)};
        const auto expected = closest_hit(ray, labs.primitives(), Interval{}); // every primitive, no BVH
        for (const Scene* scene : {&labs, &fast}) {
            const auto found = scene->closest_hit(ray);
            ASSERT_EQ(expected.has_value(), found.has_value()) << "ray " << i;
            if (expected) {
                EXPECT_EQ(expected->t, found->t) << "ray " << i;
            }
            ASSERT_EQ(expected.has_value(), scene->occluded(ray, Interval{0.0, 1e7})) << "ray " << i;
        }
        hits += expected.has_value();
    }
    EXPECT_GT(hits, 1900);
}

namespace {

// Sixteen rays as a packet would take them: from one point (a pinhole's eye
// rays through a 4 x 4 block of pixels), or from sixteen nearby points towards
// one (shadow feelers towards a light), `spread` wide; some bundles straddle an
// axis, so their direction signs differ and they go one by one.
std::vector<Ray> bundle(std::mt19937& rng, Vec3 offset, double scale, bool feelers, double spread) {
    std::uniform_real_distribution<double> position(-15.0, 15.0), unit(-1.0, 1.0);
    const Point3 from = offset + scale * Point3(position(rng), position(rng), position(rng));
    const Point3 to = offset + scale * Point3(0.3 * position(rng), 0.3 * position(rng), 0.3 * position(rng));
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i) {
        const Vec3 jitter = spread * scale * Vec3(unit(rng), unit(rng), unit(rng));
        const Point3 origin = feelers ? from + jitter : from;
        const Point3 target = feelers ? to : to + jitter;
        rays.push_back(Ray{origin, glm::normalize(target - origin)});
    }
    return rays;
}

} // namespace

TEST_P(FastPath, PacketsOfRaysGetTheAnswersOfRaysAlone) {
    const auto [setting, layout] = GetParam();
    const Scene fast(random_scene(3, 2000, setting.offset, setting.scale, layout), linked_leaf_kernels());
    ASSERT_TRUE(fast.queries_packets());
    std::mt19937 rng(11);
    int hits = 0, blocked = 0, misses = 0, together = 0;
    for (int b = 0; b < 300; ++b) {
        const bool feelers = b % 2 == 1;
        std::vector<Ray> rays = bundle(rng, setting.offset, setting.scale, feelers, b % 3 == 0 ? 0.05 : 1.5);
        // Directions of other lengths (a packet scales them by one power of two),
        // and some along a plane (a component of 0, which the box tests replace).
        const double length = b % 5 == 0 ? 0.125 : b % 5 == 1 ? 48.0 : 1.0;
        for (Ray& ray : rays) {
            if (b % 7 == 0) ray.direction.y = 0.0;
            ray.direction *= length;
        }
        const Interval eye_range{};
        std::vector<Interval> ranges(rays.size(), eye_range);
        for (std::size_t i = 0; i < rays.size(); ++i)
            if (feelers) ranges[i] = Interval{0.0, (3.0 + static_cast<double>(i % 5)) * setting.scale};
        together += RayPacket(rays, ranges, 1.0).coherent();
        std::vector<std::optional<Hit>> found(rays.size());
        fast.closest_hits(rays, ranges, found);
        bool packed[RayPacket::kMaxRays];
        fast.occluded_rays(rays, ranges, std::span<bool>(packed, rays.size()));
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const auto expected = fast.closest_hit(rays[i], ranges[i]);
            ASSERT_EQ(expected.has_value(), found[i].has_value()) << "bundle " << b << " ray " << i;
            if (expected) {
                EXPECT_EQ(expected->t, found[i]->t) << "bundle " << b << " ray " << i;
                EXPECT_EQ(expected->primitive, found[i]->primitive) << "bundle " << b << " ray " << i;
                EXPECT_EQ(expected->normal, found[i]->normal) << "bundle " << b << " ray " << i;
            }
            ASSERT_EQ(fast.occluded(rays[i], ranges[i]), packed[i]) << "bundle " << b << " ray " << i;
            hits += expected.has_value();
            misses += !expected.has_value();
            blocked += packed[i];
        }
    }
    EXPECT_GT(hits, 800); // the comparison means something only if many rays hit, and many miss
    EXPECT_GT(misses, 300);
    EXPECT_GT(blocked, 300);
    EXPECT_GT(together, 150); // most bundles walk as packets (the others go one by one)
}

TEST_P(FastPath, AFormerBlockerTestedFirstChangesNoAnswer) {
    // Scene::occluded(ray, range, blocker) tests the former blocker first. The
    // answer must be the one without it whatever it names: nothing, any
    // primitive, the plane, a primitive the ray meets just beyond the range (the
    // hint must be held to the range), or no primitive at all; and it must come
    // back as a primitive that does block the ray, or kNoBlocker. The same for
    // packets, which may not take a blocker from any but their own rays.
    const auto [setting, layout] = GetParam();
    const Scene labs(random_scene(3, 2000, setting.offset, setting.scale, layout));
    const Scene fast(random_scene(3, 2000, setting.offset, setting.scale, layout), linked_leaf_kernels());
    const auto primitive_count = static_cast<std::uint32_t>(fast.primitives().size());
    const auto blocks = [&](const Ray& ray, Interval range, std::uint32_t i) {
        return i < primitive_count && intersect(ray, fast.primitives()[i], range).has_value();
    };
    std::mt19937 rng(23);
    std::uniform_int_distribution<std::uint32_t> any(0, primitive_count + 2);
    int blocked = 0, beyond = 0, from_hint = 0;
    std::uint32_t previous = kNoBlocker;
    for (int i = 0; i < 3000; ++i) {
        const Ray ray = random_ray(rng, setting.offset, setting.scale);
        const std::optional<Hit> hit = fast.closest_hit(ray);
        const std::uint32_t nearest = hit ? hit->primitive : kNoBlocker; // a primitive's index is its position
        // Half the feelers stop just short of the nearest hit, and one in ten starts
        // just beyond it: that primitive is then no blocker.
        const Interval range = !hit          ? Interval{0.0, 6.0 * setting.scale}
                               : i % 2       ? Interval{0.0, hit->t * (1.0 - 1e-9)}
                               : i % 10 == 0 ? Interval{hit->t * (1.0 + 1e-9), 6.0 * setting.scale}
                                             : Interval{0.0, 6.0 * setting.scale};
        const bool expected = closest_hit(ray, labs.primitives(), range).has_value(); // the labs' answer
        ASSERT_EQ(fast.occluded(ray, range), expected) << "ray " << i;
        for (const std::uint32_t hint : {kNoBlocker, any(rng), primitive_count - 1, nearest, previous}) {
            std::uint32_t blocker = hint;
            ASSERT_EQ(fast.occluded(ray, range, blocker), expected) << "ray " << i << " hint " << hint;
            ASSERT_TRUE(expected ? blocks(ray, range, blocker) : blocker == kNoBlocker) << "ray " << i << " hint " << hint;
            from_hint += expected && blocker == hint;
            beyond += !expected && hint == nearest && hint != kNoBlocker;
        }
        std::uint32_t blocker = kNoBlocker;
        fast.occluded(ray, range, blocker);
        previous = blocker;
        blocked += expected;
    }
    EXPECT_GT(blocked, 150); // many, but not all, feelers are blocked
    EXPECT_LT(blocked, 2850);
    EXPECT_GT(from_hint, 250); // the hint itself was the answer
    EXPECT_GT(beyond, 300);    // the hint lay beyond the range

    for (int b = 0; b < 300; ++b) {
        const std::vector<Ray> rays = bundle(rng, setting.offset, setting.scale, true, b % 3 == 0 ? 0.05 : 1.5);
        std::vector<Interval> ranges(rays.size());
        for (std::size_t i = 0; i < rays.size(); ++i) ranges[i] = Interval{0.0, (3.0 + static_cast<double>(i % 5)) * setting.scale};
        bool packed[RayPacket::kMaxRays];
        std::uint32_t blocker = b % 2 ? previous : any(rng);
        fast.occluded_rays(rays, ranges, std::span<bool>(packed, rays.size()), blocker);
        bool any_blocked = false, blocker_blocks_one = false;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            ASSERT_EQ(fast.occluded(rays[i], ranges[i]), packed[i]) << "bundle " << b << " ray " << i;
            any_blocked |= packed[i];
            blocker_blocks_one |= packed[i] && blocks(rays[i], ranges[i], blocker);
        }
        ASSERT_TRUE(any_blocked ? blocker_blocks_one : blocker == kNoBlocker) << "bundle " << b;
        previous = blocker;
    }
}

TEST(FastPath, EqualDistancesInManyLeavesGoToTheLowestIndexAlsoInPackets) {
    // Forty copies of one triangle: their boxes are one box, so the BVH splits
    // them by count into several leaves, which a ray alone and a packet visit in
    // different orders. Every copy is hit at the same t; the answer must be the
    // first copy (the labs' loop over all of them keeps the first), whatever the order.
    SceneData data;
    data.materials.push_back(Material{});
    const Triangle triangle{Point3(-1.0, -1.0, 0.0), Point3(1.0, -1.0, 0.0), Point3(0.0, 1.0, 0.0)};
    for (int i = 0; i < 40; ++i) data.primitives.push_back({triangle});
    const Scene labs(data);
    const Scene fast(data, linked_leaf_kernels());
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i)
        rays.push_back(Ray{Point3(0.0, 0.0, -3.0), glm::normalize(Vec3(0.02 * (i % 4) - 0.03, 0.02 * (i / 4) - 0.03, 1.0))});
    const std::vector<Interval> ranges(rays.size(), Interval{});
    std::vector<std::optional<Hit>> packed(rays.size());
    fast.closest_hits(rays, ranges, packed);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto expected = closest_hit(rays[i], labs.primitives(), Interval{});
        ASSERT_TRUE(expected && packed[i]);
        EXPECT_EQ(expected->primitive, 0u);
        EXPECT_EQ(labs.closest_hit(rays[i])->primitive, 0u);
        EXPECT_EQ(fast.closest_hit(rays[i])->primitive, 0u);
        EXPECT_EQ(packed[i]->primitive, 0u) << i;
        EXPECT_EQ(packed[i]->t, expected->t);
    }
}

TEST(FastPath, TiesInLeavesMetOutOfIndexOrderGoToTheLowestIndex) {
    // n copies of one triangle in the plane z = 0, every third in place and the
    // others moved along x by 0.001 i: their boxes differ, so the walk meets
    // their leaves in an order that is not their indices', and the leaf kernels
    // test neighbours two at a time. A ray straight down meets every copy under
    // it at t = 3 exactly; the labs' loop over all of them keeps the lowest index.
    int compared = 0;
    for (int n = 2; n < 120; ++n) {
        SceneData data;
        data.materials.push_back(Material{});
        for (int i = 0; i < n; ++i) {
            const Vec3 shift(i % 3 == 0 ? 0.0 : 0.001 * i, 0.0, 0.0);
            data.primitives.push_back({Triangle{Point3(-1.0, -1.0, 0.0) + shift, Point3(1.0, -1.0, 0.0) + shift,
                                                Point3(0.0, 1.0, 0.0) + shift}});
        }
        const Scene fast(data, linked_leaf_kernels());
        std::vector<Ray> rays;
        for (int k = 0; k < 16; ++k) rays.push_back(Ray{Point3(-0.3 + 0.04 * k, -0.2 + 0.03 * k, 3.0), Vec3(0.0, 0.0, -1.0)});
        const std::vector<Interval> ranges(rays.size(), Interval{});
        std::vector<std::optional<Hit>> packed(rays.size());
        fast.closest_hits(rays, ranges, packed);
        for (std::size_t k = 0; k < rays.size(); ++k) {
            const auto expected = closest_hit(rays[k], fast.primitives(), Interval{});
            const auto alone = fast.closest_hit(rays[k]);
            ASSERT_TRUE(expected && alone && packed[k]) << n << " copies, ray " << k;
            EXPECT_EQ(alone->primitive, expected->primitive) << n << " copies, ray " << k;
            EXPECT_EQ(packed[k]->primitive, expected->primitive) << n << " copies, ray " << k;
            EXPECT_EQ(alone->t, 3.0);
            ++compared;
        }
    }
    EXPECT_EQ(compared, 118 * 16);
}

TEST(FastPath, APlaneWinsItsTieWithAPrimitiveLyingInIt) {
    // A triangle lying in the plane z = 0, hit straight down: both at t = 1
    // exactly. Every query that walks the BVH tests the infinite planes first
    // and keeps the plane (so a box standing on the floor plane shows the
    // floor where they touch), rays alone and packets alike. (Lab 1's loop over
    // every primitive, `accel none`, meets the planes last and keeps the triangle.)
    SceneData data;
    data.materials.push_back(Material{});
    data.primitives.push_back({Triangle{Point3(0.0, 0.0, 0.0), Point3(1.0, 0.0, 0.0), Point3(0.0, 1.0, 0.0)}});
    data.primitives.push_back({Triangle{Point3(5.0, 0.0, 0.0), Point3(6.0, 0.0, 0.0), Point3(5.0, 1.0, 0.0)}});
    data.primitives.push_back({Plane{Point3(0.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0)}});
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i) rays.push_back(Ray{Point3(0.1 + 0.01 * i, 0.25, 1.0), Vec3(0.0, 0.0, -1.0)});
    const std::vector<Interval> ranges(rays.size(), Interval{});
    std::vector<std::optional<Hit>> packed(rays.size());
    const Scene labs(data);
    const Scene fast(data, linked_leaf_kernels());
    fast.closest_hits(rays, ranges, packed);
    const std::uint32_t plane = 2;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        ASSERT_TRUE(packed[i]);
        EXPECT_EQ(packed[i]->t, 1.0);
        EXPECT_EQ(labs.closest_hit(rays[i])->primitive, plane) << i;
        EXPECT_EQ(fast.closest_hit(rays[i])->primitive, plane) << i;
        EXPECT_EQ(packed[i]->primitive, plane) << i;
    }
}

namespace {

// Adds `count` small spheres scattered around the origin: a BVH of many nodes,
// which packets walk (a scene of a few shapes is one leaf and never uses them).
void add_small_spheres(SceneData& data, unsigned seed, int count) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < count; ++i) data.primitives.push_back({Sphere{Point3(3.0 * unit(rng), 3.0 * unit(rng), 3.0 * unit(rng)), 0.1}});
}

// Whitted's settings (one ray through each pixel centre, the path that traces
// blocks) for `stage`, with a budget of `budget` rays a pixel.
RenderSettings block_settings(Stage stage, std::uint32_t budget) {
    RenderSettings settings;
    settings.samples_per_pixel = 0;
    settings.stage = stage_number(stage);
    settings.max_rays_per_pixel = budget;
    return settings;
}

// What render() draws when each pixel is traced alone (trace_pixel), as the labs describe.
RenderResult pixels_alone(const Scene& scene, const RenderSettings& settings, int threads) {
    return render_pixels(scene.camera(), threads, {}, [&](RayStats& stats) -> PixelFunction {
        return [tracer = Tracer(scene, settings, stats)](double x, double y) { return tracer.trace_pixel(x, y); };
    });
}

// A random scene for the look-ahead: 250 spheres, triangles and boxes (a BVH of
// many nodes, so packets are used) of opaque, mirror and glass materials above a
// floor plane, with `lights` point lights of which some lie exactly on the floor,
// some under it and some where the light before is, and `area` area lights.
SceneData many_lights_scene(unsigned seed, int lights, int area) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.0, 1.0);
    SceneData data;
    data.ambient = Color(0.1);
    for (int m = 0; m < 4; ++m) {
        Material material;
        material.color = Color(fraction(rng), fraction(rng), fraction(rng));
        material.specular = m == 0 ? 0.0 : 0.5 * fraction(rng);
        material.shininess = 1.0 + 50.0 * fraction(rng);
        material.transmittance = m == 3 ? 0.6 : 0.0;
        material.ior = 1.5;
        data.materials.push_back(material);
    }
    for (int i = 0; i < 250; ++i) {
        const Point3 c(3.0 * unit(rng), 3.0 * unit(rng), 3.0 * unit(rng));
        Primitive primitive{Sphere{c, 0.05 + 0.3 * fraction(rng)}};
        if (i % 3 == 1) primitive = Primitive{Triangle{c, c + Vec3(0.5, 0.0, 0.1), c + Vec3(0.0, 0.5, 0.2)}};
        if (i % 7 == 2) primitive = Primitive{Box{c, c + Vec3(0.3, 0.2, 0.4)}};
        primitive.material = static_cast<std::uint32_t>(i % 4);
        data.primitives.push_back(primitive);
    }
    data.primitives.push_back({Plane{Point3(0.0, -3.5, 0.0), Vec3(0.0, 1.0, 0.0)}});
    for (int l = 0; l < lights; ++l) {
        Point3 position(5.0 * unit(rng), 5.0 * unit(rng), 5.0 * unit(rng));
        if (l % 4 == 3) position.y = -3.5;                             // on the floor
        if (l % 5 == 4) position.y = -6.0;                             // under it
        if (l % 6 == 5) position = data.lights[l - 1].position;        // where the one before is
        data.lights.push_back(PointLight{position, Color(0.3 + fraction(rng), 0.3 + fraction(rng), 0.3 + fraction(rng))});
    }
    for (int a = 0; a < area; ++a)
        data.area_lights.push_back(AreaLight{Point3(2.0 * unit(rng), 4.0, 2.0 * unit(rng)), Color(1.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), 1 + 3 * a});
    data.camera.eye = Point3(0.3, 1.2, 9.0);
    data.camera.at = Point3(0.0);
    data.camera = data.camera.with_resolution(37, 29);
    return data;
}

} // namespace

TEST(FastPath, BlocksOfPixelsRenderWhatPixelsAloneRender) {
    // render() traces 4 x 4 pixel blocks with packets of eye rays and shadow
    // feelers; each pixel traced alone (trace_pixel) must give the same colour
    // bit for bit, and the same ray counts, on every shipped scene.
    for (const char* folder : {WHITTED_SOURCE_DIR "/scenes", WHITTED_SOURCE_DIR "/instructor/tests/hidden/scenes"}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (entry.path().extension() != ".p3f" && entry.path().extension() != ".nff") continue;
            LoadedScene loaded = load_scene(entry.path().string());
            loaded.data.camera = loaded.data.camera.with_resolution(37, 29); // blocks cut by the tiles' and image's edges
            const Scene scene(loaded.data, linked_leaf_kernels());
            RenderSettings settings;
            settings.samples_per_pixel = 0; // Whitted: one ray through each pixel centre, the path that uses blocks
            const RenderResult blocks = render(scene, settings, 2);
            const RenderResult alone = pixels_alone(scene, settings, 2);
            EXPECT_TRUE(same_pixels(blocks.image, alone.image)) << entry.path();
            EXPECT_EQ(blocks.stats.eye, alone.stats.eye) << entry.path();
            EXPECT_EQ(blocks.stats.shadow, alone.stats.shadow) << entry.path();
            EXPECT_EQ(blocks.stats.reflected, alone.stats.reflected) << entry.path();
            EXPECT_EQ(blocks.stats.refracted, alone.stats.refracted) << entry.path();
        }
    }
}

TEST(FastPath, BlocksOfPixelsOnARayBudgetRenderWhatPixelsAloneRender) {
    // The look-ahead computes each eye hit's local colour once, with its feelers
    // taken as unblocked, and the pixel's trace uses it only when none is blocked
    // and every feeler still fits in the pixel's ray budget (a feeler over budget
    // counts as blocked). Budgets of 1 to 4 rays cut pixels short before, among
    // and after the feelers of scenes with 2 and 3 lights, for Lambert (lab 2),
    // Blinn-Phong (lab 3) and every stage after. Small spheres give each scene a
    // BVH of many nodes, without which there are no packets and no look-ahead.
    for (const char* name : {"02_shadows.p3f", "03_blinn_phong.p3f", "10_bvh.p3f", "course_features.p3f"}) {
        LoadedScene loaded = load_scene(std::string(WHITTED_SOURCE_DIR "/scenes/") + name);
        add_small_spheres(loaded.data, 7, 200);
        loaded.data.camera = loaded.data.camera.with_resolution(37, 29);
        const Scene scene(loaded.data, linked_leaf_kernels());
        ASSERT_TRUE(scene.queries_packets()) << name;
        for (const Stage stage : {Stage::shadows, Stage::blinn_phong, Stage::bvh}) {
            for (std::uint32_t budget = 1; budget <= 4; ++budget) {
                const RenderSettings settings = block_settings(stage, budget);
                const RenderResult blocks = render(scene, settings, 2);
                const RenderResult alone = pixels_alone(scene, settings, 2);
                const std::string where = std::string(name) + " stage " + std::to_string(stage_number(stage)) + " budget " + std::to_string(budget);
                EXPECT_TRUE(same_pixels(blocks.image, alone.image)) << where;
                EXPECT_EQ(blocks.stats.shadow, alone.stats.shadow) << where;
                EXPECT_EQ(blocks.stats.pixels_cut_short, alone.stats.pixels_cut_short) << where;
                if (budget == 1) {
                    EXPECT_GT(alone.stats.pixels_cut_short, 0u) << where; // the budget bites
                }
            }
        }
    }
}

TEST(FastPath, BlocksOfPixelsRenderWhatPixelsAloneRenderWithManyLights) {
    // The look-ahead's feelers, grouped by light, and its local colours, used
    // only when no feeler is blocked and all fit in the budget: the same image
    // and the same counts as pixels alone with 0 to 7 point lights (on, under
    // and at the same place as others), area lights, each stage that shades,
    // and budgets that cut pixels short anywhere (0 rays to none).
    for (unsigned seed : {1u, 2u}) {
        for (const int lights : {0, 1, 3, 7}) {
            for (const int area : {0, 2}) {
                const Scene scene(many_lights_scene(seed * 100 + 3 * lights + area, lights, area), linked_leaf_kernels());
                ASSERT_TRUE(scene.queries_packets());
                for (const Stage stage : {Stage::shadows, Stage::blinn_phong, Stage::fresnel, Stage::soft_shadows, Stage::bvh}) {
                    for (const std::uint32_t budget : {0u, 1u, 2u, 5u, 10000u}) {
                        const RenderSettings settings = block_settings(stage, budget);
                        const RenderResult blocks = render(scene, settings, 2);
                        const RenderResult alone = pixels_alone(scene, settings, 1);
                        const std::string where = "seed " + std::to_string(seed) + ", " + std::to_string(lights) + " lights, " +
                                                  std::to_string(area) + " area lights, stage " + std::to_string(stage_number(stage)) +
                                                  ", budget " + std::to_string(budget);
                        ASSERT_TRUE(same_pixels(blocks.image, alone.image)) << where;
                        ASSERT_EQ(blocks.stats.shadow, alone.stats.shadow) << where;
                        ASSERT_EQ(blocks.stats.total(), alone.stats.total()) << where;
                        ASSERT_EQ(blocks.stats.pixels_cut_short, alone.stats.pixels_cut_short) << where;
                    }
                }
            }
        }
    }
}

TEST(FastPath, BlocksOfPixelsWithAreaLightsRenderWhatPixelsAloneRender) {
    // Soft shadows: each pixel sample sees its own points on the area light, so
    // the feelers the look-ahead notes must be the ones of the pixel's sample.
    // A few hundred small spheres give the scene a BVH of many nodes, which the
    // packets walk (a scene of a few shapes is one leaf and never uses them).
    LoadedScene loaded = load_scene(WHITTED_SOURCE_DIR "/scenes/08_soft_shadows.p3f");
    ASSERT_FALSE(loaded.data.area_lights.empty());
    add_small_spheres(loaded.data, 23, 300);
    loaded.data.camera = loaded.data.camera.with_resolution(41, 33);
    const Scene scene(loaded.data, linked_leaf_kernels());
    ASSERT_TRUE(scene.queries_packets());
    RenderSettings settings;
    settings.samples_per_pixel = 0;
    const RenderResult blocks = render(scene, settings, 2);
    const RenderResult alone = pixels_alone(scene, settings, 2);
    EXPECT_TRUE(same_pixels(blocks.image, alone.image));
    EXPECT_EQ(blocks.stats.shadow, alone.stats.shadow);
    EXPECT_GT(blocks.stats.shadow, 1000u);
}

TEST(FastPath, PixelsWhoseEyeRaysEscapeLeaveTheTracerAsPixelsAloneDo) {
    // trace_pixels() gives a pixel whose eye ray meets nothing its colour without
    // tracing the ray again (Tracer::Engine::escaped_eye_ray). Block by block,
    // each colour, the counts and what the tracer holds afterwards (state(),
    // pixel_sample()) must be what trace_pixel() leaves, pixel by pixel, in a
    // twin tracer: with the background colour (the classic scene's sky) and with
    // a skybox (course_features has one), and budgets of 0, 1 and 10,000 rays a pixel.
    const auto same_bits = [](const Color& a, const Color& b) { return std::memcmp(&a, &b, sizeof(Color)) == 0; };
    for (const char* name : {"whitted_1980.p3f", "course_features.p3f"}) {
        LoadedScene loaded = load_scene(std::string(WHITTED_SOURCE_DIR "/scenes/") + name);
        add_small_spheres(loaded.data, 7, 200);
        loaded.data.camera = loaded.data.camera.with_resolution(24, 16);
        const Scene scene(loaded.data, linked_leaf_kernels());
        ASSERT_TRUE(scene.queries_packets()) << name;
        for (const std::uint32_t budget : {0u, 1u, 10000u}) {
            const std::string where = std::string(name) + " budget " + std::to_string(budget);
            const RenderSettings settings = block_settings(Stage::bvh, budget);
            RayStats block_stats, alone_stats;
            const Tracer blocks(scene, settings, block_stats), alone(scene, settings, alone_stats);
            int escaped = 0, met = 0;
            for (int y0 = 0; y0 < 16; y0 += 4) {
                for (int x0 = 0; x0 < 24; x0 += 4) {
                    Vec2 positions[16];
                    Color colors[16];
                    for (int k = 0; k < 16; ++k) positions[k] = Vec2(x0 + k % 4 + 0.5, y0 + k / 4 + 0.5);
                    blocks.trace_pixels(positions, colors);
                    for (int k = 0; k < 16; ++k) {
                        EXPECT_TRUE(same_bits(colors[k], alone.trace_pixel(positions[k].x, positions[k].y))) << where << " pixel " << k;
                        const bool escapes = !scene.closest_hit(primary_ray(scene.camera(), positions[k].x, positions[k].y));
                        escaped += escapes;
                        met += !escapes;
                    }
                    const TracerState a = blocks.state(), b = alone.state();
                    EXPECT_EQ(a.stats.eye, b.stats.eye) << where;
                    EXPECT_EQ(a.stats.total(), b.stats.total()) << where;
                    EXPECT_EQ(a.stats.pixels_cut_short, b.stats.pixels_cut_short) << where;
                    EXPECT_TRUE(same_bits(a.path_weight, b.path_weight)) << where;
                    EXPECT_EQ(a.pixel_rays, b.pixel_rays) << where;
                    EXPECT_EQ(a.pixel_cut_short, b.pixel_cut_short) << where;
                    EXPECT_EQ(a.sample, b.sample) << where;
                    EXPECT_EQ(blocks.pixel_sample(), alone.pixel_sample()) << where;
                }
            }
            EXPECT_GT(escaped, 40) << where; // both kinds of pixel, in blocks that mix them
            EXPECT_GT(met, 40) << where;
            if (budget == 0) {
                EXPECT_EQ(block_stats.pixels_cut_short, 24u * 16u) << where;
            }
        }
    }
}
