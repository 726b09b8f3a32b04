// compile_shader: glslang + SPIRV-Tools in process, diagnostics with file and line.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "scratch_folder.hpp"

using namespace arealight;
using arealight::test::ScratchFolder;

namespace {

const char* const kValidShader = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer In { float in_values[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Out { float out_values[]; };
layout(push_constant) uniform Push { uint count; uint base; } pc;

float twice(float x) { return x + x; }

void main() {
    uint i = pc.base + gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    float unused = in_values[i] * 3.0;
    out_values[i] = twice(in_values[i]);
}
)";

struct Collected {
    std::vector<Diagnostic> all;
    DiagnosticConsumer consumer() {
        return [this](const Diagnostic& d) { all.push_back(d); };
    }
    std::string text() const {
        std::string s;
        for (const auto& d : all) {
            s += std::string(to_string(d.severity)) + " " + d.file + ":" + std::to_string(d.line) +
                 ": " + d.message + "\n";
        }
        return s;
    }
    int errors() const {
        int n = 0;
        for (const auto& d : all) n += d.severity == Severity::Error;
        return n;
    }
};

}  // namespace

TEST_CASE("a valid compute shader compiles, validates and optimizes", "[compiler]") {
    Collected diag;
    CompileOptions plain;
    plain.optimize = false;
    const auto unoptimized = compile_shader(kValidShader, "valid.comp", plain, diag.consumer());
    const auto optimized =
        compile_shader(kValidShader, "valid.comp", CompileOptions{}, diag.consumer());
    INFO(diag.text());
    REQUIRE(unoptimized);
    REQUIRE(optimized);
    CHECK(diag.errors() == 0);
    CHECK((*optimized)[0] == 0x07230203u);  // SPIR-V magic
    const std::size_t before = spirv_instruction_count(*unoptimized);
    const std::size_t after = spirv_instruction_count(*optimized);
    INFO("instructions: unoptimized " << before << ", optimized " << after);
    CHECK(after > 0);
    CHECK(after <= before);

    const std::string text = disassemble(*optimized);
    CHECK(text.find("OpEntryPoint GLCompute") != std::string::npos);
    CHECK(text.find("LocalSize") != std::string::npos);
}

TEST_CASE("CompileOptions::entry names the SPIR-V entry point", "[compiler]") {
    // Lengths 3, 4 and 16 cover every padding of the nul-terminated literal.
    for (const char* name : {"cs1", "csmn", "shade_area_light"}) {
        for (const bool optimize : {false, true}) {
            CompileOptions options;
            options.entry = name;
            options.optimize = optimize;
            Collected diag;
            const auto spirv = compile_shader(kValidShader, "valid.comp", options, diag.consumer());
            INFO(name << (optimize ? " optimized" : "") << "\n" << diag.text());
            REQUIRE(spirv);
            const std::string text = disassemble(*spirv);
            INFO(text);
            CHECK(text.find("OpEntryPoint GLCompute %main \"" + std::string(name) + "\"") !=
                  std::string::npos);
        }
    }
}

TEST_CASE("an error after #line is reported at the template file and line", "[compiler]") {
    const std::string source =
        "#version 450\n"
        "#extension GL_GOOGLE_cpp_style_line_directive : enable\n"
        "layout(local_size_x = 64) in;\n"
        "#line 7 \"templates/broken.glsl\"\n"
        "float broken() { return undeclared_thing; }\n"  // line 7 of templates/broken.glsl
        "#line 6 \"generated.comp\"\n"
        "void main() { broken(); }\n";
    Collected diag;
    const auto spirv = compile_shader(source, "generated.comp", CompileOptions{}, diag.consumer());
    INFO(diag.text());
    CHECK_FALSE(spirv);
    REQUIRE(diag.errors() >= 1);
    const Diagnostic& first = diag.all.front();
    CHECK(first.severity == Severity::Error);
    CHECK(first.file == "templates/broken.glsl");
    CHECK(first.line == 7);
    CHECK(first.message.find("undeclared_thing") != std::string::npos);
    for (const auto& d : diag.all) CHECK(d.message.find("No code generated") == std::string::npos);
}

TEST_CASE("without #line, errors name the source and its line", "[compiler]") {
    const std::string source =
        "#version 450\n"
        "layout(local_size_x = 64) in;\n"
        "void main() { int x = vec2(1.0); }\n";
    Collected diag;
    CHECK_FALSE(compile_shader(source, "inline.comp", CompileOptions{}, diag.consumer()));
    INFO(diag.text());
    REQUIRE(diag.errors() >= 1);
    CHECK(diag.all.front().file == "inline.comp");
    CHECK(diag.all.front().line == 3);
}

TEST_CASE("a link error (no entry point) fails with an error diagnostic", "[compiler]") {
    const std::string source =
        "#version 450\n"
        "layout(local_size_x = 64) in;\n"
        "void not_main() {}\n";
    Collected diag;
    CHECK_FALSE(compile_shader(source, "nomain.comp", CompileOptions{}, diag.consumer()));
    INFO(diag.text());
    CHECK(diag.errors() >= 1);
}

namespace {

const char* const kIncludingShader = R"(#version 450
layout(local_size_x = 1) in;
#include "included.glsl"
layout(std430, binding = 0) buffer B { float v[]; };
void main() { v[0] = twice(v[0]); }
)";

// kIncludingShader compiled as src/main.comp of `dir`, with `dir`/lib as the include folder.
struct IncludeRun {
    bool compiled = false;
    std::string shader;  // the path it was compiled as
    Collected diag;
    std::vector<std::string> included;
};
IncludeRun compile_including(const ScratchFolder& dir, bool includes = true) {
    IncludeRun run;
    run.shader = dir.write("src/main.comp", kIncludingShader);
    CompileOptions options;
    options.includes = includes;
    options.include_dirs = {dir / "lib"};
    run.compiled = compile_shader(kIncludingShader, run.shader, options, run.diag.consumer(),
                                &run.included)
                       .has_value();
    return run;
}

}  // namespace

