// A folder of compiled kernels by their source text. The test suite runs hundreds of
// processes over the same variants (ctest starts one per test case, in two build trees),
// and each used to run glslang and SPIRV-Tools again on text an earlier one had compiled:
// with a cache folder, the first compile of a text writes its SPIR-V there and the
// others read it. Each entry keeps the text and the compile's tag beside the words, and a
// read compares both (fnv_hash.hpp: a key alone is not trusted). An entry is as valid as
// the tools that wrote it: the tag names the front end, SPIRV-Tools and the options, not
// arealight's own compile code, so a folder belongs to one build (scripts/test.sh empties
// it at the start of each run).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace arealight {

// "glslang MAJOR.MINOR.PATCH, SPIRV-Tools VERSION": the tools a compile ran, for tags.
std::string compiler_versions();

// The SPIR-V of `source` under `tag` (the compile's language and options, with
// compiler_versions()): read from `dir` when an entry holds exactly this tag and text,
// else compile() and, when it succeeds, written there (atomically: processes share the
// folder). An empty `dir` only compiles. A folder that cannot be read or written only
// costs a compile; no message.
std::optional<std::vector<uint32_t>> cached_compile(
    const std::string& dir, const std::string& tag, const std::string& source,
    const std::function<std::optional<std::vector<uint32_t>>()>& compile);

}  // namespace arealight
