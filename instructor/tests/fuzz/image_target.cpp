// libFuzzer target: the PNG, PPM and PFM readers.
#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    whitted::fuzz::check_image_input(data, size);
    return 0;
}
