// Moving the items of an array into a new order where they stand.
//
// Why: the scene's primitives (tens of megabytes in a big scene) and the BVH
// builder's boxes must follow the order the builder chose; a second array to copy
// them into would double their memory. Following the permutation's cycles moves
// each item once, with one item set aside per cycle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace whitted::detail {

/// Rearranges `items` so that items[k] becomes what items[from[k]] was (`from` is a permutation of its indices).
template <class T>
void permute_in_place(std::span<T> items, std::span<const std::uint32_t> from) {
    std::vector<bool> placed(items.size());
    for (std::size_t start = 0; start < items.size(); ++start) {
        if (placed[start]) continue;
        T first = std::move(items[start]);
        std::size_t k = start;
        while (from[k] != start) {
            items[k] = std::move(items[from[k]]);
            placed[k] = true;
            k = from[k];
        }
        items[k] = std::move(first);
        placed[k] = true;
    }
}

} // namespace whitted::detail
