// The loop-exact module of a kernel: every loop asked to unroll, then SPIRV-Tools'
// full unroller and its performance passes, so that a compiler whose cost model
// counts each loop as a fixed number of iterations (ACO: 8) sees every loop of
// compile-time trip count at its true length. In process, it gives the same words as
// `spirv-opt --loop-unroll -O` on the module mark_loops_unroll returns.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight {

// OpLoopMerge instructions in a module; stops at the first malformed word count.
std::size_t spirv_loop_count(const std::vector<uint32_t>& spirv);

// The module with every OpLoopMerge's loop control set to Unroll and DontUnroll
// cleared (other controls and their operands kept).
std::vector<uint32_t> mark_loops_unroll(std::vector<uint32_t> spirv);

// mark_loops_unroll, then the full loop unroller and the performance passes in the
// order spirv-opt's command line runs them for `--loop-unroll -O`, with its default
// target environment and validation; loops whose trip count is not a compile-time
// constant stay. nullopt, with SPIRV-Tools' messages, when the module is rejected.
std::optional<std::vector<uint32_t>> unroll_constant_loops(const std::vector<uint32_t>& spirv,
                                                           const DiagnosticConsumer& diag);

}  // namespace arealight
