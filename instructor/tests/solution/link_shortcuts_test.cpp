// The grading link's two shortcuts (instructor/link/lab_link.hpp) give the answers one call at a time would.
//
// StratifiedCell: a worker turns the cell the checker sends into stratified_sample()'s answer for each u; it
// must be the reference's answer to the last bit, or lab 8's image test would grade a student's light points
// against points that are not the reference's. LensRaysAhead: the checker asks for the eye rays of the
// samples its own pixel_color() traces next; a wrong guess only costs speed, but every guess that is right is
// what makes lab 9's image test fast, so the guesses are checked against what pixel_color() really traces.
#include "lab_link.hpp"

#include "whitted/labs.hpp"
#include "whitted/tracer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace whitted;
using link::LensRaysAhead;

namespace {

std::uint64_t bits_of(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

TEST(LinkShortcuts, TheCellGivesTheReferencesSampleToTheLastBit) {
    std::mt19937_64 numbers(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int count = 1; count <= 70; ++count)
        for (int index = 0; index < count; ++index) {
            const std::optional<link::StratifiedCell> cell = link::stratified_cell_of(index, count);
            ASSERT_TRUE(cell) << "index " << index << " of " << count;
            for (int trial = 0; trial < 50; ++trial) {
                const Vec2 u(unit(numbers), unit(numbers));
                const Vec2 expected = stratified_sample(index, count, u);
                const Vec2 computed = cell->sample(u);
                ASSERT_EQ(bits_of(computed.x), bits_of(expected.x)) << index << " of " << count << " at u.x " << u.x;
                ASSERT_EQ(bits_of(computed.y), bits_of(expected.y)) << index << " of " << count << " at u.y " << u.y;
            }
        }
}

// What a tracer's trace_sample() was asked, recorded in place of tracing.
class RecordedSamples final : public TraceForwarding {
  public:
    mutable std::vector<LensRaysAhead::Query> asked;
    Color trace(const Tracer&, const Ray&, int, RayKind, const Color&) const override { return Color(0.0); }
    Color trace_sample(const Tracer&, const PixelSample& sample, double x, double y) const override {
        asked.push_back({x, y, sample_numbers(sample, SampleUse::lens)});
        return Color(0.0);
    }
};

TEST(LinkShortcuts, ThePixelsSamplesAreThoseItsPixelColorTraces) {
    SceneData data;
    data.camera = Camera::create(Point3(0.0, 0.0, 5.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 40.0, 64, 48);
    const Scene scene(data);
    for (const int count : {2, 4, 9, 16, 25}) {
        RenderSettings settings;
        settings.stage = stage_number(Stage::depth_of_field);
        settings.samples_per_pixel = count;
        RayStats stats;
        Tracer tracer(scene, settings, stats);
        RecordedSamples recorded;
        tracer.forward_to(&recorded);
        for (const auto& [px, py] : {std::pair{0, 0}, std::pair{17, 5}, std::pair{63, 47}}) {
            recorded.asked.clear();
            pixel_color(tracer, px, py);
            ASSERT_EQ(recorded.asked.size(), static_cast<std::size_t>(count));
            for (std::size_t k = 0; k < recorded.asked.size(); ++k) {
                const LensRaysAhead::Query& from = recorded.asked[k];
                const std::vector<LensRaysAhead::Query> guessed = link::pixel_samples_from(from.x, from.y, from.lens_u);
                const std::vector<LensRaysAhead::Query> traced(recorded.asked.begin() + static_cast<std::ptrdiff_t>(k),
                                                                recorded.asked.end());
                EXPECT_TRUE(guessed == traced) << "pixel (" << px << ", " << py << "), sample " << k << " of " << count;
            }
        }
    }
}

TEST(LinkShortcuts, NoGuessForNumbersThatAreNoPixelsSample) {
    EXPECT_TRUE(link::pixel_samples_from(10.5, 3.5, Vec2(0.5, 0.5)).empty());
    EXPECT_TRUE(link::pixel_samples_from(1e300, 3.5, Vec2(0.5, 0.5)).empty());
}

} // namespace
