// `arealight fit-ltc`: fits a distribution's LTC table (fit/, include/arealight/ltc_table.hpp)
// and writes it atomically. Its options are in cli/main.cpp, which calls run_fit_ltc.
#pragma once

#include <string>

namespace arealight::cli {

struct FitLtcArgs {
    std::string dist;
    int size = 64;
    unsigned threads = 0;  // 0: hardware concurrency
    std::string out;
};

// Exit codes as cli/main.cpp: 0 ok, 3 fit or write failure (usage errors are CLI11's, 2).
int run_fit_ltc(const FitLtcArgs& args);

}  // namespace arealight::cli
