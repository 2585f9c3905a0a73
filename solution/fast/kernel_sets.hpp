// The reference renderer's leaf kernels come in two builds of the same
// arithmetic: plain (any x86-64 or other CPU) and AVX (four spheres or four
// triangles per instruction). linked_leaf_kernels() picks the best one this
// CPU runs; tests ask for every one, to prove they all answer alike.
#pragma once

#include "whitted/leaf_kernels.hpp"

#include <vector>

namespace whitted {

struct NamedLeafKernels {
    const char* name;
    const LeafKernels* kernels;
};

/// The plain kernels: one primitive at a time.
const LeafKernels* plain_leaf_kernels();

/// The AVX kernels, or nullptr where the build has none; call only when the CPU has AVX.
const LeafKernels* avx_leaf_kernels();

/// Every kernel set this build has and this CPU can run, plain first.
std::vector<NamedLeafKernels> runnable_leaf_kernels();

} // namespace whitted
