// Reading arealight-cases/1 and writing arealight-results/1 (CONTRACT.md section 3).
#pragma once

#include <optional>
#include <string>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/results.hpp"

namespace arealight {

// Tolerances of the geometric checks (CONTRACT.md 3): relative to the light's own size,
// plus what rounding its coordinates to fp32 moves them, since a renderer's data is fp32.
struct ValidationTolerances {
    double coplanar_rel = 1e-6;   // |distance to plane| / polygon diameter
    double collinear_rel = 1e-9;  // |sin| of the turn angle at a vertex
    double orthogonal_rel = 1e-6; // |u.v| / (|u| |v|) of disk and ellipsoid axes
    // fp32 ulps at the largest coordinate magnitude added to the plane distance (and,
    // scaled by the other vector's length, to |u.v|).
    double fp32_ulps = 8.0;
};

// Parses and validates a case file. On failure returns nullopt and reports
// "FILE: case 'ID': field 'FIELD': reason" (file name in Diagnostic::file).
std::optional<CaseSet> read_cases(const std::string& path, const DiagnosticConsumer& diag,
                                  const ValidationTolerances& tol = {});
// Same, from text already in memory; `name` stands for the file in messages.
std::optional<CaseSet> parse_cases(const std::string& text, const std::string& name,
                                   const DiagnosticConsumer& diag,
                                   const ValidationTolerances& tol = {});

// Serializes with round-trip-exact doubles, keys in the order of CONTRACT.md and only the
// present fields. JSON has no NaN or infinity: a non-finite value is written as null, which
// read_results reads back as absent.
std::string format_results(const ResultSet& results);
// Writes atomically (temporary file in the same folder, then rename).
// On failure the destination is untouched and false is returned.
bool write_results(const std::string& path, const ResultSet& results,
                   const DiagnosticConsumer& diag);
// Reads a results file (for tests and reports).
std::optional<ResultSet> read_results(const std::string& path, const DiagnosticConsumer& diag);
// Same, from text already in memory; `name` stands for the file in messages.
std::optional<ResultSet> parse_results(const std::string& text, const std::string& name,
                                       const DiagnosticConsumer& diag);

}  // namespace arealight
