#include "closest_name.hpp"

#include <algorithm>

namespace whitted {

// The optimal string alignment distance: Levenshtein's, plus the swap of two
// neighbouring letters as one edit ("lbas" is one edit from "labs").
std::size_t edit_distance(std::string_view a, std::string_view b) {
    const std::size_t columns = b.size() + 1;
    // Three rows of the table: two rows back (for swaps), the last one and the current one.
    std::vector<std::size_t> before(columns), last(columns), row(columns);
    for (std::size_t j = 0; j < columns; ++j) last[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j < columns; ++j) {
            const std::size_t replace = last[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            row[j] = std::min({last[j] + 1, row[j - 1] + 1, replace});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], before[j - 2] + 1);
        }
        std::swap(before, last);
        std::swap(last, row);
    }
    return last[b.size()];
}

std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& names) {
    const std::size_t allowed = std::max<std::size_t>(1, given.size() / 3);
    std::optional<std::string> best;
    std::size_t best_distance = allowed + 1;
    for (const std::string& name : names) {
        const std::size_t distance = edit_distance(given, name);
        if (distance < best_distance) {
            best = name;
            best_distance = distance;
        }
    }
    if (best) return best;
    // A name cut short ("--out" for "--output"): the one name it begins, when it is one and three letters or more.
    const std::size_t letters = given.size() - std::min(given.find_first_not_of('-'), given.size());
    if (letters < 3) return std::nullopt;
    for (const std::string& name : names) {
        if (!name.starts_with(given)) continue;
        if (best) return std::nullopt; // the beginning of two names
        best = name;
    }
    return best;
}

} // namespace whitted
