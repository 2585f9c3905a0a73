// "Did you mean ...?": the known name closest to a mistyped one.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace whitted {

/// The number of one-letter edits (insert, delete, replace, swap two neighbours) that turn `a` into `b`.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name of `names` nearest to `given`, when it is near enough to be a typing slip
/// (at most one edit for every three letters, and at least one), else the one name that
/// `given` begins ("--out" for "--output", three letters or more); nothing otherwise.
std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& names);

} // namespace whitted
