// Progress of long commands on stderr (moved out of cli/main.cpp for render's use).
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace arealight::cli {

// Reports progress on stderr once a run has taken more than a second: one live
// line (rewritten every 250 ms) on a terminal, plain lines (every 5 s, and the
// last) when stderr is a file or a pipe, so that logs stay readable.
class ProgressPrinter {
  public:
    ProgressPrinter(std::string what, std::string unit);
    void operator()(std::size_t done, std::size_t total);

  private:
    std::string what_, unit_;
    std::chrono::steady_clock::time_point start_, last_{};
    bool live_;
};

}  // namespace arealight::cli
