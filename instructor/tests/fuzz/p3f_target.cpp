// libFuzzer target: the P3F loader and a tiny render of every scene it accepts.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    whitted::fuzz::check_scene_input(data, size, whitted::Dialect::p3f);
    return 0;
}
