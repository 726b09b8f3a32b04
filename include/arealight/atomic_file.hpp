// Whole-file writes that never leave a partial file behind.
#pragma once

#include <string>

#include "arealight/diagnostics.hpp"

namespace arealight {

// Writes `bytes` to a temporary file beside `path`, flushes it and renames it
// over `path`. On failure `path` is untouched, the temporary is removed, and
// "PATH: cannot write: REASON" goes to `diag`.
bool write_file_atomic(const std::string& path, const std::string& bytes,
                       const DiagnosticConsumer& diag);

}  // namespace arealight
