// Asking the kernel for a big block's pages in one call instead of one fault each.
//
// Why: a scene of half a million primitives writes to ~150 MB of fresh memory
// while it loads, and each 4 KiB page costs a page fault the first time it is
// written, which is over a microsecond on a virtual machine: tens of
// milliseconds in all. Linux can map the pages of a range at once
// (MADV_POPULATE_WRITE, Linux 5.14); elsewhere, or when the kernel says no,
// this does nothing and the pages fault in as they are written.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <future>
#include <system_error>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace whitted::detail {

/// Maps in the whole pages inside [begin, begin + bytes), for blocks of a megabyte or more.
inline void prefault(void* begin, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    constexpr std::size_t kPage = 4096;
    if (bytes < (std::size_t{1} << 20)) return;
    const auto first = (reinterpret_cast<std::uintptr_t>(begin) + kPage - 1) & ~(kPage - 1);
    const auto last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) & ~(kPage - 1);
    if (last > first) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
#else
    (void)begin;
    (void)bytes;
#endif
}

/// prefault() on another thread, while this one goes on writing from the front;
/// the block must outlive the returned future (declare it after the block's owner, and
/// wait for it before the block can move).
inline std::future<void> prefault_behind(void* begin, std::size_t bytes) {
    if (bytes < (std::size_t{1} << 20)) return {};
    try {
        return std::async(std::launch::async, [begin, bytes] { prefault(begin, bytes); });
    } catch (const std::system_error&) {
        return {}; // no thread to be had: the pages fault in as they are written
    }
}

/// prefault_behind() for a block of at most `most` bytes whose size takes work to
/// find: `bytes()` finds it on the other thread too, off this one's path (what it
/// reads must outlive the returned future, as the block must).
template <class Bytes>
std::future<void> prefault_behind(void* begin, std::size_t most, Bytes bytes) {
    if (most < (std::size_t{1} << 20)) return {};
    try {
        return std::async(std::launch::async, [begin, most, bytes] { prefault(begin, std::min(most, bytes())); });
    } catch (const std::system_error&) {
        return {};
    }
}

} // namespace whitted::detail
