// Generating and listing the benchmark's scenes (see bench_scenes.hpp).
#include "bench_scenes.hpp"

#include "whitted/generators.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <stdexcept>

namespace whitted::bench {
namespace {

// `name`, or name-2, name-3... when it is already taken.
std::string unique_name(const std::vector<BenchScene>& scenes, const std::string& name) {
    auto taken = [&](const std::string& candidate) {
        return std::any_of(scenes.begin(), scenes.end(), [&](const BenchScene& s) { return s.name == candidate; });
    };
    std::string candidate = name;
    for (int n = 2; taken(candidate); ++n) candidate = name + "-" + std::to_string(n);
    return candidate;
}

BenchScene generate(const Generator& generator, int level, const std::filesystem::path& folder) {
    BenchScene scene;
    scene.name = std::string(generator.short_name) + std::to_string(level);
    scene.path = folder / (scene.name + std::string(generator.extension));
    scene.generator = generator.name;
    scene.level = level;
    scene.generated_primitives = generator.primitive_count(level);
    std::ofstream file(scene.path, std::ios::binary);
    if (file) generator.write(level, file);
    file.close();
    if (!file) throw std::runtime_error("cannot write the generated scene " + scene.path.string());
    return scene;
}

BenchScene given(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".nff" && extension != ".p3f")
        throw std::runtime_error("not a scene file (.nff or .p3f): " + path.string());
    if (!std::ifstream(path)) throw std::runtime_error("cannot read the scene " + path.string());
    BenchScene scene;
    scene.name = path.stem().string();
    scene.path = std::filesystem::absolute(path).lexically_normal();
    return scene;
}

} // namespace

std::vector<BenchScene> prepare_scenes(const BenchOptions& options, const std::filesystem::path& folder) {
    std::vector<BenchScene> files;
    for (const std::filesystem::path& path : options.scenes) files.push_back(given(path)); // all checked before writing
    std::vector<BenchScene> scenes;
    for (int level : options.flake_levels) scenes.push_back(generate(*find_generator("sphereflake"), level, folder));
    for (int level : options.tetra_levels) scenes.push_back(generate(*find_generator("tetra"), level, folder));
    for (int level : options.soup_levels) scenes.push_back(generate(*find_generator("soup"), level, folder));
    for (BenchScene& scene : files) {
        scene.name = unique_name(scenes, scene.name);
        scenes.push_back(scene);
    }
    return scenes;
}

} // namespace whitted::bench
