// `arealight replot DIR...`: a report's or sweep's markdown and pictures drawn again from
// its JSON (report.json or sweep.json), with today's plots and marks (front, recommended),
// without measuring again. Its options are in cli/main.cpp, which calls run_replot.
#pragma once

#include <string>
#include <vector>

namespace arealight::cli {

struct ReplotArgs {
    std::vector<std::string> dirs;
};

// Exit codes as cli/main.cpp: 0 ok, 1 a folder without a readable report or sweep JSON
// (nothing is written for it, nor for the folders after it), 3 a write failure.
int run_replot(const ReplotArgs& args);

}  // namespace arealight::cli
