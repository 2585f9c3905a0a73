// "Did you mean ...?" (framework/app/closest_name.hpp): the edit distance and when a name is near enough.
#include "closest_name.hpp"

#include <gtest/gtest.h>

namespace whitted {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsAndReplacements) {
    EXPECT_EQ(edit_distance("render", "render"), 0u);
    EXPECT_EQ(edit_distance("rendr", "render"), 1u);
    EXPECT_EQ(edit_distance("renders", "render"), 1u);
    EXPECT_EQ(edit_distance("grade", "trace"), 2u);
    EXPECT_EQ(edit_distance("", "labs"), 4u);
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(EditDistance, CountsASwapOfNeighboursAsOneEdit) {
    EXPECT_EQ(edit_distance("lbas", "labs"), 1u);
    EXPECT_EQ(edit_distance("widht", "width"), 1u);
    EXPECT_EQ(edit_distance("ab", "ba"), 1u);
}

TEST(EditDistance, IsSymmetric) {
    EXPECT_EQ(edit_distance("max-dpeth", "max-depth"), edit_distance("max-depth", "max-dpeth"));
    EXPECT_EQ(edit_distance("generate", "gen"), edit_distance("gen", "generate"));
}

TEST(ClosestName, SuggestsANameOneSlipAway) {
    const std::vector<std::string> commands = {"render", "trace", "diff", "generate", "labs", "completion"};
    EXPECT_EQ(closest_name("rendr", commands), "render");
    EXPECT_EQ(closest_name("lbas", commands), "labs");
    EXPECT_EQ(closest_name("gnerate", commands), "generate");
}

TEST(ClosestName, AllowsOneEditForEveryThreeLetters) {
    const std::vector<std::string> options = {"width", "height", "max-depth", "min-weight"};
    EXPECT_EQ(closest_name("max-dpht", options), "max-depth"); // two edits in eight letters
    EXPECT_EQ(closest_name("wdht", options), std::nullopt);    // two edits in four letters
}

TEST(ClosestName, SuggestsNothingForAFarName) {
    const std::vector<std::string> commands = {"render", "trace", "diff", "generate", "labs", "completion"};
    EXPECT_EQ(closest_name("grade", commands), std::nullopt); // two edits from trace: too many for five letters
    EXPECT_EQ(closest_name("paint", commands), std::nullopt);
    EXPECT_EQ(closest_name("x", {}), std::nullopt);
}

TEST(ClosestName, SuggestsTheOneNameAShortenedNameBegins) {
    const std::vector<std::string> options = {"--output", "--overwrite", "--threads", "--stage", "--stats"};
    EXPECT_EQ(closest_name("--out", options), "--output"); // three edits from --output: no slip, but its beginning
    EXPECT_EQ(closest_name("--thr", options), "--threads");
    EXPECT_EQ(closest_name("--st", options), std::nullopt);  // two letters
    EXPECT_EQ(closest_name("--sta", options), std::nullopt); // the beginning of --stage and --stats
}

TEST(ClosestName, PrefersTheNearestName) {
    EXPECT_EQ(closest_name("heigth", {"width", "height"}), "height");
    EXPECT_EQ(closest_name("spp", {"stats", "spp"}), "spp");
}

} // namespace
} // namespace whitted
