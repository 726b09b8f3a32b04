// Linear radiance as a Portable Float Map (PFM, colour): the text header "PF\n",
// "WIDTH HEIGHT\n", "-1.0\n" (negative: little-endian), then WIDTH * HEIGHT RGB triples
// of 32-bit floats, rows from the bottom of the picture to the top. Read by most HDR tools.
#pragma once

#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"
#include "arealight/image.hpp"

namespace arealight {

std::string format_pfm(const LinearImage& image);
// Writes atomically; on failure `path` is untouched.
bool write_pfm(const std::string& path, const LinearImage& image, const DiagnosticConsumer& diag);
// Colour PFM of either byte order; "PATH: not a colour PFM: REASON" on failure.
std::optional<LinearImage> parse_pfm(const std::string& bytes, const std::string& name,
                                     const DiagnosticConsumer& diag);
std::optional<LinearImage> read_pfm(const std::string& path, const DiagnosticConsumer& diag);

}  // namespace arealight
