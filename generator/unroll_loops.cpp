#include "arealight/unroll_loops.hpp"

#include <spirv-tools/optimizer.hpp>
#include <string>

#include "arealight/spirv_instructions.hpp"
#include "spirv_tools_severity.hpp"

namespace arealight {
namespace {

constexpr uint32_t kOpLoopMerge = 246;  // SPIR-V spec 3.42.17
// Loop Control mask bits (SPIR-V spec 3.23).
constexpr uint32_t kLoopUnroll = 0x1, kLoopDontUnroll = 0x2;
// spirv-opt's target environment when --target-env is not given (its --help: spv1.5).
constexpr spv_target_env kSpirvOptDefaultEnv = SPV_ENV_UNIVERSAL_1_5;

// Calls f(word index of the instruction) for each OpLoopMerge.
template <typename F>
void for_each_loop_merge(const std::vector<uint32_t>& spirv, F&& f) {
    // Operands: merge block, continue target, loop control.
    for_each_spirv_instruction(spirv, [&](std::size_t at, uint32_t words, uint32_t op) {
        if (op == kOpLoopMerge && words >= 4) f(at);
    });
}

}  // namespace

std::size_t spirv_loop_count(const std::vector<uint32_t>& spirv) {
    std::size_t n = 0;
    for_each_loop_merge(spirv, [&](std::size_t) { ++n; });
    return n;
}

std::vector<uint32_t> mark_loops_unroll(std::vector<uint32_t> spirv) {
    std::vector<std::size_t> merges;
    for_each_loop_merge(spirv, [&](std::size_t at) { merges.push_back(at); });
    for (std::size_t at : merges) spirv[at + 3] = (spirv[at + 3] | kLoopUnroll) & ~kLoopDontUnroll;
    return spirv;
}

std::optional<std::vector<uint32_t>> unroll_constant_loops(const std::vector<uint32_t>& spirv,
                                                           const DiagnosticConsumer& diag) {
    const std::vector<uint32_t> marked = mark_loops_unroll(spirv);
    bool failed = false;
    spvtools::Optimizer optimizer(kSpirvOptDefaultEnv);
    optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*,
                                     const spv_position_t& position, const char* message) {
        const Severity s = severity_of(level);
        failed = failed || s == Severity::Error;
        std::string text =
            std::string("unroll (spirv-opt --loop-unroll -O): ") + (message ? message : "");
        if (position.index != 0) text += " (word " + std::to_string(position.index) + ")";
        if (diag) diag({s, "", 0, std::move(text)});
    });
    // Flag order is pass order on spirv-opt's command line: the unroller first.
    optimizer.RegisterPass(spvtools::CreateLoopUnrollPass(true));
    optimizer.RegisterPerformancePasses();
    std::vector<uint32_t> out;
    if (!optimizer.Run(marked.data(), marked.size(), &out) || failed) {
        if (diag) diag({Severity::Error, "", 0, "unroll: spirv-opt's passes rejected the module"});
        return std::nullopt;
    }
    return out;
}

}  // namespace arealight
