// Variant -> shader source: templates stitched in a fixed order with #define
// switches and #line provenance (as Filament's shader generator does).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"
#include "arealight/variant.hpp"

namespace arealight {

enum class Language {
    Glsl,  // GLSL 4.50 compute shader for glslang (Vulkan)
    Cpp,   // the same math as C++ over GLM, for the CPU mirror
    Hlsl,  // the same text as HLSL (Shader Model 6 syntax, glslang's HLSL front end)
};
// "glsl", "cpp", "hlsl".
const char* to_string(Language lang);
// Whether the library can be written in `lang` for the variant: HLSL only at fp32
// (the HLSL layer maps GLSL's fp32 words; fp64 and fp16 variants are GLSL only).
bool language_supports(Language lang, const Variant& v);

// Template files of a variant's kernel, in stitch order: the library's types,
// shared math, the family's templates (distribution, method, light), the light's
// library entry, then (GLSL only) the light's validation kernel. Paths are
// "templates/NAME.glsl".
std::vector<std::string> variant_templates(const Variant& v, Language lang);

// What a library's functions say of themselves beyond variant and domain: by
// canonical variant name, one comment line of measured error and cost.
struct LibraryOptions {
    std::map<std::string, std::string> measured;
};

// One table sampler of a library, in library order (each variant's samplers in turn):
// the variant (index into the library's variants), the sampler as the family row spells
// it, and its binding, AREALIGHT_BINDING + binding_offset. A sampler reading the same
// table as an earlier one (sampler_table_id) is no declaration of its own: `shares` is
// that entry's index (its binding_offset the same), else -1.
struct LibrarySampler {
    std::size_t variant = 0;
    std::string sampler;
    int binding_offset = 0;
    int shares = -1;
};
std::vector<LibrarySampler> library_samplers(const std::vector<Variant>& variants);

// The shading library of CONTRACT.md 5 for these variants: GLSL (no #version, no
// entry point) or, for the CPU mirror, the same text as C++ over GLM. One public
// function per variant, arealight_<light>_<dist>; every other name is moved into
// the variant's namespace al_<light>_<dist>_ (library_rename). nullopt with a
// diagnostic when two variants share a light type and distribution or a variant has
// no implementation. Deterministic.
std::optional<std::string> generate_library(const std::vector<Variant>& variants, Language lang,
                                            const LibraryOptions& opt,
                                            const DiagnosticConsumer& diag);

// "arealight_polygon_ggx".
// The light's arguments of the library function as the validation kernel and the
// CPU mirror spell them over their locals vertices[8], axes[3], count, two_sided
// (templates/library/kernel.glsl): "vertices[0], vertices[1].x" for a sphere.
std::string kernel_light_arguments(const Variant& v);
std::string library_function_name(const Variant& v);
// The macro that sets a sampler's binding ("AREALIGHT_POLYGON_GGX_LTC_MATRIX_BINDING"),
// for a sampler name as the family row spells it.
std::string sampler_binding_macro(const Variant& v, const std::string& sampler);
// The HLSL library's macro for the same table's register number, a literal
// ("AREALIGHT_POLYGON_GGX_LTC_MATRIX_REGISTER": register(tN) and register(sN)).
std::string sampler_register_macro(const Variant& v, const std::string& sampler);
// Which names library_rename moves: Prefixed, arealight's own (al_x, AL_X, AlX) and
// the precision words, enough to keep variants apart (the C++ mirror); EveryName also
// every other name but GLSL's own words, the contract's (CONTRACT.md 5) and
// swizzle-shaped members (x, rgb, st), so that no renderer's macro can reach the
// library's locals, parameters or struct members (the GLSL library).
enum class RenameScope { Prefixed, EveryName };
// The variant's namespace inside a library, "<light>_<dist>" ("polygon_ggx"): light and
// distribution, which a library holds at most one function for.
std::string library_tag(const Variant& v);
// Template text moved into the variant's namespace, as the library writes it:
// al_x -> al_<light>_<dist>_x, AL_X -> AL_<LIGHT>_<DIST>_X, AlX -> Al<Light><Dist>X,
// the precision words (real, rvec3, ...) -> al_<light>_<dist>_real, ..., and with
// EveryName any other name x -> al_<light>_<dist>_x; comments, strings and the
// text of #line, #extension, #error, #pragma and #version lines are kept
// (generator/library_rename.cpp).
std::string library_rename(const std::string& text, const Variant& v,
                           RenameScope scope = RenameScope::Prefixed);

// Which results the validation kernel writes: Shading, the library function's
// diffuse and specular (what a renderer pays for: timed and counted), or All, also
// the family's second quantity (ndf or moment) from a second call.
enum class KernelOutputs { Shading, All };

// The validation kernel (GLSL: a compute shader over cases; see
// templates/kernel_<light>.glsl) or the variant's library as C++ (Language::Cpp, for
// the CPU mirror). Deterministic. Every template chunk starts with
// `#line 1 "templates/NAME.glsl"` and is followed by a `#line` back to the generated
// text, so compiler messages name the template and line.
std::string generate_source(const Variant& v, Language lang,
                            KernelOutputs outputs = KernelOutputs::All);

// The validation kernel of `v` (GLSL) around a library text instead of v's own: the
// same #version prolog and entry point, so generate_kernel(v, library of {v}) compiles
// to what generate_source(v, Glsl, outputs) does. The library must define v's public
// function (a scene's pruned library, to compare it with the hand-named variant).
std::string generate_kernel(const Variant& v, const std::string& library_text,
                            KernelOutputs outputs = KernelOutputs::Shading);
// The validation kernel in HLSL (templates/library/kernel.hlsl around v's HLSL library):
// the same bindings, case layout and single library call as the GLSL kernel, entry
// function main. v must be language_supports(Hlsl, v).
std::string generate_hlsl_kernel(const Variant& v, KernelOutputs outputs = KernelOutputs::Shading);

// Where template text comes from: the embedded copies by default; tests inject
// modified text (a deliberately broken template) through this.
using TemplateLookup = std::function<const std::string*(const std::string& path)>;
std::string generate_source(const Variant& v, Language lang, const TemplateLookup& lookup,
                            KernelOutputs outputs = KernelOutputs::All);

// The text of an embedded template, or nullptr when unknown.
const std::string* template_text(const std::string& path);

// Gauss-Legendre rule on [-1, 1] with `n` nodes (Newton on P_n, double precision).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights);

}  // namespace arealight
