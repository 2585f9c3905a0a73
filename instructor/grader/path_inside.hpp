// Whether one path lies inside a folder, by whole components: what the grader's
// commands check before writing, so that no output lands in what they read.
#pragma once

#include <algorithm>
#include <filesystem>

namespace whitted::grade {

/// True when `path` is `folder` or lies below it (both absolute and normalised; "/a/bc" is not inside "/a/b").
inline bool path_inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
    const auto [end, ignored] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
    return end == folder.end();
}

} // namespace whitted::grade