TEST_CASE("#include is found in an include folder without an #extension line", "[compiler]") {
    ScratchFolder dir("include_ok");
    const std::string lib = dir.write("lib/included.glsl",
                                      "#ifndef INCLUDED\n#define INCLUDED\n"
                                      "float twice(float x) { return x + x; }\n#endif\n");
    const IncludeRun run = compile_including(dir);
    INFO(run.diag.text());
    CHECK(run.compiled);
    CHECK(run.diag.errors() == 0);
    CHECK(run.included == std::vector<std::string>{lib});
}

TEST_CASE("an error in an included file names that file and its line", "[compiler]") {
    ScratchFolder dir("include_error");
    dir.write("lib/included.glsl",
              "// line 1\n\nfloat twice(float x) { return undeclared_thing * x; }\n");
    const IncludeRun run = compile_including(dir);
    INFO(run.diag.text());
    CHECK_FALSE(run.compiled);
    REQUIRE(run.diag.errors() >= 1);
    const Diagnostic& first = run.diag.all.front();
    CHECK(first.file == dir / "lib/included.glsl");
    CHECK(first.line == 3);
    CHECK(first.message.find("undeclared_thing") != std::string::npos);
}

TEST_CASE("a missing include names the header and the folders searched", "[compiler]") {
    ScratchFolder dir("include_missing");
    const IncludeRun run = compile_including(dir);
    INFO(run.diag.text());
    CHECK_FALSE(run.compiled);
    REQUIRE(run.diag.errors() >= 1);
    const Diagnostic& first = run.diag.all.front();
    CHECK(first.file == run.shader);
    CHECK(first.line == 3);
    CHECK(first.message.find("included.glsl") != std::string::npos);
    CHECK(first.message.find(dir / "src") != std::string::npos);
    CHECK(first.message.find(dir / "lib") != std::string::npos);
}

TEST_CASE("a quoted include prefers the including file's folder", "[compiler]") {
    ScratchFolder dir("include_order");
    const std::string near =
        dir.write("src/included.glsl", "float twice(float x) { return 2.0 * x; }\n");
    dir.write("lib/included.glsl", "this would not compile\n");
    const IncludeRun run = compile_including(dir);
    INFO(run.diag.text());
    CHECK(run.compiled);
    CHECK(run.included == std::vector<std::string>{near});
}

TEST_CASE("without CompileOptions::includes, #include is an error", "[compiler]") {
    ScratchFolder dir("include_off");
    dir.write("src/included.glsl", "float twice(float x) { return 2.0 * x; }\n");
    const IncludeRun run = compile_including(dir, false);
    CHECK_FALSE(run.compiled);
    CHECK(run.diag.errors() >= 1);
}

TEST_CASE("the stage comes from the extension and reaches the entry point", "[compiler]") {
    CHECK(stage_from_path("a/b.frag") == ShaderStage::Fragment);
    CHECK(stage_from_path("x.vert") == ShaderStage::Vertex);
    CHECK(stage_from_path("x.tesc") == ShaderStage::TessControl);
    CHECK(stage_from_path("x.tese") == ShaderStage::TessEvaluation);
    CHECK(stage_from_path("x.geom") == ShaderStage::Geometry);
    CHECK(stage_from_path("dir.comp/x.comp") == ShaderStage::Compute);
    CHECK_FALSE(stage_from_path("x.glsl"));
    CHECK_FALSE(stage_from_path("dir.frag/x"));

    const std::string fragment =
        "#version 450\nlayout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n";
    CompileOptions options;
    options.stage = ShaderStage::Fragment;
    Collected diag;
    const auto spirv = compile_shader(fragment, "x.frag", options, diag.consumer());
    INFO(diag.text());
    REQUIRE(spirv);
    // OpEntryPoint (opcode 15): its first operand is the execution model, Fragment = 4.
    constexpr uint32_t kOpEntryPoint = 15, kExecutionModelFragment = 4;
    uint32_t model = ~0u;
    for (std::size_t at = 5; at < spirv->size(); at += (*spirv)[at] >> 16) {
        if (((*spirv)[at] & 0xffffu) == kOpEntryPoint) model = (*spirv)[at + 1];
        if (((*spirv)[at] >> 16) == 0) break;
    }
    CHECK(model == kExecutionModelFragment);
}

