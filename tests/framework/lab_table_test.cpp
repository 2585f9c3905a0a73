// The lab table (whitted/lab_table.hpp) is the one list of labs: each row must
// come with its files, its functions in the contract, and a probe for each.
#include "whitted/lab_status.hpp"
#include "whitted/scene.hpp"
#include "whitted/tracer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace whitted;

namespace {

const std::filesystem::path kSource = WHITTED_SOURCE_DIR;

std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST(LabTable, EveryRowHasItsLabFileTestsAndHandout) {
    for (const LabInfo& lab : kLabs) {
        const std::string stem(lab.stem);
        EXPECT_TRUE(std::filesystem::is_regular_file(kSource / "labs" / (stem + ".cpp"))) << stem;
        EXPECT_TRUE(std::filesystem::is_directory(kSource / "tests" / "labs" / stem)) << stem;
        EXPECT_TRUE(std::filesystem::is_regular_file(kSource / "docs" / "labs" / (stem + ".md"))) << stem;
    }
}

TEST(LabTable, EveryFunctionIsDeclaredInTheContractOnce) {
    const std::string contract = read_text(kSource / "framework" / "include" / "whitted" / "labs.hpp");
    std::set<std::string_view> seen;
    for (const LabInfo& lab : kLabs) {
        ASSERT_FALSE(lab_functions(lab).empty()) << lab.stem;
        for (const std::string_view function : lab_functions(lab)) {
            EXPECT_TRUE(seen.insert(function).second) << function << " is in two rows";
            const std::string declared = std::string(function).insert(0, 1, ' ').append(1, '(');
            EXPECT_NE(contract.find(declared), std::string::npos)
                << function << " (lab " << lab.number << ") is not declared in labs.hpp";
        }
    }
}

TEST(LabTable, EveryFunctionHasAProbeAndEveryProbeAFunction) {
    SceneData data;
    data.lights = {PointLight{Point3(0.0, 5.0, 0.0), Color(1.0)}};
    const Scene scene(std::move(data));
    const RenderSettings settings;
    RayStats stats;
    const Tracer tracer(scene, settings, stats);
    std::set<std::string_view> probed;
    for (const auto& [function, probe] : lab_probes(scene, tracer)) probed.insert(function);
    std::set<std::string_view> asked;
    for (const LabInfo& lab : kLabs)
        for (const std::string_view function : lab_functions(lab)) asked.insert(function);
    EXPECT_EQ(probed, asked);
}

TEST(LabTable, StageListAndDefaultsFollowTheTable) {
    EXPECT_EQ(stage_list(), "1 ray casting, 2 shadows, 3 Blinn-Phong, 4 reflection, 5 refraction, 6 Fresnel, 7 anti-aliasing, 8 soft shadows, 9 depth of field, 10 bounding volume hierarchy");
    EXPECT_EQ(RenderSettings{}.stage, kLabCount);
    EXPECT_EQ(probe_labs().size(), kLabs.size());
}

TEST(LabTable, FunctionListsSplitOnSpaces) {
    EXPECT_EQ(lab_functions(LabInfo{1, "01_x", "x", Stage::ray_casting, "a  bc d"}),
              (std::vector<std::string_view>{"a", "bc", "d"}));
    EXPECT_TRUE(lab_functions(LabInfo{1, "01_x", "x", Stage::ray_casting, ""}).empty());
}
