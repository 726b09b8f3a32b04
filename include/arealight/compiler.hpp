// GLSL compute shader -> validated (and optionally optimized) SPIR-V, in process.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight {

struct CompileOptions {
    bool optimize = true;        // spvtools::Optimizer::RegisterPerformancePasses
    std::string entry = "main";  // SPIR-V entry point name; the GLSL function stays main()
};

// Compiles one compute shader for Vulkan 1.1 / SPIR-V 1.3 and validates the result (again after
// optimizing). `source_name` names the text in diagnostics until a `#line N "file"` directive
// (GL_GOOGLE_cpp_style_line_directive) renames it. Every compiler and validator message goes to
// `diag`; on any error returns nullopt. Safe to call from several threads at once.
std::optional<std::vector<uint32_t>> compile_glsl(const std::string& source,
                                                  const std::string& source_name,
                                                  const CompileOptions& options,
                                                  const DiagnosticConsumer& diag);

// Number of instructions after the 5-word header; stops at the first malformed word count.
std::size_t spirv_instruction_count(const std::vector<uint32_t>& spirv);
// Image reads (sample, fetch, gather; SPIR-V 3.37.10) in a module: texture fetches per
// shading point of a shader whose reads sit outside loops (the LTC tables).
std::size_t spirv_texture_sample_count(const std::vector<uint32_t>& spirv);

// SPIRV-Tools assembly text with friendly names; empty when the binary cannot be parsed.
std::string disassemble(const std::vector<uint32_t>& spirv);

}  // namespace arealight
