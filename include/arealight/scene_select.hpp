// From a scene to the variants its library needs (CONTRACT.md section 7): one per
// (light type, distribution) that occurs (every material can be lit by every light),
// each specialised to what the scene uses and chosen by measured quality.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/quality.hpp"
#include "arealight/scene.hpp"
#include "arealight/variant.hpp"

namespace arealight {

// The relative L2 error a scene without "quality" tolerates.
constexpr double kDefaultMaxError = 0.02;

struct SelectedVariant {
    Variant variant;
    std::string why;  // one line: the measured error and cost it was chosen by
};

// One variant per (light type, distribution) of the scene, ordered by light type, then
// distribution. The quality of a pair is effective_quality(scene, its distribution):
// the scene's, overridden by its materials' own. Only variants it allows count
// (precision fp32 unless it says fp64, no tables if tables is false, no patented peak
// function if patented is false, no excluded method). Each is:
// - the method: with quality.method alone, that method with every other key at its
//   default (precision=fp32 where fp64 is not allowed and the family offers it);
//   otherwise, among the allowed measured variants of the pair (of that method when
//   quality.method is also given), the cheapest by GPU cost (CONTRACT.md 4: the
//   MeasuredVariant's gpu.cost; rows without GPU figures rank after, by x86-64 count)
//   whose MeasuredVariant::error() is at most max_error (kDefaultMaxError without one);
//   when none is, the most accurate allowed, with a warning naming the error it reaches.
//   Only rows measured at the default sided and verts count (those ran on every case);
//   the data is per variant, pooled over the public case sets, so the scene's parameter
//   range cannot narrow it.
// - specialised: sided=one when every light of its type is one-sided, two when every one
//   is two-sided (else any), and verts the smallest the family offers that holds the
//   scene's largest polygon; a value the family does not offer stays at its default.
// nullopt, with an error per problem, when a pair has no implemented variant (or none of
// quality.method), quality.method or an exclude name is no method, the method asked for
// is one the quality refuses, materials of one distribution ask for different methods,
// or no allowed measured row fits a pair.
std::optional<std::vector<SelectedVariant>> select_variants(const Scene& scene,
                                                            const QualityData& measured,
                                                            const DiagnosticConsumer& diag);

// data/quality/measured.json as compiled into arealight (empty if it failed to parse,
// which the tests rule out).
const QualityData& shipped_quality();

}  // namespace arealight
