// Walking a SPIR-V module word by word (SPIR-V spec 2.3: a five-word header, then
// instructions whose first word holds the word count in its high 16 bits and the
// opcode in its low 16), for the few passes that read a module without SPIRV-Tools.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace arealight {

constexpr std::size_t kSpirvHeaderWords = 5;

// Calls f(at, words, opcode) for each instruction after the header, `at` being the
// index of its first word. Returns the index of the first malformed instruction (a
// word count of 0 or one running past the end), where the walk stopped, or the
// module's size when every instruction is well formed.
template <typename F>
std::size_t for_each_spirv_instruction(const std::vector<uint32_t>& spirv, F&& f) {
    std::size_t at = kSpirvHeaderWords;
    while (at < spirv.size()) {
        const uint32_t words = spirv[at] >> 16;
        if (words == 0 || at + words > spirv.size()) return at;
        f(at, words, spirv[at] & 0xffffu);
        at += words;
    }
    return spirv.size();
}

}  // namespace arealight
