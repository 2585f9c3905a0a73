// `whitted trace`'s checks beside each ray: they agree with the reference
// everywhere, and they catch a ray bent the wrong way or a feeler that meets
// its own surface.
#include "lab_helpers.hpp"
#include "trace/ray_tree_report.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

// Glass ball (ior 1.5) and a mirror ball over a floor, one light.
SceneData glass_and_mirror() {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 1.5, 6.0), Point3(0.0, 1.0, 0.0), Vec3(0.0, 1.0, 0.0), 45.0, 32, 32);
    data.lights = {PointLight{Point3(5.0, 8.0, 5.0), Color(1.0)}};
    data.materials = {diffuse_material(Color(0.8)), glass_material(1.5, 0.9), mirror_material(0.7)};
    data.primitives.push_back({Plane{Point3(0.0), Vec3(0.0, 1.0, 0.0)}, 0});
    data.primitives.push_back({Sphere{Point3(0.8, 1.0, 0.0), 0.9}, 1});
    data.primitives.push_back({Sphere{Point3(-1.2, 1.0, -1.0), 0.9}, 2});
    return data;
}

struct Traced {
    Scene scene{glass_and_mirror()};
    RenderSettings settings;
    RayStats stats;
    RayTree tree;
    TraceContext context{scene, settings, "scene.p3f", 0, 0, 32, 32};

    void trace(const Ray& ray, int stage = 5) {
        settings.stage = stage;
        tree.clear();
        Tracer(scene, settings, stats, &tree).trace(ray, 1, RayKind::eye, Color(1.0));
    }
    int first(RayKind kind) const {
        for (std::size_t i = 0; i < tree.nodes.size(); ++i)
            if (tree.nodes[i].kind == kind) return static_cast<int>(i);
        return -1;
    }
};

} // namespace

TEST(TraceChecks, AgreeWithTheReferenceOnEveryRayOfEveryPixel) {
    Traced t;
    t.settings.stage = 6;
    int checked = 0;
    const Tracer tracer(t.scene, t.settings, t.stats, &t.tree);
    for (int y = 0; y < 32; ++y) {
        for (int x = 0; x < 32; ++x) {
            tracer.trace_pixel(x + 0.5, y + 0.5);
            for (std::size_t i = 0; i < t.tree.nodes.size(); ++i) {
                if (t.tree.nodes[i].fate != RayFate::traced) continue;
                if (const auto check = check_direction(t.tree, static_cast<int>(i), t.context)) {
                    ASSERT_TRUE(check->agrees) << check->law << " at pixel " << x << " " << y << ": off by "
                                               << check->off_degrees << " deg";
                    ++checked;
                }
                EXPECT_FALSE(blocked_by_own_surface(t.tree, static_cast<int>(i), t.context));
            }
        }
    }
    EXPECT_GT(checked, 200);
}

TEST(TraceChecks, SnellsLawCatchesARayBentTheWrongWay) {
    // Into the glass ball at 30 degrees from the normal: Snell's law gives
    // sin(theta_t) = sin(30) / 1.5, theta_t = 19.47 degrees. With eta upside
    // down, sin(theta_t) = 1.5 sin(30) = 0.75, 48.59 degrees: 29.1 degrees off.
    Traced t;
    const Point3 top(0.8, 1.9, 0.0); // the ball's top: the normal is +y
    const Vec3 in(std::sin(radians(30.0)), -std::cos(radians(30.0)), 0.0);
    t.trace(Ray{top - 3.0 * in, in});
    const int refracted = t.first(RayKind::refracted);
    ASSERT_GE(refracted, 0);
    std::optional<DirectionCheck> check = check_direction(t.tree, refracted, t.context);
    ASSERT_TRUE(check && check->agrees);
    EXPECT_NEAR(check->theta_i, 30.0, 1e-6);
    EXPECT_NEAR(check->theta_out, 19.4712206, 1e-6);

    const double theta_wrong = std::asin(0.75);
    t.tree.nodes[refracted].ray.direction = Vec3(std::sin(theta_wrong), -std::cos(theta_wrong), 0.0);
    check = check_direction(t.tree, refracted, t.context);
    ASSERT_TRUE(check.has_value());
    EXPECT_FALSE(check->agrees);
    EXPECT_NEAR(check->off_degrees, 48.5903779 - 19.4712206, 1e-5);
    const std::string text = ray_tree_text(t.tree, t.context);
    EXPECT_NE(text.find("<- DIFFERS"), std::string::npos) << text;
}