TEST_CASE("an empty consumer drops diagnostics without failing differently", "[compiler]") {
    CHECK(compile_shader(kValidShader, "valid.comp", CompileOptions{}, DiagnosticConsumer{}));
    CHECK_FALSE(compile_shader("#version 450\nsyntax error here\n", "bad.comp", CompileOptions{},
                             DiagnosticConsumer{}));
}

TEST_CASE("spirv_instruction_count tolerates truncated modules", "[compiler]") {
    CHECK(spirv_instruction_count({}) == 0);
    CHECK(spirv_instruction_count({0x07230203u, 0x00010300u, 0, 10, 0}) == 0);
    // OpCapability Shader (2 words) then a word claiming 3 words with only 1 left.
    CHECK(spirv_instruction_count(
              {0x07230203u, 0x00010300u, 0, 10, 0, (2u << 16) | 17u, 1u, (3u << 16) | 17u}) == 1);
    CHECK(disassemble({1, 2, 3}).empty());
}

namespace {

const char* const kHlslShader = R"(RWStructuredBuffer<float> values : register(u0);
float twice(float x) { return x + x; }
[numthreads(64, 1, 1)]
void double_them(uint3 id : SV_DispatchThreadID) { values[id.x] = twice(values[id.x]); }
)";

// The SPIR-V version word of a module: 0x00MMmm00.
std::pair<int, int> spirv_version(const std::vector<uint32_t>& spirv) {
    return {static_cast<int>((spirv[1] >> 16) & 0xffu), static_cast<int>((spirv[1] >> 8) & 0xffu)};
}

}  // namespace

TEST_CASE("HLSL compiles from its entry function, legalised, with or without the optimizer",
          "[compiler][hlsl]") {
    CHECK(language_from_path("dir.hlsl/x.comp") == SourceLanguage::Glsl);
    CHECK(language_from_path("x.comp.hlsl") == SourceLanguage::Hlsl);
    for (const bool optimize : {false, true}) {
        CompileOptions options;
        options.language = SourceLanguage::Hlsl;
        options.source_entry = "double_them";
        options.optimize = optimize;
        Collected diag;
        const auto spirv = compile_shader(kHlslShader, "x.comp.hlsl", options, diag.consumer());
        INFO(diag.text());
        REQUIRE(spirv);
        const std::string text = disassemble(*spirv);
        INFO(text);
        CHECK(text.find("OpEntryPoint GLCompute %main \"main\"") != std::string::npos);
        CHECK(text.find("OpFAdd") != std::string::npos);  // double_them's body, not an empty main
        CHECK(text.find("OpSource HLSL") != std::string::npos);
    }
    // An entry function the file lacks is an error (glslang only warns).
    CompileOptions missing;
    missing.language = SourceLanguage::Hlsl;
    missing.source_entry = "absent";
    Collected diag;
    CHECK_FALSE(compile_shader(kHlslShader, "x.comp.hlsl", missing, diag.consumer()));
    INFO(diag.text());
    CHECK(diag.text().find("no entry function absent") != std::string::npos);
}

TEST_CASE("target environments: each Vulkan version's SPIR-V, validated for it", "[compiler]") {
    CHECK(target_env_from_string("vulkan1.2") == TargetEnv::Vulkan1_2);
    CHECK_FALSE(target_env_from_string("vulkan1.4"));
    CHECK(std::string(to_string(TargetEnv::Vulkan1_3)) == "vulkan1.3");
    const std::pair<TargetEnv, std::pair<int, int>> glsl_versions[] = {
        {TargetEnv::Vulkan1_0, {1, 0}}, {TargetEnv::Vulkan1_1, {1, 3}},
        {TargetEnv::Vulkan1_2, {1, 5}}, {TargetEnv::Vulkan1_3, {1, 6}}};
    for (const auto& [env, version] : glsl_versions) {
        for (const SourceLanguage lang : {SourceLanguage::Glsl, SourceLanguage::Hlsl}) {
            CompileOptions options;
            options.target_env = env;
            options.language = lang;
            options.source_entry = "double_them";
            const bool hlsl = lang == SourceLanguage::Hlsl;
            Collected diag;
            const auto spirv = compile_shader(hlsl ? kHlslShader : kValidShader,
                                              hlsl ? "x.comp.hlsl" : "x.comp", options,
                                              diag.consumer());
            INFO(to_string(env) << (hlsl ? " hlsl\n" : " glsl\n") << diag.text());
            REQUIRE(spirv);
            // HLSL above Vulkan 1.1 stays SPIR-V 1.3 (glslang 12's BufferBlock).
            const std::pair<int, int> want =
                hlsl && env > TargetEnv::Vulkan1_1 ? std::pair<int, int>{1, 3} : version;
            CHECK(spirv_version(*spirv) == want);
        }
    }
}
