// Renders a scene with the shading library: every visible surface point, once per
// light, becomes a CONTRACT 1 case; all of a variant's cases run in one batch on the
// Evaluator (or all cases through the oracle), and a pixel's radiance is
//   sum over lights of intensity * (albedo * diffuse + specular)
// (no shadows: CONTRACT 1's visibility is the light's own). Light faces seen directly
// show their intensity; the background is 0.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/image.hpp"
#include "arealight/reference.hpp"
#include "arealight/quality.hpp"
#include "arealight/render_scene.hpp"
#include "arealight/scene_select.hpp"
#include "arealight/variant.hpp"

namespace arealight {

struct RenderOptions {
    int width = 320, height = 240;
    // At most one per (light type, distribution); the rest take render_variant's choice.
    std::vector<Variant> variants;
    // The measured data the rest are selected by; null: shipped_quality().
    const QualityData* quality = nullptr;
    bool reference = false;  // the oracle instead of the Evaluator
    ReferenceOptions reference_options;
};

struct RenderStats {
    std::size_t cases = 0;             // shading points times lights
    double shading_seconds = 0.0;      // Evaluator backend time, or the oracle's wall time
    std::vector<std::string> variants;  // canonical names used, in order of first use
    std::size_t unconverged = 0;       // oracle cases its evaluation budget stopped
};

// The variant for a (light type, distribution) of the scene that no --variant covers:
// the scene's own selection, exactly what `arealight generate --scene` puts in its library
// (select_variants: quality.method, quality.max_error or kDefaultMaxError, specialised to
// the sidedness and largest polygon of the scene's lights of that type), named in a note
// with why it was chosen. nullopt after select_variants' errors.
std::optional<SelectedVariant> render_variant(const Scene& scene, LightType light,
                                              Distribution dist, const QualityData& measured,
                                              const DiagnosticConsumer& diag);

// The scene's picture in linear radiance. `evaluator` may be null with opt.reference.
// nullopt after a diagnostic when no variant is selected, one does not apply to a light (sidedness,
// polygon size) or fails to run.
std::optional<LinearImage> render(const RenderScene& scene, const RenderOptions& opt,
                                  Evaluator* evaluator, const DiagnosticConsumer& diag,
                                  const ProgressConsumer& progress = {},
                                  RenderStats* stats = nullptr);

}  // namespace arealight
