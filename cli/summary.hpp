// Human-readable tables of result sets for the command line.
#pragma once

#include <string>

#include "arealight/results.hpp"

namespace arealight::cli {

// One row per case: the quantities and the oracle's error bound.
std::string results_table(const ResultSet& results);

// One line: case count, non-converged count, largest relative error bound.
std::string results_summary(const ResultSet& results, double seconds);

}  // namespace arealight::cli
