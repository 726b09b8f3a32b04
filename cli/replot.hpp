// `arealight replot DIR...`: a report's or sweep's markdown and pictures drawn again from
// its JSON (report.json or sweep.json), with today's plots and marks (front, recommended),
// without measuring again. Hooked into cli/main.cpp with add_replot_command before parsing
// and run_replot when the subcommand was parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace arealight::cli {

struct ReplotArgs {
    std::vector<std::string> dirs;
};

CLI::App* add_replot_command(CLI::App& app, ReplotArgs& args);

// Exit codes as cli/main.cpp: 0 ok, 1 a folder without a readable report or sweep JSON
// (nothing is written for it, nor for the folders after it), 3 a write failure.
int run_replot(const ReplotArgs& args);

}  // namespace arealight::cli
