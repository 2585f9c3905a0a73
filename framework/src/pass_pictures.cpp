#include "pass_pictures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace whitted::detail {
namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
    char line[256];
    std::snprintf(line, sizeof line, pattern, a, b, c);
    return line;
}

} // namespace

Color ramp(double s) {
    static const std::array<Color, 5> stops = {Color(0.05, 0.05, 0.45), Color(0.0, 0.55, 0.9), Color(0.0, 0.8, 0.0),
                                               Color(1.0, 0.9, 0.0), Color(1.0, 0.0, 0.0)};
    s = std::clamp(s, 0.0, 1.0) * (stops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(s), stops.size() - 2);
    return stops[i] + (stops[i + 1] - stops[i]) * (s - static_cast<double>(i));
}

std::string finish_pass(Pass pass, Image& image) {
    std::vector<Color>& pixels = image.pixels;
    const double n = static_cast<double>(std::max<std::size_t>(1, pixels.size()));
    if (pass == Pass::depth) {
        double near = kInfinity, far = 0.0;
        for (const Color& c : pixels)
            if (c.y > 0.0) near = std::min(near, c.x), far = std::max(far, c.x);
        for (Color& c : pixels) {
            if (c.y == 0.0) continue;
            const double s = far > near ? (c.x - near) / (far - near) : 0.0;
            c = Color(1.0 - 0.85 * s);
        }
        return near <= far ? format("distances from %.4g (white) to %.4g (dark grey)", near, far)
                           : "the eye rays hit nothing";
    }
    if (pass == Pass::cost) {
        double most = 0.0, sum = 0.0;
        for (const Color& c : pixels) most = std::max(most, c.x), sum += c.x;
        for (Color& c : pixels) c = ramp(most > 0.0 ? std::log1p(c.x) / std::log1p(most) : 0.0);
        return format("intersection tests per pixel: %.1f on average, %.0f at most", sum / n, most);
    }
    if (pass == Pass::shadow) {
        double none = 0.0, some = 0.0, all = 0.0;
        for (const Color& c : pixels) {
            if (c == kNotApplicable || c == kShadowBackground) continue;
            (c.x == 0.0 ? none : c.x == 1.0 ? all : some) += 1.0;
        }
        // (Whether a dark pixel is acne is not read from the picture: a soft shadow's penumbra is speckled
        // too. render_pass() asks each feeler what stopped it: hits_its_own_surface(), whitted/ray_tree.hpp.)
        if (none + some + all == 0.0) return "no point the eye rays hit has a light in front of it";
        const double lit_from_front = none + some + all;
        return format("of the points with a light in front: %.1f %% see every such light, %.1f %% some, %.1f %% none",
                      100.0 * all / lit_from_front, 100.0 * some / lit_from_front, 100.0 * none / lit_from_front);
    }
    return {};
}

} // namespace whitted::detail
