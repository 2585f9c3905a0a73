// Where `whitted explore` finds the build it rebuilds when a lab file is saved.
//
// Why: the page follows the student's edits, so the server must rebuild the labs and render with the new
// program. The server cannot rebuild itself (Windows refuses to overwrite a running program), so each build
// has a twin of `whitted`, the worker, built only when explore asks for it; the server runs it for every
// picture and tree. CMake writes this information into the `whitted` it builds (cmake/WhittedLabs.cmake).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace whitted {

struct LiveBuild {
    std::filesystem::path cmake;     // the cmake program that configured the build
    std::filesystem::path build_dir; // the build folder
    std::string config;              // the configuration to build (Debug, Release, ...); empty: the build's own
    std::string worker_target;       // the target to build: `whitted` with the same labs
    std::filesystem::path worker;    // its executable file
    std::filesystem::path labs_dir;  // the folder of the lab files it is built from
};

/// This program's build, when it was built with one (the main `whitted` of a build); none otherwise.
std::optional<LiveBuild> live_build();

} // namespace whitted
