#include "whitted/sampling.hpp"

namespace whitted {

namespace {

/// A 64-bit mixing function (the finaliser of the SplitMix64 generator): every
/// input bit changes about half the output bits.
constexpr std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/// The top 53 bits as a double in [0, 1).
constexpr double unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

} // namespace

Vec2 sample_numbers(const PixelSample& sample, SampleUse use, std::uint32_t n) {
    // One key from every field (each hashed in turn), then two numbers from it.
    std::uint64_t key = mix(static_cast<std::uint32_t>(sample.x) + 0x9e3779b97f4a7c15ULL);
    key = mix(key ^ static_cast<std::uint32_t>(sample.y));
    key = mix(key ^ static_cast<std::uint32_t>(sample.index));
    key = mix(key ^ (static_cast<std::uint64_t>(use) << 32 | n));
    return Vec2(unit(mix(key ^ 1)), unit(mix(key ^ 2)));
}

} // namespace whitted
