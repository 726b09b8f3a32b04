// Diagnostics collected as text for a failing check's message, and GLSL compiled for a
// test (a compile error fails the test with the compiler's messages).
#pragma once

#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "arealight/diagnostics.hpp"

namespace arealight::test {

struct Collected {
    std::string text;  // "severity: message" lines
    int lines = 0;
    DiagnosticConsumer consumer() {
        return [this](const Diagnostic& d) {
            text += std::string(to_string(d.severity)) + ": " + d.message + "\n";
            ++lines;
        };
    }
};

inline std::vector<uint32_t> compile(const char* source, const char* name) {
    Collected diag;
    auto spirv = compile_shader(source, name, CompileOptions{}, diag.consumer());
    INFO(diag.text);
    REQUIRE(spirv);
    return *spirv;
}

}  // namespace arealight::test
