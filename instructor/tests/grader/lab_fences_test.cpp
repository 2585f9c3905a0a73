// The link fence (grader/lab_fences.hpp) and the symbol reader under it
// (grader/elf_symbols.hpp), on objects compiled here: a lab's object that
// calls a fenced function of the kit is refused for the labs the fence names,
// and a damaged object is refused rather than read past its end.
#include "grader/elf_symbols.hpp"
#include "grader/lab_fences.hpp"
#include "grader/submission.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace whitted::grade;
namespace fs = std::filesystem;

namespace {

/// A folder of this test's own, removed at the end.
struct Scratch {
    fs::path folder = fs::temp_directory_path() / ("lab_fences_test_" + std::to_string(getpid()));
    Scratch() { fs::create_directories(folder); }
    ~Scratch() { fs::remove_all(folder); }

    /// Compiles `source` to an object and returns its path.
    fs::path object(const std::string& name, const std::string& source) const {
        const fs::path cpp = folder / (name + ".cpp"), o = folder / (name + ".o");
        std::ofstream(cpp) << source;
        const std::string command = std::string(TEST_CXX) + " -std=c++20 -c " + cpp.string() + " -o " + o.string();
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        return o;
    }
};

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// A stand-in for the framework: one fenced function for every lab, one for lab 10 only, one free to use.
constexpr const char* kFramework = R"(
namespace whitted {
int framework_bvh_tree(int n) { return n; }
struct Scene { int closest_hit(int) const; };
int Scene::closest_hit(int n) const { return n; }
int intersect(int n) { return n; }
})";

constexpr const char* kDeclarations = R"(
namespace whitted {
int framework_bvh_tree(int);
struct Scene { int closest_hit(int) const; };
int intersect(int);
})";

} // namespace

TEST(ElfSymbols, ReadsWhatAnObjectDefinesAndCalls) {
    const Scratch scratch;
    const fs::path o = scratch.object("calls", "int f(int); int g(int x) { return f(x) + 1; }");
    const ObjectSymbols symbols = elf_object_symbols(read_regular_file(o, 1 << 24));
    EXPECT_TRUE(has(symbols.undefined, "_Z1fi"));
    EXPECT_TRUE(has(symbols.defined, "_Z1gi"));
    EXPECT_FALSE(has(symbols.defined, "_Z1fi"));
}

TEST(ElfSymbols, ADamagedObjectIsRefusedNotReadPastItsEnd) {
    const Scratch scratch;
    const std::string bytes = read_regular_file(scratch.object("whole", "int f(int); int g(int x) { return f(x); }"), 1 << 24);
    // Every shorter prefix either still reads (the tables ended before the cut) or is refused.
    for (std::size_t size = 0; size < bytes.size(); ++size) {
        try {
            elf_object_symbols(std::string_view(bytes).substr(0, size));
        } catch (const ObjectFormatError&) {
        }
    }
    EXPECT_THROW(elf_object_symbols("not an object at all, but long enough to have a header of sixty-four bytes."),
                 ObjectFormatError);
    EXPECT_THROW(archive_defined_symbols("!<arch>\nx/              0           0     0     644     99999999  `\n"),
                 ObjectFormatError);
}

TEST(LabFences, ACallOfAFencedFunctionRefusesTheLabsItIsFencedFor) {
    const Scratch scratch;
    const fs::path framework = scratch.object("framework", kFramework);
    const fs::path library = scratch.folder / "libframework.a";
    const std::string archive = std::string(TEST_AR) + " rcs " + library.string() + " " + framework.string();
    ASSERT_EQ(std::system(archive.c_str()), 0) << archive;
    WorkerKit kit;
    kit.libraries = {library};
    const LabFences fences(kit);

    const auto refused = [&](const std::string& lab, const std::string& name, const std::string& body) {
        return fences.refused(lab, read_regular_file(scratch.object(name, std::string(kDeclarations) + body), 1 << 24));
    };
    const std::vector<FencedCall> builder = refused("04_reflection", "builder", "int f() { return whitted::framework_bvh_tree(1); }");
    ASSERT_EQ(builder.size(), 1u) << "the framework's builder is fenced for every lab";
    EXPECT_EQ(builder[0].function, "whitted::framework_bvh_tree(int)");
    EXPECT_NE(LabFences::describe("04_reflection", builder).find("labs/04_reflection.cpp calls whitted::framework_bvh_tree(int)"),
              std::string::npos);
    const std::string query = "int f(const whitted::Scene& s) { return s.closest_hit(1); }";
    EXPECT_EQ(refused("10_bvh", "query10", query).size(), 1u) << "the scene's queries are lab 10's answer";
    EXPECT_TRUE(refused("04_reflection", "query4", query).empty()) << "... and any other lab's to use";
    EXPECT_TRUE(refused("10_bvh", "free", "int f() { return whitted::intersect(1); }").empty());
}
