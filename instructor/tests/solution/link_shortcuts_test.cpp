// The grading link's two shortcuts (instructor/link/lab_link.hpp) give the answers one call at a time would.
//
// StratifiedCell: a worker turns the cell the checker sends into stratified_sample()'s answer for each u; it
// must be the reference's answer to the last bit, or lab 8's image test would grade a student's light points
// against points that are not the reference's. LensRaysAhead: the checker asks for the eye rays of the
// samples its own pixel_color() traces next; a wrong guess only costs speed, but every guess that is right is
// what makes lab 9's image test fast, so the guesses are checked against what pixel_color() really traces.
// AnswerAhead: the checker's answers to the calls fresnel_blend() makes of labs 2, 4 and 5 are the reference's,
// and are sent only where those labs are earlier than the graded one and this program's.
#include "channel.hpp"
#include "lab_link.hpp"

#include "whitted/labs.hpp"
#include "whitted/tracer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <unistd.h>
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

// A channel's descriptors, closed at the end (the memory stays mapped by the links made on it).
struct OpenChannel {
    link::ChannelPair pair = link::make_channel_pair();
    ~OpenChannel() {
        for (const link::ChannelFds& side : {pair.checker, pair.worker})
            for (const int fd : {side.memory, side.wake_in, side.wake_out}) ::close(fd);
    }
};

// A glass sphere's material (index 0) in a scene, and a hit on it from outside or from inside.
struct GlassHit {
    Scene scene;
    Hit hit;
    static SceneData glass() {
        SceneData data;
        data.camera = Camera::create(Point3(0.0, 0.0, 5.0), Point3(0.0), Vec3(0.0, 1.0, 0.0), 40.0, 64, 48);
        Material material;
        material.transmittance = 0.9, material.ior = 1.5;
        data.materials.push_back(material);
        return data;
    }
    explicit GlassHit(bool front_face) : scene(glass()) {
        // The unit sphere at the origin, hit at (0, 0, 1) from outside or from inside: the normal faces the ray
        // either way.
        hit.front_face = front_face;
        hit.point = Point3(0.0, 0.0, 1.0);
        hit.normal = hit.geometric_normal = Vec3(0.0, 0.0, front_face ? 1.0 : -1.0);
    }
};

// The function an answer ahead answers: its call's first two bytes.
std::uint16_t op_of(const link::AnswerAhead& answer) { return link::Reader(answer.call).raw<std::uint16_t>(); }

// What each answer ahead says: the reference's result for its call, decoded as the worker decodes a reply.
void expect_reference_answers(const std::vector<link::AnswerAhead>& answers) {
    for (const link::AnswerAhead& answer : answers) {
        link::Reader in(answer.call), reply(answer.reply);
        const auto op = in.raw<std::uint16_t>();
        if (op == static_cast<std::uint16_t>(link::Op::mirror_direction)) {
            const Vec3 wo = in.get<Vec3>(), n = in.get<Vec3>();
            EXPECT_EQ(reply.get<Vec3>(), mirror_direction(wo, n));
        } else if (op == static_cast<std::uint16_t>(link::Op::refracted_direction)) {
            const Vec3 wo = in.get<Vec3>(), n = in.get<Vec3>();
            const double eta_i = in.get<double>(), eta_t = in.get<double>();
            EXPECT_EQ(reply.get<std::optional<Vec3>>(), refracted_direction(wo, n, eta_i, eta_t));
        } else {
            ASSERT_EQ(op, static_cast<std::uint16_t>(link::Op::spawn_ray));
            const Hit hit = in.get<Hit>();
            const Vec3 direction = in.get<Vec3>();
            const Ray expected = spawn_ray(hit, direction), answered = reply.get<Ray>();
            EXPECT_EQ(answered.origin, expected.origin);
            EXPECT_EQ(answered.direction, expected.direction);
        }
        EXPECT_TRUE(in.at_end() && reply.at_end());
    }
}

TEST(LinkShortcuts, FresnelBlendsCallsAreAnsweredAheadWithTheReferencesAnswers) {
    RenderSettings settings;
    RayStats stats;
    for (const bool front_face : {true, false}) {
        const GlassHit glass(front_face);
        Tracer tracer(glass.scene, settings, stats);
        const OpenChannel channel;
        link::Link checker(link::Role::checker, channel.pair.checker, link::lab_bit(6));
        // The mirror direction and its ray, then the refracted direction for both orders of the indices (air to
        // glass, glass to air) and each one's ray. At 60 degrees from the normal, past the critical angle of glass
        // to air (41.8 degrees): no refracted ray that way, from either side.
        const Vec3 wo = Vec3(std::sqrt(0.75), 0.0, 0.5) * (front_face ? 1.0 : -1.0);
        const std::vector<link::AnswerAhead> answers = checker.fresnel_blend_answers(tracer, glass.hit, wo);
        EXPECT_EQ(answers.size(), 5u);
        expect_reference_answers(answers);
        // The same calls, in the same order, whichever side the hit is on: nothing tells which order applies.
        std::vector<std::uint16_t> ops;
        for (const link::AnswerAhead& answer : answers) ops.push_back(op_of(answer));
        const std::vector<std::uint16_t> expected_ops = {
            static_cast<std::uint16_t>(link::Op::mirror_direction), static_cast<std::uint16_t>(link::Op::spawn_ray),
            static_cast<std::uint16_t>(link::Op::refracted_direction), static_cast<std::uint16_t>(link::Op::spawn_ray),
            static_cast<std::uint16_t>(link::Op::refracted_direction)};
        EXPECT_EQ(ops, expected_ops);
    }
}

TEST(LinkShortcuts, NoAnswersAheadOfLabsThatAreTheGradedOnesOrLater) {
    // Lab 5's checker would hand over lab 5's refracted_direction(); where every lab is the worker's (the
    // integration tests), the answers would be the reference's, not the student's.
    RenderSettings settings;
    RayStats stats;
    const GlassHit glass(true);
    Tracer tracer(glass.scene, settings, stats);
    for (const link::LabSet graded : {link::lab_bit(4), link::lab_bit(5), link::LabSet{0x7fe}}) {
        const OpenChannel channel;
        link::Link checker(link::Role::checker, channel.pair.checker, graded);
        EXPECT_TRUE(checker.fresnel_blend_answers(tracer, glass.hit, Vec3(0.0, 0.0, 1.0)).empty()) << graded;
    }
    const OpenChannel channel;
    link::Link worker(link::Role::worker, channel.pair.worker, 0);
    EXPECT_TRUE(worker.fresnel_blend_answers(tracer, glass.hit, Vec3(0.0, 0.0, 1.0)).empty());
}

} // namespace
