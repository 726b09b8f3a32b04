// What a scene needs (CONTRACT.md section 7, arealight-scene/1): its lights and
// materials, read and validated exactly as a case's (section 3), and the quality it
// asks for. Variant selection from a scene is generator/scene_select.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/case_io.hpp"
#include "arealight/diagnostics.hpp"

namespace arealight {

// What a scene's "quality" object allows (CONTRACT.md section 7). Every field is
// optional: a material's own quality overrides the scene's field by field
// (effective_quality).
struct SceneQuality {
    // max_error: the relative L2 error tolerated (> 0).
    std::optional<double> max_error;
    // method: a method name, checked against the variant keys when selecting (the
    // reader knows no variants).
    std::optional<std::string> method;
    // precision "fp64" allows fp64 variants (true), "fp32" does not (false; the default).
    std::optional<bool> fp64;
    // tables: whether methods that sample tables (ltc) may be chosen (default true).
    std::optional<bool> tables;
    // patented: whether the patented peak-function methods (lorentz, pearson,
    // ellipsoid) may be chosen (default true).
    std::optional<bool> patented;
    // exclude: method names never to choose (names checked when selecting).
    std::vector<std::string> exclude;
};

struct Scene {
    std::vector<Light> lights;        // at least one
    std::vector<Material> materials;  // at least one; each may be lit by every light
    SceneQuality quality;             // the scene's "quality" (all unset without one)
    // Per material (parallel to materials): its own "quality", if it has one.
    std::vector<std::optional<SceneQuality>> material_quality;
};

// The quality that applies to one distribution: the scene's, with each field that a
// material of that distribution sets taken from the material. Where several materials
// of the distribution set it, the strictest wins (the smallest max_error, a false of
// fp64, tables or patented, the union of exclude); their methods must agree, else
// `conflict` names the field and the materials (and the scene's quality is returned).
SceneQuality effective_quality(const Scene& scene, Distribution dist, std::string* conflict);

// Parses and validates a scene file. On failure returns nullopt and reports
// "FILE: light N: field 'FIELD': reason" (N counts from 0 in "lights"; likewise
// "material N"), or "FILE: field 'FIELD': reason" for the top-level fields.
// Unknown fields are ignored.
std::optional<Scene> read_scene(const std::string& path, const DiagnosticConsumer& diag,
                                const ValidationTolerances& tol = {});
// Same, from text already in memory; `name` stands for the file in messages.
std::optional<Scene> parse_scene(const std::string& text, const std::string& name,
                                 const DiagnosticConsumer& diag,
                                 const ValidationTolerances& tol = {});

}  // namespace arealight
