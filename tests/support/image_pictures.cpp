#include "image_pictures.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace whitted::testing_helpers {
namespace {

// A number for JSON: finite values with enough digits to round-trip, else null.
std::string json_number(double value) {
    if (!std::isfinite(value)) return "null";
    char text[64];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

} // namespace

void write_gate_numbers(const ImageDifference& d, const std::string& scene, int stage, const std::filesystem::path& file) {
    std::ofstream out(file);
    out << "{\n"
        << "  \"scene\": \"" << scene << "\",\n"
        << "  \"stage\": " << stage << ",\n"
        << "  \"same_size\": " << (d.same_size ? "true" : "false") << ",\n"
        << "  \"pixel_count\": " << d.pixel_count << ",\n"
        << "  \"failing_pixels\": " << d.failing_pixels << ",\n"
        << "  \"non_finite_pixels\": " << d.non_finite_pixels << ",\n"
        << "  \"failing_fraction\": " << json_number(d.same_size ? d.failing_fraction : 1.0) << ",\n"
        << "  \"mean_error\": " << json_number(d.same_size ? d.mean_error : 1.0) << ",\n"
        << "  \"max_error\": " << json_number(d.same_size ? d.max_error : 1.0) << ",\n"
        << "  \"worst_x\": " << d.worst_x << ",\n"
        << "  \"worst_y\": " << d.worst_y << ",\n"
        << "  \"psnr\": " << json_number(d.psnr) << ",\n"
        << "  \"passed\": " << (d.passed ? "true" : "false") << "\n"
        << "}\n";
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

} // namespace whitted::testing_helpers
