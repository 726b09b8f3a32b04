// Measured quality of variants (arealight-quality/1): per variant, the pooled relative L2
// error of each quantity and the cost, taken from report JSON files (arealight report,
// docs/report*/report.json). The data behind scene-driven selection (scene_select.hpp);
// `arealight quality` writes it and the build embeds data/quality/measured.json.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/gpu_cost.hpp"

namespace arealight {

struct MeasuredVariant {
    std::string variant;  // the name as the report wrote it (canonical)
    // Pooled relative L2 error over every case the report ran it on (shared/tools/score's
    // metric), per quantity: "diffuse", "specular", and "ndf" or "moment".
    std::map<std::string, double> rel_l2;
    // The report's error_rel_l2: the larger of specular's and the second quantity's.
    double error_rel_l2 = 0;
    std::size_t x86_instructions = 0;  // lavapipe's machine code for the shader
    double ratio_to_point = 0;         // time per case over the point baseline's, same run
    // RADV's figures of the variant's kernel (gpu_cost.hpp); absent where RADV was not
    // available. `arealight quality` measures it from the variant itself.
    std::optional<GpuCost> gpu;
    std::size_t cases = 0;
    std::string report;  // the report file that measured it

    // What a scene's max_error is compared with: error_rel_l2, or diffuse's relL2 when
    // larger (exact in every method but point, whose large diffuse error then shows).
    double error() const;
};

struct QualityData {
    std::vector<std::string> reports;  // the report files read, in order
    std::vector<MeasuredVariant> variants;

    const MeasuredVariant* find(const std::string& variant) const;
};

// Reads arealight-report/1 files into one table. A variant in several reports takes the
// last one's row (in the order given), so a newer report listed later supersedes. A row
// without an x86 count (a report run without a shader cache) or with a non-finite error is
// left out with a warning; a row's `gpu` object is kept when well formed (else dropped
// with a warning). Reports written before error_rel_l2 existed get it as the
// larger relL2 of the quantities other than diffuse, as the report computes it.
std::optional<QualityData> quality_from_reports(const std::vector<std::string>& paths,
                                                const DiagnosticConsumer& diag);

// arealight-quality/1: keys in a fixed order, round-trip-exact numbers.
std::string format_quality(const QualityData& data);
std::optional<QualityData> parse_quality(const std::string& text, const std::string& name,
                                         const DiagnosticConsumer& diag);

}  // namespace arealight
