#include "whitted/scene_loader.hpp"

namespace whitted {
// Placeholder until the loaders land.
LoadedScene load_scene(const std::filesystem::path&, const SceneLimits&) { throw SceneError("load_scene() is not implemented yet"); }
LoadedScene parse_scene(std::string_view, Dialect, std::string_view, const SceneLimits&) { throw SceneError("parse_scene() is not implemented yet"); }
} // namespace whitted
