// The data a shading library samples (CONTRACT.md 5: `arealight generate --tables
// DIR`): one file per sampler and a manifest saying which binding takes which file
// and how to sample it.
#pragma once

#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/variant.hpp"

namespace arealight {

// Writes, for every sampler of `variants` in library order, DIR/<light>_<dist>_<name>.rgba32f
// (width * height texels of 4 little-endian fp32, row-major from v = 0) and then
// DIR/tables.json (format arealight-tables/1). Each file is written atomically and
// the manifest last, so a manifest always describes complete files. A library
// without samplers gets a manifest with no tables. false with a diagnostic on failure.
bool write_library_tables(const std::vector<Variant>& variants, const std::string& dir,
                          const DiagnosticConsumer& diag);

}  // namespace arealight
