// Variant -> shader source: templates stitched in a fixed order with #define
// switches and #line provenance (as Filament's shader generator does).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arealight/variant.hpp"

namespace arealight {

enum class Language {
    Glsl,  // GLSL 4.50 compute shader for glslang (Vulkan)
    Cpp,   // the same math as C++ over GLM, for the CPU mirror
};

// Template files of a variant, in stitch order: shared math, distribution,
// method, light, then (GLSL only) the entry point. Paths are "templates/NAME.glsl".
std::vector<std::string> variant_templates(const Variant& v, Language lang);

// The stitched source. Deterministic: the same variant gives the same bytes.
// Every template chunk starts with `#line 1 "templates/NAME.glsl"` and is followed by a
// `#line` back to the generated text, so compiler messages name the template and line.
std::string generate_source(const Variant& v, Language lang);

// Where template text comes from: the embedded copies by default; tests inject
// modified text (a deliberately broken template) through this.
using TemplateLookup = std::function<const std::string*(const std::string& path)>;
std::string generate_source(const Variant& v, Language lang, const TemplateLookup& lookup);

// The text of an embedded template, or nullptr when unknown.
const std::string* template_text(const std::string& path);

// Gauss-Legendre rule on [-1, 1] with `n` nodes (Newton on P_n, double precision).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace arealight
