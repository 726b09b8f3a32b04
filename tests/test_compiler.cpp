// compile_glsl: glslang + SPIRV-Tools in process, diagnostics with file and line.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"

using namespace arealight;

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
    const auto unoptimized = compile_glsl(kValidShader, "valid.comp", plain, diag.consumer());
    const auto optimized =
        compile_glsl(kValidShader, "valid.comp", CompileOptions{}, diag.consumer());
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
            const auto spirv = compile_glsl(kValidShader, "valid.comp", options, diag.consumer());
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
    const auto spirv = compile_glsl(source, "generated.comp", CompileOptions{}, diag.consumer());
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
    CHECK_FALSE(compile_glsl(source, "inline.comp", CompileOptions{}, diag.consumer()));
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
    CHECK_FALSE(compile_glsl(source, "nomain.comp", CompileOptions{}, diag.consumer()));
    INFO(diag.text());
    CHECK(diag.errors() >= 1);
}

TEST_CASE("an empty consumer drops diagnostics without failing differently", "[compiler]") {
    CHECK(compile_glsl(kValidShader, "valid.comp", CompileOptions{}, DiagnosticConsumer{}));
    CHECK_FALSE(compile_glsl("#version 450\nsyntax error here\n", "bad.comp", CompileOptions{},
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
