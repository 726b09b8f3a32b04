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

struct Scene {
    std::vector<Light> lights;        // at least one
    std::vector<Material> materials;  // at least one; each may be lit by every light
    // quality.max_error: the relative L2 error the scene tolerates (> 0).
    std::optional<double> max_error;
    // quality.method: a method name, checked against the variant keys when selecting
    // (the reader knows no variants).
    std::optional<std::string> method;
};

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