TEST(TraceChecks, SnellsLawSaysWhenNoRefractedRayShouldExist) {
    // Leaving glass at 60 degrees: sin(theta_t) = 1.5 sin(60) = 1.3 > 1, total
    // internal reflection. A refracted ray there is a bug; none is correct.
    Traced t;
    t.settings.stage = 5;
    RayTree& tree = t.tree;
    RayNode eye;
    eye.ray = Ray{Point3(0.8, 1.0, 0.0), Vec3(std::sin(radians(60.0)), std::cos(radians(60.0)), 0.0)};
    Hit hit = make_hit(eye.ray, 1.0, Vec3(0.0, 1.0, 0.0)); // leaving through a surface with outward normal +y
    hit.material = 1;
    hit.primitive = 1;
    eye.hit = hit;
    eye.local = Color(0.0);
    RayNode wrong;
    wrong.kind = RayKind::refracted;
    wrong.depth = 2;
    wrong.parent = 0;
    wrong.ray = Ray{hit.point, Vec3(0.0, 1.0, 0.0)};
    eye.children = {1};
    tree.nodes = {eye, wrong};
    const std::optional<DirectionCheck> check = check_direction(tree, 1, t.context);
    ASSERT_TRUE(check.has_value());
    EXPECT_FALSE(check->expected.has_value());
    EXPECT_FALSE(check->agrees);
    EXPECT_NE(ray_tree_text(tree, t.context).find("so total internal reflection: no refracted ray should exist"),
              std::string::npos);
    tree.nodes.pop_back();
    tree.nodes[0].children.clear();
    EXPECT_NE(ray_tree_text(tree, t.context).find("gives total internal reflection here: ok"), std::string::npos);
}

