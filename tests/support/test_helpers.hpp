// Small helpers shared by the framework tests: rays with unit directions and vector comparisons.
#pragma once

#include "whitted/ray.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace whitted::testing_helpers {

/// A ray from origin along direction, normalised as every ray of the framework is.
inline Ray make_ray(const Point3& origin, const Vec3& direction) { return Ray{origin, glm::normalize(direction)}; }

/// Passes when every component of actual is a finite number within tolerance of expected; prints both otherwise.
/// (A NaN or infinite component never passes, whichever component it is in.)
inline ::testing::AssertionResult near(const Vec3& actual, const Vec3& expected, double tolerance = 1e-12) {
    if (is_finite(actual) && is_finite(expected) && max_abs_component(actual - expected) <= tolerance)
        return ::testing::AssertionSuccess();
    std::ostringstream out;
    out.precision(17);
    out << "got (" << actual.x << ", " << actual.y << ", " << actual.z << "), expected (" << expected.x << ", "
        << expected.y << ", " << expected.z << ") within " << tolerance;
    if (!is_finite(actual)) out << ": NaN or infinity where a finite number was expected";
    return ::testing::AssertionFailure() << out.str();
}

} // namespace whitted::testing_helpers
