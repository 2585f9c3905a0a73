// Lab 8, light_samples(): an area light as light.samples point lights for the
// pixel sample being traced, each with an equal share of the colour, spread over
// the light on lab 7's jittered grid with the framework's numbers.
#include "whitted/labs.hpp"

#include "lab_helpers.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace whitted;
using namespace whitted::testing_helpers;

namespace {

/// A scene with only an area light: light_samples needs a tracer for its pixel sample.
struct LightScene {
    Scene scene;
    RenderSettings settings = soft_shadow_settings();
    RayStats stats;
    Tracer tracer{scene, settings, stats};
    explicit LightScene(const AreaLight& light) : scene(scene_with(light)) {}
    static SceneData scene_with(const AreaLight& light) {
        SceneData data;
        data.area_lights = {light};
        return data;
    }
    const AreaLight& light() const { return scene.area_lights()[0]; }
};

} // namespace

TEST(LightSamples, OnePointLightPerSampleEachWithAnEqualShareOfTheColour) {
    AreaLight light = square_light(Point3(0.0, 10.0, 0.0), 2.0, 9);
    light.color = Color(0.9, 0.6, 0.3);
    const LightScene s(light);
    s.tracer.begin_pixel(PixelSample{3, 4, 0});
    const std::vector<PointLight> points = light_samples(s.tracer, s.light());
    ASSERT_EQ(points.size(), 9u) << "light.samples = 9 point lights";
    Color total(0.0);
    for (const PointLight& point : points) {
        EXPECT_NEAR(point.color.r, 0.1, 1e-15);
        EXPECT_NEAR(point.color.g, 0.6 / 9.0, 1e-15);
        EXPECT_NEAR(point.color.b, 0.3 / 9.0, 1e-15);
        total += point.color;
    }
    EXPECT_NEAR(total.r, 0.9, 1e-12) << "together the points give the light's whole colour";
}

TEST(LightSamples, PointKIsWhereTheHandoutPutsIt) {
    // Point k: numbers u = sample_numbers(pixel sample, SampleUse::light, first_number + k),
    // placed in cell k of the grid by stratified_sample, then onto the light by point_on_light.
    AreaLight light;
    light.center = Point3(1.0, 8.0, -2.0);
    light.edge_u = Vec3(3.0, 0.0, 0.0);
    light.edge_v = Vec3(0.0, 1.0, 2.0);
    for (int count : {1, 4, 6, 16}) {
        light.samples = count;
        const LightScene s(light);
        for (const PixelSample sample : {PixelSample{0, 0, 0}, PixelSample{5, 2, 3}, PixelSample{100, 7, 1}}) {
            s.tracer.begin_pixel(sample);
            const std::vector<PointLight> points = light_samples(s.tracer, s.light());
            ASSERT_EQ(points.size(), static_cast<std::size_t>(count));
            for (int k = 0; k < count; ++k) {
                expect_point(points[static_cast<std::size_t>(k)].position, expected_light_point(s.light(), sample, k),
                             std::to_string(count) + " samples, point " + std::to_string(k) + " of pixel (" +
                                 std::to_string(sample.x) + ", " + std::to_string(sample.y) + ") sample " +
                                 std::to_string(sample.index));
                if (enough_failures()) return;
            }
        }
    }
}

TEST(LightSamples, EachCellOfTheLightHoldsOnePoint) {
    // 16 points, a 4 x 4 grid over the 4 x 4 square: one point in each unit cell.
    const LightScene s(square_light(Point3(0.0, 10.0, 0.0), 4.0, 16));
    s.tracer.begin_pixel(PixelSample{11, 13, 2});
    std::set<std::pair<int, int>> cells;
    for (const PointLight& point : light_samples(s.tracer, s.light())) {
        EXPECT_NEAR(point.position.y, 10.0, 1e-12) << "on the light";
        const int cell_x = static_cast<int>(std::floor(point.position.x + 2.0));
        const int cell_z = static_cast<int>(std::floor(point.position.z + 2.0));
        ASSERT_TRUE(cell_x >= 0 && cell_x < 4 && cell_z >= 0 && cell_z < 4)
            << "a point outside the light: (" << point.position.x << ", " << point.position.z << ")";
        cells.insert({cell_x, cell_z});
    }
    EXPECT_EQ(cells.size(), 16u) << "two points share a cell: the grid is not stratified";
}

TEST(LightSamples, EachPixelSampleAndEachLightHasItsOwnPoints) {
    // Other pixel samples jitter the points differently (no fixed pattern of hard shadows),
    // and a second light draws other numbers (its first_number).
    AreaLight light = square_light(Point3(0.0, 10.0, 0.0), 2.0, 4);
    SceneData data;
    data.area_lights = {light, light};
    const Scene scene(data);
    ASSERT_EQ(scene.area_lights()[1].first_number, 4u) << "the scene numbers the lights' points one after the other";
    RayStats stats;
    const RenderSettings settings = soft_shadow_settings();
    const Tracer tracer(scene, settings, stats);
    tracer.begin_pixel(PixelSample{2, 2, 0});
    const std::vector<PointLight> first = light_samples(tracer, scene.area_lights()[0]);
    const std::vector<PointLight> second = light_samples(tracer, scene.area_lights()[1]);
    tracer.begin_pixel(PixelSample{2, 2, 1});
    const std::vector<PointLight> next_sample = light_samples(tracer, scene.area_lights()[0]);
    ASSERT_EQ(first.size(), 4u);
    ASSERT_EQ(second.size(), 4u);
    ASSERT_EQ(next_sample.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_NE(first[k].position, second[k].position) << "point " << k << ": the second light uses the first one's numbers";
        EXPECT_NE(first[k].position, next_sample[k].position) << "point " << k << ": sample 1 of the pixel reuses sample 0's numbers";
    }
}
