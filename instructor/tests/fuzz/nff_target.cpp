// libFuzzer target: the NFF loader and a tiny render of every scene it accepts.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    whitted::fuzz::check_scene_input(data, size, whitted::Dialect::nff);
    return 0;
}
