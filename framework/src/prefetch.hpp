// Asking for memory a little before it is read: a hint, which changes only the time.
#pragma once

namespace whitted::detail {

/// Asks for the cache line that holds `address`, to be read soon; nothing where the compiler has no such hint.
inline void prefetch(const void* address) {
#if defined(__GNUC__) || defined(__clang__)
    __builtin_prefetch(address);
#else
    (void)address;
#endif
}

} // namespace whitted::detail
