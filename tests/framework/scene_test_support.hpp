// Small helpers for the scene loader tests: parse text, or catch its error message.
#pragma once

#include "whitted/scene_loader.hpp"

#include <string>
#include <string_view>

namespace scene_test {

/// A viewpoint on line 1, for scenes whose camera does not matter: the body starts on line 2.
inline constexpr std::string_view kView = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 64 48\n";

/// Parses NFF text named "scene.nff".
inline whitted::LoadedScene nff(std::string_view text) {
    return whitted::parse_scene(text, whitted::Dialect::nff, "scene.nff");
}

/// Parses P3F text named "scene.p3f".
inline whitted::LoadedScene p3f(std::string_view text) {
    return whitted::parse_scene(text, whitted::Dialect::p3f, "scene.p3f");
}

/// Parses the viewpoint line followed by the NFF body.
inline whitted::LoadedScene nff_body(std::string_view body) { return nff(std::string(kView) + std::string(body)); }

/// Parses the viewpoint line followed by the P3F body.
inline whitted::LoadedScene p3f_body(std::string_view body) { return p3f(std::string(kView) + std::string(body)); }

/// The message of the SceneError that parsing throws, or "no error".
inline std::string error_of(std::string_view text, whitted::Dialect dialect, const whitted::SceneLimits& limits = {}) {
    try {
        whitted::parse_scene(text, dialect, dialect == whitted::Dialect::nff ? "scene.nff" : "scene.p3f", limits);
    } catch (const whitted::SceneError& error) {
        return error.what();
    }
    return "no error";
}

/// The error of the viewpoint line followed by the NFF body.
inline std::string nff_error(std::string_view body, const whitted::SceneLimits& limits = {}) {
    return error_of(std::string(kView) + std::string(body), whitted::Dialect::nff, limits);
}

/// The error of the viewpoint line followed by the P3F body.
inline std::string p3f_error(std::string_view body, const whitted::SceneLimits& limits = {}) {
    return error_of(std::string(kView) + std::string(body), whitted::Dialect::p3f, limits);
}

} // namespace scene_test
