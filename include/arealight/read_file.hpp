// Whole-file reads with the project's message style.
#pragma once

#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"

namespace arealight {

// The file's bytes, or nullopt after "PATH: cannot read: REASON" (a folder is named
// as one rather than read as empty).
std::optional<std::string> read_file(const std::string& path, const DiagnosticConsumer& diag);

}  // namespace arealight