TEST(TraceChecks, AFeelerStoppedByItsOwnSurfaceIsCalledShadowAcne) {
    // A feeler from the glass ball's top that "hits" the same ball at t = 1e-17,
    // as a feeler starting exactly on the surface does; then one stopped by the
    // other ball, which is a real shadow.
    Traced t;
    t.trace(Ray{Point3(0.8, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 2);
    const int feeler = t.first(RayKind::shadow);
    ASSERT_GE(feeler, 0);
    RayNode& node = t.tree.nodes[feeler];
    node.blocked = true;
    node.hit = t.tree.nodes[0].hit;
    node.hit->t = 1e-17;
    EXPECT_TRUE(blocked_by_own_surface(t.tree, feeler, t.context));
    EXPECT_NE(ray_tree_text(t.tree, t.context).find("self-intersection (shadow acne, lab 2)"), std::string::npos);
    node.hit->primitive = t.tree.nodes[0].hit->primitive == 2 ? 1 : 2;
    EXPECT_FALSE(blocked_by_own_surface(t.tree, feeler, t.context));
}

TEST(TraceChecks, FromInsideOrTowardsALightBehindOnlyATinyTIsShadowAcne) {
    // Inside the glass ball (a feeler from its far wall, hit from inside) the
    // ball itself may stand between the point and the light: blocked at t = 1.7
    // is a real shadow, at t = 1e-17 the rounding error. The same holds for a
    // feeler from outside towards a light behind the surface (code that casts
    // feelers before checking n . L): the ball's far side blocks it at t = 1.8.
    Traced t;
    t.trace(Ray{Point3(0.8, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 2);
    const int feeler = t.first(RayKind::shadow);
    ASSERT_GE(feeler, 0);
    RayNode& node = t.tree.nodes[feeler];
    RayNode& eye = t.tree.nodes[0];
    node.blocked = true;
    node.hit = eye.hit;
    // From inside: the eye ray's hit seen from within the ball.
    eye.hit->front_face = false;
    eye.hit->normal = -eye.hit->normal;
    eye.hit->geometric_normal = -eye.hit->geometric_normal;
    node.ray.direction = eye.hit->geometric_normal;
    node.hit->t = 1.7;
    EXPECT_FALSE(blocked_by_own_surface(t.tree, feeler, t.context));
    node.hit->t = 1e-17;
    EXPECT_TRUE(blocked_by_own_surface(t.tree, feeler, t.context));
    // From outside, towards a light behind the surface.
    eye.hit->front_face = true;
    eye.hit->normal = -eye.hit->normal;
    eye.hit->geometric_normal = -eye.hit->geometric_normal;
    node.ray.direction = -eye.hit->geometric_normal;
    node.hit->t = 1.8;
    EXPECT_FALSE(blocked_by_own_surface(t.tree, feeler, t.context));
}

TEST(TraceChecks, ANormalThatDoesNotFaceTheRayIsCalledOut) {
    // The reference's normals face the ray everywhere; an intersection that
    // forgets to turn the normal for a ray from inside does not.
    Traced t;
    t.trace(Ray{Point3(0.8, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)}, 5);
    EXPECT_EQ(ray_tree_text(t.tree, t.context).find("the normal should face"), std::string::npos);
    t.tree.nodes[0].hit->normal = -t.tree.nodes[0].hit->normal;
    EXPECT_NE(ray_tree_text(t.tree, t.context).find("<- DIFFERS: the normal should face the incoming ray"), std::string::npos);
    t.tree.nodes[0].hit->normal = -2.0 * t.tree.nodes[0].hit->normal;
    EXPECT_NE(ray_tree_text(t.tree, t.context).find("the normal's length is 2, not 1"), std::string::npos);
}

TEST(TraceReport, JsonNestsEveryRayOnce) {
    Traced t;
    t.settings.stage = 6;
    t.tree.clear();
    Tracer(t.scene, t.settings, t.stats, &t.tree).trace_pixel(17.5, 16.5);
    const nlohmann::json json = ray_tree_json(t.tree, t.context);
    std::size_t rays = 0;
    std::function<void(const nlohmann::json&)> count = [&](const nlohmann::json& ray) {
        ++rays;
        for (const nlohmann::json& child : ray["children"]) count(child);
    };
    count(json["ray"]);
    EXPECT_EQ(rays, t.tree.nodes.size());
    EXPECT_EQ(json["ray"]["kind"], "eye");
    EXPECT_GT(t.tree.nodes.size(), 3u);
}

TEST(TraceReport, RaysWithNaNFromBuggyCodeAreReportedAndNotDrawn) {
    // Code with a bug can hand the tracer NaN directions and hit points: the
    // text says nan, the JSON null, and the picture has no NaN pixel.
    Traced t;
    t.trace(Ray{Point3(0.8, 5.0, 0.0), Vec3(0.0, -1.0, 0.0)});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    RayNode bad = t.tree.nodes[0];
    bad.kind = RayKind::refracted;
    bad.parent = 0;
    bad.depth = 2;
    bad.children.clear();
    bad.ray.direction = Vec3(nan);
    bad.hit->point = Vec3(nan);
    t.tree.nodes[0].children.push_back(static_cast<int>(t.tree.nodes.size()));
    t.tree.nodes.push_back(bad);
    EXPECT_NE(ray_tree_text(t.tree, t.context).find("nan"), std::string::npos);
    EXPECT_TRUE(ray_tree_json(t.tree, t.context).dump().find("null") != std::string::npos);
    const Image view(32, 32, Color(0.5));
    const Camera side = side_camera_for(t.tree, t.scene.camera(), 32, 32);
    EXPECT_TRUE(is_finite(side.eye));
    const Image picture = ray_tree_picture(t.tree, t.context, view, view, side);
    EXPECT_EQ(count_non_finite(picture), 0u);
}
