// 8-bit RGB PNG files (libpng).
#pragma once

#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"
#include "arealight/image.hpp"

namespace arealight {

// The PNG file's bytes (8-bit RGB, no interlace); nullopt with "NAME: cannot encode
// PNG: REASON" when libpng fails.
std::optional<std::string> encode_png(const Image8& image, const std::string& name,
                                      const DiagnosticConsumer& diag);
// Encodes, then writes atomically; on failure `path` is untouched.
bool write_png(const std::string& path, const Image8& image, const DiagnosticConsumer& diag);

}  // namespace arealight
