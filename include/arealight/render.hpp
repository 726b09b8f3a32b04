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
#include "arealight/render_scene.hpp"
#include "arealight/variant.hpp"

namespace arealight {

struct RenderOptions {
    int width = 320, height = 240;
    // At most one per (light type, distribution); the rest take default_render_variant.
    std::vector<Variant> variants;
    bool reference = false;  // the oracle instead of the Evaluator
    ReferenceOptions reference_options;
};

struct RenderStats {
    std::size_t cases = 0;             // shading points times lights
    double shading_seconds = 0.0;      // Evaluator backend time, or the oracle's wall time
    std::vector<std::string> variants;  // canonical names used, in order of first use
    std::size_t unconverged = 0;       // oracle cases its evaluation budget stopped
};

// The variant for a (light type, distribution) when none is given: the scene's
// quality.method if that combination exists (a note says when it does not), else method=ltc for ggx (what README's
// method guide recommends to renderers) and method=pearson (the paper's best fitted
// peak method) for phong, blinn and beckmann. nullopt with a diagnostic naming the
// combination when it has no implementation.
std::optional<Variant> default_render_variant(LightType light, Distribution dist,
                                              const std::string& scene_method,
                                              const DiagnosticConsumer& diag);

// The scene's picture in linear radiance. `evaluator` may be null with opt.reference.
// nullopt after a diagnostic when a variant is missing, does not apply to a light
// (sidedness, polygon size) or fails to run.
std::optional<LinearImage> render(const RenderScene& scene, const RenderOptions& opt,
                                  Evaluator* evaluator, const DiagnosticConsumer& diag,
                                  const ProgressConsumer& progress = {},
                                  RenderStats* stats = nullptr);

}  // namespace arealight
