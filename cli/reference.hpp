// `arealight reference`: the oracle's values of every case of a file (adaptive cubature,
// reference/), with a summary of its effort on stdout. Its options are in cli/main.cpp,
// which calls run_reference.
#pragma once

#include <string>

namespace arealight::cli {

struct ReferenceArgs {
    std::string cases, out;
    double rel_tol = 1e-10;  // requested relative accuracy
    unsigned threads = 1;
    bool table = false;  // also every case's values on stdout
};

// Exit codes as cli/main.cpp: 0 ok, 1 malformed cases, 3 a write failure.
int run_reference(const ReferenceArgs& args);

}  // namespace arealight::cli
