#include "whitted/image.hpp"

namespace whitted {
// Placeholder until image I/O lands.
std::size_t count_non_finite(const Image&) { throw ImageError("count_non_finite() is not implemented yet"); }
void write_image(const Image&, const std::filesystem::path&, Encoding) { throw ImageError("write_image() is not implemented yet"); }
Image read_image(const std::filesystem::path&) { throw ImageError("read_image() is not implemented yet"); }
unsigned char to_byte(double, Encoding) { return 0; }
} // namespace whitted
