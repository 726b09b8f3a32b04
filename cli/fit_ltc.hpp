// `arealight fit-ltc`: fits a distribution's LTC table (fit/, include/arealight/ltc_table.hpp)
// and writes it atomically. Hooked into cli/main.cpp with add_fit_ltc_command before
// parsing and run_fit_ltc when the subcommand was parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace arealight::cli {

struct FitLtcArgs {
    std::string dist;
    int size = 64;
    unsigned threads = 0;  // 0: hardware concurrency
    std::string out;
};

CLI::App* add_fit_ltc_command(CLI::App& app, FitLtcArgs& args);

// Exit codes as cli/main.cpp: 0 ok, 3 fit or write failure (usage errors are CLI11's, 2).
int run_fit_ltc(const FitLtcArgs& args);

}  // namespace arealight::cli
