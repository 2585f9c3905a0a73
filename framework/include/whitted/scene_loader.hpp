// Reading scene files: NFF 3.9 (Eric Haines' Neutral File Format) and P3F (the
// course's format), plus the framework's small extensions (docs/scene_format.md).
//
// Why: both formats are read as a stream of tokens, so line breaks never matter
// and every error can name the file, line and column where it happened. The
// dialect comes from the file extension. All validation happens here, so the
// renderer can trust what it gets.
#pragma once

#include "whitted/scene.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace whitted {

/// A scene file error. what() is one line: "file:line:col: what was expected, what was found".
struct SceneError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

enum class Dialect { nff, p3f };

struct LoadedScene {
    SceneData data;
    std::vector<std::string> warnings; // one line each, "file:line:col: warning: ..."
};

/// Hard limits that keep hostile files from exhausting the machine. Numbers
/// must also be finite and within +-1e15, and `maxdepth` at most 100.
struct SceneLimits {
    std::size_t max_file_bytes = std::size_t{1} << 30; // 1 GiB; sphereflake level 7 is about 0.4 GiB
    std::size_t max_token_length = 1024;               // characters in one word or number
    int max_resolution = 16384;                        // per side
    std::size_t max_pixels = std::size_t{1} << 26;     // width x height: 8192 x 8192
    std::size_t max_primitives = 10'000'000;           // about 2.6 GB of scene at most
    std::size_t max_polygon_vertices = 10'000;
};

/// Loads a scene file; the dialect comes from the extension (.nff or .p3f).
/// Throws SceneError.
LoadedScene load_scene(const std::filesystem::path& path, const SceneLimits& limits = {});

/// Parses scene text; `file_name` is used in messages only. Throws SceneError.
LoadedScene parse_scene(std::string_view text, Dialect dialect, std::string_view file_name,
                        const SceneLimits& limits = {});

} // namespace whitted
