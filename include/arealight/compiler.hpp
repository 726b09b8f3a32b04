// GLSL or HLSL shader (any graphics or compute stage) -> validated (and optionally optimized)
// SPIR-V for a Vulkan version, in process, with `#include` resolved from the file system when
// asked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight {

enum class ShaderStage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };
enum class SourceLanguage { Glsl, Hlsl };
// The Vulkan version the SPIR-V is for, and with it the SPIR-V version (1.0, 1.3, 1.5, 1.6).
enum class TargetEnv { Vulkan1_0, Vulkan1_1, Vulkan1_2, Vulkan1_3 };

// The stage glslc infers from a file name's last extension: .vert .tesc .tese .geom .frag
// .comp; nullopt for any other.
std::optional<ShaderStage> stage_from_path(const std::string& path);
// The extension without its dot ("comp"), as stage_from_path reads it.
const char* to_string(ShaderStage stage);
// .hlsl -> Hlsl; any other name -> Glsl.
SourceLanguage language_from_path(const std::string& path);
// "vulkan1.0" .. "vulkan1.3"; nullopt for any other.
std::optional<TargetEnv> target_env_from_string(const std::string& name);
const char* to_string(TargetEnv env);

struct CompileOptions {
    bool optimize = true;        // spvtools::Optimizer::RegisterPerformancePasses
    std::string entry = "main";  // SPIR-V entry point name; the GLSL function stays main()
    ShaderStage stage = ShaderStage::Compute;
    SourceLanguage language = SourceLanguage::Glsl;
    // HLSL: the function the stage starts at (glslc's -fentry-point, dxc's -E); empty: `entry`.
    // GLSL's is always main().
    std::string source_entry;
    TargetEnv target_env = TargetEnv::Vulkan1_1;
    // `#include "name"` and `#include <name>` (GL_GOOGLE_include_directive, enabled without an
    // #extension line, which also enables `#line N "file"`). Off for the generated kernels,
    // which include nothing (enabling it adds an OpSourceExtension). "name" is searched in the
    // including file's folder (the folder of `source_name` for the top file), then in each of
    // `include_dirs` in order; <name> only in `include_dirs`. Errors in an included file
    // name that file and its line.
    bool includes = false;
    std::vector<std::string> include_dirs;
};

// Compiles one shader for options.target_env (Vulkan 1.1 / SPIR-V 1.3 by default) and validates
// the result (again after optimizing; HLSL after SPIRV-Tools' legalization passes, which
// glslang's HLSL output needs). `source_name` names the text in diagnostics until a `#line N "file"` directive
// (GL_GOOGLE_cpp_style_line_directive) renames it. Every compiler and validator message goes to
// `diag`; on any error returns nullopt. When `included_files` is given it receives the path of
// every file an #include read, once each, in first-read order (a build's dependencies), also
// on failure. Safe to call from several threads at once.
std::optional<std::vector<uint32_t>> compile_shader(const std::string& source,
                                                  const std::string& source_name,
                                                  const CompileOptions& options,
                                                  const DiagnosticConsumer& diag,
                                                  std::vector<std::string>* included_files = nullptr);

// Number of instructions after the 5-word header; stops at the first malformed word count.
std::size_t spirv_instruction_count(const std::vector<uint32_t>& spirv);
// Image reads (sample, fetch, gather; SPIR-V 3.37.10) in a module: texture fetches per
// shading point of a shader whose reads sit outside loops (the LTC tables).
std::size_t spirv_texture_sample_count(const std::vector<uint32_t>& spirv);

// SPIRV-Tools assembly text with friendly names; empty when the binary cannot be parsed.
std::string disassemble(const std::vector<uint32_t>& spirv);

}  // namespace arealight
