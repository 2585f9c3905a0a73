#pragma once
// A function's result built where it is kept, with no copy.
//
// Why: g++ 12 writes a returned struct (a Hit, a Ray) with 8-byte or narrower
// stores, and copies it with 16-byte loads. A load that spans two stores not
// yet in the cache waits until both are written (a store-forwarding stall),
// and on the renderer's paths that happens once a ray. A function's result
// initialises its destination in place only when it initialises it:
// `optional.emplace(f())` and `x = f()` build it aside and copy it. Handing
// emplace() a ResultOf{f} instead lets the value be initialised from
// ResultOf's conversion, whose result g++ builds straight in the optional's
// storage (checked in the disassembly; any compiler gives the same value).
#include <type_traits>

namespace whitted {

/// Converts to make()'s result: `opt.emplace(ResultOf{[&] { return f(x); }})`.
template <class Make>
struct ResultOf {
    Make make;
    operator std::invoke_result_t<Make&>() { return make(); }
};
template <class Make>
ResultOf(Make) -> ResultOf<Make>;

} // namespace whitted
