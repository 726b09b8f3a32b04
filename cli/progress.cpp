#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>  // isatty: a live progress line only on a terminal

#include <cstdio>

namespace arealight::cli {

ProgressPrinter::ProgressPrinter(std::string what, std::string unit)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      start_(std::chrono::steady_clock::now()),
      live_(isatty(fileno(stderr)) != 0) {}

void ProgressPrinter::operator()(std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const auto every = live_ ? std::chrono::milliseconds(250) : std::chrono::milliseconds(5000);
    if (elapsed < 1.0 || (done != total && now - last_ < every)) return;
    last_ = now;
    fmt::print(stderr, "{}{}: {}/{} {}, {:.1f} s{}", live_ ? "\r" : "", what_, done, total,
               unit_, elapsed, live_ && done != total ? "" : "\n");
    std::fflush(stderr);
}

}  // namespace arealight::cli
