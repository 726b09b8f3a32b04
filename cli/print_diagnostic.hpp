// How the subcommands print library diagnostics on stderr: "arealight: SEVERITY: message".
// Messages already name their file (and line), so they are printed verbatim. `arealight
// compile` prints compiler positions gcc-style instead (cli/compile.cpp).
#pragma once

#include <cstdio>

#include "arealight/diagnostics.hpp"

namespace arealight::cli {

inline void print_diagnostic(const Diagnostic& d) {
    std::fprintf(stderr, "arealight: %s: %s\n", to_string(d.severity), d.message.c_str());
}

}  // namespace arealight::cli
