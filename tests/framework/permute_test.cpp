// Moving items into a new order where they stand: the result must be what a
// copy into a new array gives, items[k] = old items[from[k]], for permutations
// of every shape (the identity, one long cycle, many short ones, fixed points).
#include "permute.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using whitted::detail::permute_in_place;

namespace {

// Permutes strings "0", "1"... by `from` in place and checks them against the copy.
// Strings, not numbers: a string moved from is left empty, so a move made twice,
// or from the wrong place, shows.
void expect_permuted(const std::vector<std::uint32_t>& from, const std::string& what) {
    std::vector<std::string> items(from.size());
    for (std::size_t i = 0; i < items.size(); ++i) items[i] = std::to_string(i);
    permute_in_place(std::span<std::string>(items), from);
    for (std::size_t k = 0; k < items.size(); ++k)
        ASSERT_EQ(items[k], std::to_string(from[k])) << what << ", position " << k << " of " << items.size();
}

std::vector<std::uint32_t> identity(std::size_t count) {
    std::vector<std::uint32_t> from(count);
    std::iota(from.begin(), from.end(), 0u);
    return from;
}

TEST(PermuteInPlace, EmptyAndOneItem) {
    expect_permuted({}, "empty");
    expect_permuted({0}, "one item");
}

TEST(PermuteInPlace, TheIdentityMovesNothing) { expect_permuted(identity(1000), "identity"); }

TEST(PermuteInPlace, OneCycleThroughEveryItem) {
    for (const std::size_t count : {2u, 3u, 17u, 5000u}) {
        std::vector<std::uint32_t> from = identity(count);
        std::rotate(from.begin(), from.begin() + 1, from.end()); // k takes k + 1's item
        expect_permuted(from, "rotation by one");
        std::rotate(from.begin(), from.end() - 2, from.end()); // k takes k - 1's item
        expect_permuted(from, "rotation back by one");
    }
}

TEST(PermuteInPlace, SwapsOfNeighboursBesideFixedPoints) {
    std::vector<std::uint32_t> from = identity(1001); // the last one stays
    for (std::size_t k = 0; k + 1 < from.size(); k += 3) std::swap(from[k], from[k + 1]); // every third one stays too
    expect_permuted(from, "swaps");
}

TEST(PermuteInPlace, RandomPermutationsOfManySizes) {
    std::mt19937 rng(20261127);
    for (const std::size_t count : {2u, 5u, 16u, 17u, 100u, 4099u, 200'000u}) {
        for (int round = 0; round < 3; ++round) {
            std::vector<std::uint32_t> from = identity(count);
            std::shuffle(from.begin(), from.end(), rng);
            expect_permuted(from, "random permutation of " + std::to_string(count) + ", round " + std::to_string(round));
        }
    }
}

} // namespace
