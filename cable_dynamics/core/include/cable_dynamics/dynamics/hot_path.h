#pragma once
/// \file
/// \brief CABLE_HOT_PATH: runtime dispatch of the few functions every evaluation runs.
///
/// With GCC on x86-64 a function marked CABLE_HOT_PATH is compiled three times: for the baseline x86-64
/// the package is built for (SSE2: two doubles per vector instruction), for x86-64-v3 (AVX2 and FMA:
/// four doubles, three-operand and fused multiply-add instructions) and for x86-64-v4 (AVX-512: eight
/// doubles, and 32 vector registers instead of 16, so the recursion's serial loop keeps its values in
/// registers instead of spilling them). The loops over a block's eight links (link_block.h) take one
/// instruction per quantity in the v4 copy. The loader picks the best copy the processor runs (an ifunc,
/// as glibc's libm does for its own functions). Elsewhere, or with -DCABLE_DYNAMICS_NO_CLONES, it is
/// an ordinary function.
/// The versions round differently (a fused multiply-add rounds once), by ~1e-16 relative per
/// operation: results agree across processors to round-off, not bit for bit.

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(CABLE_DYNAMICS_NO_CLONES)
#define CABLE_HOT_PATH __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define CABLE_HOT_PATH
#endif
