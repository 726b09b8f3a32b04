// Emitters plus one orchestrator. A library (CONTRACT.md 5) is: banner, the
// extensions it needs, the shared types, then per variant one chunk: language
// macros, defines, generated tables, samplers, template chunks bracketed by #line
// markers, the public function; every internal name of the chunk moved into the
// variant's own namespace (library_rename). The validation kernel is a library of
// one variant between a #version prolog and the light's kernel template.
#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <set>

#include "ascii_upper.hpp"
#include "arealight/fnv_hash.hpp"
#include "arealight/generator.hpp"
#include "embedded_templates.hpp"

namespace arealight {
namespace {

constexpr const char* kGeneratedName = "arealight-generated";

// What the library offers per light type (CONTRACT.md 5): the public function's
// light parameters, the templates that turn them into the methods' record, and how
// the validation kernel and the CPU mirror pass a case's light (their locals
// vertices[8], axes[3], count, two_sided; templates/library/kernel.glsl). A new light type
// is a row.
struct LightEntry {
    LightType light;
    const char* params;  // after `ArealightSurface s, `
    const char* args;    // the parameters' names, in order
    std::vector<std::string> library_templates;
    const char* kernel_args;
    const char* domain;
};

const std::vector<LightEntry>& light_entries() {
    static const std::vector<LightEntry> rows = {
        {LightType::Polygon, "vec3 vertices[8], int count, bool two_sided",
         "vertices, count, two_sided", {"library/polygon.glsl"}, "vertices, count, two_sided",
         "convex planar polygon, counter-clockwise seen from its emitting side, count in [3, "
         "AL_MAX_VERTS] (more are cut to the first AL_MAX_VERTS)"},
        // axis_u, axis_v (CONTRACT 5): case files' u and v, named apart from the view s.v.
        {LightType::Disk, "vec3 center, vec3 axis_u, vec3 axis_v, bool two_sided",
         "center, axis_u, axis_v, two_sided",
         {"light/ellipse_record.glsl", "light/spin_polygon.glsl", "library/disk.glsl"}, "vertices[0], vertices[1], vertices[2], two_sided",
         "disk or ellipse with orthogonal semi-axes axis_u, axis_v, emitting towards axis_u x "
         "axis_v (both sides if two_sided)"},
        {LightType::Sphere, "vec3 center, float radius", "center, radius",
         {"light/ellipse_record.glsl", "light/spin_polygon.glsl", "library/sphere.glsl"}, "vertices[0], vertices[1].x",
         "sphere of radius > 0, p outside it"},
        {LightType::Ellipsoid, "vec3 center, vec3 axes[3]", "center, axes",
         {"light/ellipse_record.glsl", "light/spin_polygon.glsl", "library/ellipsoid.glsl"}, "vertices[0], axes",
         "ellipsoid with orthogonal semi-axes, p outside it"},
    };
    return rows;
}

const LightEntry* find_light(LightType t) {
    for (const auto& e : light_entries())
        if (e.light == t) return &e;
    return nullptr;
}

int count_lines(const std::string& s) {
    int lines = 0;
    for (char ch : s) lines += ch == '\n';
    return lines;
}



// The suffix of a literal at the variant's working precision: fp64 GLSL needs lf
// (an unsuffixed GLSL literal is fp32 and would be rounded first), C++ has none.
std::string literal_suffix(const Variant& v, Language lang) {
    if (effective_precision(v) != Precision::Fp64) return "f";
    return lang == Language::Cpp ? "" : "lf";
}

// Templates write a literal at the working precision as AL_R(1.5). glslang cannot
// paste a suffix onto a number with ##, so the stitcher spells such literals out
// itself, on the same line (the #line markers stay exact).
std::string expand_literals(const std::string& text, const std::string& suffix) {
    static const std::string open = "AL_R(";
    std::string out;
    std::size_t pos = 0;
    for (;;) {
        const std::size_t at = text.find(open, pos);
        const std::size_t close = at == std::string::npos ? at : text.find(')', at);
        if (close == std::string::npos) break;
        out.append(text, pos, at - pos);
        out.append(text, at + open.size(), close - at - open.size());
        out += suffix;
        pos = close + 1;
    }
    out.append(text, pos, std::string::npos);
    return out;
}

// The few spellings GLSL and C++ do not share, as macros the templates use, and
// the working precision: the templates compute in `real` and `rvec2..4`.
void emit_language_macros(std::string& out, const Variant& v, Language lang) {
    const bool glsl = lang == Language::Glsl;
    out += fmt::format("#define AL_LANG_{} 1\n", ascii_upper(to_string(lang)));
    out += lang == Language::Cpp ? "#define AL_INOUT(T) T&\n" : "#define AL_INOUT(T) inout T\n";
    // A loop of constant trip count the GPU should run unrolled: SPIR-V's Unroll loop
    // control, which Mesa's NIR (RADV, lavapipe) and other drivers honour; the C++
    // mirror's compiler decides for itself.
    out += glsl ? "#define AL_UNROLL [[unroll]]\n"
                : (lang == Language::Hlsl ? "#define AL_UNROLL [unroll]\n" : "#define AL_UNROLL\n");
    // A constant array's initialiser: GLSL ES 3.10 has no C-style braces, only the array
    // constructor real[N](...); C++ and HLSL have no array constructor. Written
    // AL_ARRAY_BEGIN(real, 8) a, b, ... AL_ARRAY_END.
    out += glsl ? "#define AL_ARRAY_BEGIN(T, N) T[N](\n#define AL_ARRAY_END )\n"
                : "#define AL_ARRAY_BEGIN(T, N) {\n#define AL_ARRAY_END }\n";
    // frexp's exponent (common/common.glsl al_log): an int in GLSL and C++, a float in HLSL.
    out += lang == Language::Hlsl ? "#define AL_FREXP_EXPONENT float\n"
                                  : "#define AL_FREXP_EXPONENT int\n";
    // The half-precision part of a variant computes in hreal and hvec2..4: fp16 where
    // the precision is fp16 (the mirror's al_half rounds every operation to fp16,
    // include/arealight/mirror_support.hpp), else the working precision.
    if (effective_precision(v) == Precision::Fp16) {
        out += "#define AL_PRECISION_FP16 1\n";
        out += lang == Language::Glsl
                   ? "#define hreal float16_t\n#define hvec2 f16vec2\n#define hvec3 f16vec3\n"
                     "#define hvec4 f16vec4\n"
                   : "#define hreal al_half\n#define hvec2 al_hvec2\n#define hvec3 al_hvec3\n"
                     "#define hvec4 al_hvec4\n";
    } else {
        out += "#define hreal float\n#define hvec2 vec2\n#define hvec3 vec3\n#define hvec4 vec4\n";
    }
    if (effective_precision(v) == Precision::Fp64) {
        out +=
            "#define real double\n#define rvec2 dvec2\n#define rvec3 dvec3\n"
            "#define rvec4 dvec4\n";
    } else {
        out +=
            "#define real float\n#define rvec2 vec2\n#define rvec3 vec3\n"
            "#define rvec4 vec4\n";
    }
}

void emit_defines(std::string& out, const Variant& v) {
    for (const auto& [name, value] : variant_defines(v)) {
        out += fmt::format("#define {} {}\n", name, value);
    }
    // The curved lights share one record (templates/light/ellipse_record.glsl).
    if (v.light != LightType::Polygon) out += "#define AL_LIGHT_CURVED 1\n";
}

// Whether the variant's family uses a key (its row in the family table).
bool family_uses(const Variant& v, const char* key) {
    const VariantFamily* f = find_family(v);
    if (!f) return false;
    for (const auto& k : f->keys)
        if (k.key == key) return true;
    return false;
}

// Gauss-Legendre tables at the working precision, with enough digits to round-trip
// a double: AL_GL_* for the AL_NODES of key nodes, AL_GR_* for the AL_RADIAL of key
// radial.
void emit_tables(std::string& out, const Variant& v, Language lang, const std::string& suffix) {
    auto table = [&](const char* name, const std::vector<double>& values) {
        std::string items;
        for (double d : values)
            items += fmt::format("{}{:.17e}{}", items.empty() ? "" : ", ", d, suffix);
        if (lang == Language::Glsl) {
            out += fmt::format("const real {}[{}] = real[{}]({});\n", name, values.size(),
                               values.size(), items);
        } else if (lang == Language::Hlsl) {
            // `static` is added after the renaming (hlsl_static_constants).
            out += fmt::format("const real {}[{}] = {{{}}};\n", name, values.size(), items);
        } else {
            out += fmt::format("static const real {}[{}] = {{{}}};\n", name, values.size(), items);
        }
    };
    auto rule = [&](int n, const char* x_name, const char* w_name) {
        std::vector<double> x, w;
        gauss_legendre(n, x, w);
        table(x_name, x);
        table(w_name, w);
    };
    if (family_uses(v, "nodes")) rule(v.nodes, "AL_GL_X", "AL_GL_W");
    if (family_uses(v, "radial")) rule(v.radial, "AL_GR_X", "AL_GR_W");
}

// What stands in a chunk, before its renaming, for a sampler that shares an earlier
// variant's table: one comment line (never renamed), replaced after the renaming by the
// #define that makes the variant's name the earlier one's (same line count).
std::string shared_sampler_marker(std::size_t entry) {
    return fmt::format("// arealight shared sampler {}\n", entry);
}

// In HLSL a table is a texture and a sampler state, named after the renamed sampler:
// the same kind of marker, replaced after the renaming by their one-line declaration.
std::string hlsl_table_marker(std::size_t entry) {
    return fmt::format("// arealight hlsl table {}\n", entry);
}

std::string hlsl_table_declaration(const std::string& renamed, const std::string& reg) {
    return fmt::format(
        "Texture2D<float4> {0}_texture : AREALIGHT_HLSL_REGISTER(t, {1}, AREALIGHT_SPACE); "
        "SamplerState {0}_sampler : AREALIGHT_HLSL_REGISTER(s, {1}, AREALIGHT_SPACE);\n",
        renamed, reg);
}

// GLSL's words as the HLSL library spells them, defined before its text and undefined
// after it (a renderer's own HLSL after the include never sees them): the templates are
// written in GLSL, and this is the whole difference at fp32 but for what the language
// macros carry (inout, [unroll], array initialisers, frexp's exponent), global
// constants (static const) and the tables (textureLod on a texture and sampler pair).
struct HlslWord {
    const char* glsl;
    const char* hlsl;
};
constexpr HlslWord kHlslWords[] = {
    {"vec2", "float2"},   {"vec3", "float3"},      {"vec4", "float4"},      {"ivec2", "int2"},
    {"ivec3", "int3"},    {"ivec4", "int4"},       {"uvec2", "uint2"},      {"uvec3", "uint3"},
    {"uvec4", "uint4"},   {"bvec2", "bool2"},      {"bvec3", "bool3"},      {"bvec4", "bool4"},
    {"inversesqrt", "rsqrt"}, {"mix", "lerp"},     {"fract", "frac"},
    {"textureLod(t, uv, lod)", "AREALIGHT_HLSL_SAMPLE(t, uv, lod)"},
};

void emit_hlsl_prelude(std::string& out) {
    out += "#ifndef AREALIGHT_SPACE\n#define AREALIGHT_SPACE 0\n#endif\n";
    out += "// GLSL's words in HLSL (undefined again at the end of this library).\n";
    for (const auto& w : kHlslWords) out += fmt::format("#define {} {}\n", w.glsl, w.hlsl);
    // Two levels, so that a table's alias (a shared table) is expanded before the paste.
    out += "#define AREALIGHT_HLSL_SAMPLE(t, uv, lod) AREALIGHT_HLSL_SAMPLE_(t, uv, lod)\n";
    out += "#define AREALIGHT_HLSL_SAMPLE_(t, uv, lod) t##_texture.SampleLevel(t##_sampler, uv, "
           "lod)\n";
    out += "#define AREALIGHT_HLSL_REGISTER(k, n, s) AREALIGHT_HLSL_REGISTER_(k, n, s)\n";
    out += "#define AREALIGHT_HLSL_REGISTER_(k, n, s) register(k##n, space##s)\n";
}

void emit_hlsl_postlude(std::string& out) {
    for (const auto& w : kHlslWords) {
        const std::string name = w.glsl;
        out += fmt::format("#undef {}\n", name.substr(0, name.find('(')));
    }
    for (const char* m : {"AREALIGHT_HLSL_SAMPLE", "AREALIGHT_HLSL_SAMPLE_",
                          "AREALIGHT_HLSL_REGISTER", "AREALIGHT_HLSL_REGISTER_"})
        out += fmt::format("#undef {}\n", m);
}

// Whether an identifier names a vector type of the templates, as written or renamed
// (vec3, ivec2, rvec3, al_polygon_ggx_rvec3, hvec2 ...).
bool vector_type_name(const std::string& id) {
    std::string base = id;
    for (const char* word : {"_rvec", "_hvec"}) {
        const std::size_t at = id.rfind(word);
        if (id.rfind("al_", 0) == 0 && at != std::string::npos) base = id.substr(at + 1);
    }
    if (base.size() != 4 && base.size() != 5) return false;
    const char n = base.back();
    if (n < '2' || n > '4') return false;
    const std::string stem = base.substr(0, base.size() - 1);
    return stem == "vec" || stem == "ivec" || stem == "uvec" || stem == "bvec" ||
           stem == "rvec" || stem == "hvec";
}

// GLSL's one-argument vector constructor (a splat, vec3(0.0), or a conversion,
// vec3(v4)) is no HLSL: dxc wants every component ("too few elements in vector
// initialization"; glslang takes it). HLSL's cast does both: T(x) becomes ((T)(x)), on
// the same line. Comments and preprocessor lines are left alone.
std::string hlsl_vector_casts(const std::string& text) {
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    const std::size_t n = text.size();
    std::size_t i = 0;
    bool line_start = true;
    auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    while (i < n) {
        const char c = text[i];
        if (c == '/' && i + 1 < n && (text[i + 1] == '/' || text[i + 1] == '*')) {
            const bool line = text[i + 1] == '/';
            const std::size_t end = line ? text.find('\n', i) : text.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? n : (line ? end : end + 2);
            out.append(text, i, stop - i);
            i = stop;
            continue;
        }
        if (line_start && (c == ' ' || c == '\t')) {
            out += c;
            ++i;
            continue;
        }
        if (line_start && c == '#') {
            const std::size_t end = text.find('\n', i);
            const std::size_t stop = end == std::string::npos ? n : end;
            out.append(text, i, stop - i);
            i = stop;
            continue;
        }
        line_start = c == '\n';
        if (!ident(c) || (i > 0 && ident(text[i - 1]))) {
            out += c;
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < n && ident(text[j])) ++j;
        const std::string id = text.substr(i, j - i);
        if (j < n && text[j] == '(' && vector_type_name(id)) {
            // The balanced argument list, and whether it has a comma at its top level.
            int depth = 0;
            bool comma = false;
            std::size_t k = j;
            for (; k < n; ++k) {
                if (text[k] == '(') ++depth;
                if (text[k] == ')' && --depth == 0) break;
                if (text[k] == ',' && depth == 1) comma = true;
            }
            if (k < n && !comma) {
                out += "((" + id + ")(" + hlsl_vector_casts(text.substr(j + 1, k - j - 1)) + "))";
                i = k + 1;
                continue;
            }
        }
        out.append(text, i, j - i);
        i = j;
    }
    return out;
}

// HLSL reads a global `const` as a uniform (its initialiser ignored): the templates'
// global constants, the only declarations they start at column 0 with `const`, become
// `static const`.
std::string hlsl_static_constants(const std::string& text) {
    std::string out;
    out.reserve(text.size() + 256);
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        if (text.compare(pos, 6, "const ") == 0) out += "static ";
        out.append(text, pos, end - pos);
        pos = end;
    }
    return out;
}

// Separately generated libraries included into one shader must not bind their tables
// at the same numbers (CONTRACT.md 5). Each library with tables takes the first of
// kTableSlots slots of kSlotWidth bindings that no library included before it took
// (AREALIGHT_TABLE_SLOT_<s>, defined by the taker), so its k-th table defaults to
// kSlotWidth s + k, or AREALIGHT_BINDING + kSlotWidth s + k where the renderer defines
// AREALIGHT_BINDING, unless the table's own macro is defined. The defaults are literals
// (GLSL ES 3.10 takes only literal layout ids). kSlotWidth: a library has at most two
// tables per distribution (library_samplers shares the rest), eight in all.
constexpr int kSlotWidth = 8;
constexpr int kTableSlots = 8;

void emit_table_slots(std::string& out, const std::vector<Variant>& variants,
                      const std::vector<LibrarySampler>& plan, Language lang) {
    const bool hlsl = lang == Language::Hlsl;
    std::vector<std::pair<std::string, int>> macros;
    for (const auto& s : plan)
        if (s.shares < 0)
            macros.emplace_back(hlsl ? sampler_register_macro(variants[s.variant], s.sampler)
                                     : sampler_binding_macro(variants[s.variant], s.sampler),
                                s.binding_offset);
    if (macros.empty()) return;
    if (hlsl) {
        // HLSL's register(tN) takes a literal, which no preprocessor sum can paste: each
        // table's _REGISTER macro is a literal (the slot's default, or the renderer's).
        // No apostrophe in an #error: HLSL's preprocessor reads one as a character literal
        // even in a skipped block.
        out += fmt::format(
            "// The tables' default registers (t and s, space AREALIGHT_SPACE): the first slot\n"
            "// of {0} that no arealight library included before this one took (slot s: {0} s +\n"
            "// k); a table's own _REGISTER macro (a literal), defined before the include, wins.\n"
            "#ifdef AREALIGHT_REGISTER\n#error arealight: HLSL registers are literals, which "
            "AREALIGHT_REGISTER + k cannot give: define the _REGISTER macro of each table "
            "(tables.json: register_macro) instead\n#endif\n",
            kSlotWidth);
        for (int slot = 0; slot < kTableSlots; ++slot) {
            out += fmt::format(
                "#{} !defined(AREALIGHT_TABLE_SLOT_{})\n#define AREALIGHT_TABLE_SLOT_{} 1\n",
                slot == 0 ? "if" : "elif", slot, slot);
            for (const auto& [macro, k] : macros)
                out += fmt::format("#ifndef {0}\n#define {0} {1}\n#endif\n", macro,
                                   kSlotWidth * slot + k);
        }
        out += fmt::format(
            "#else\n#error arealight: more than {} libraries with tables in one shader: define "
            "the _REGISTER macro of each table (tables.json: register_macro) before including "
            "this one\n#endif\n",
            kTableSlots);
        return;
    }
    out += fmt::format(
        "// The tables' default bindings: the first slot of {0} that no arealight library\n"
        "// included before this one took (slot s: {0} s + k, after AREALIGHT_BINDING if\n"
        "// defined); a table's own _BINDING macro, defined before the include, wins.\n",
        kSlotWidth);
    for (int slot = 0; slot < kTableSlots; ++slot) {
        out += fmt::format("#{} !defined(AREALIGHT_TABLE_SLOT_{})\n#define AREALIGHT_TABLE_SLOT_{} 1\n",
                           slot == 0 ? "if" : "elif", slot, slot);
        for (const auto& [macro, k] : macros) {
            const int binding = kSlotWidth * slot + k;
            out += fmt::format(
                "#ifndef {0}\n#ifdef AREALIGHT_BINDING\n#define {0} (AREALIGHT_BINDING + {1})\n"
                "#else\n#define {0} {1}\n#endif\n#endif\n",
                macro, binding);
        }
    }
    out += fmt::format(
        "#else\n#error arealight: more than {} libraries with tables in one shader; define "
        "each table's _BINDING macro (tables.json: binding_macro) before including this one\n"
        "#endif\n",
        kTableSlots);
}

// The tables the variant samples (`entries`, its part of library_samplers): in GLSL
// sampled images at set AREALIGHT_SET and binding AREALIGHT_<TAG>_<NAME>_BINDING
// (emit_table_slots gives its default), or, for a table an earlier variant's sampler
// already reads, a marker for the alias; in C++ the mirror's samplers (bound by its
// run(), generator/mirror_tool.cpp).
void emit_samplers(std::string& out, const Variant& v, Language lang,
                   const std::vector<std::pair<std::size_t, LibrarySampler>>& entries) {
    for (const auto& [entry, s] : entries) {
        if (lang != Language::Cpp && s.shares >= 0) {
            out += shared_sampler_marker(entry);
        } else if (lang == Language::Hlsl) {
            out += hlsl_table_marker(entry);
        } else if (lang == Language::Glsl) {
            out += fmt::format("layout(set = AREALIGHT_SET, binding = {}) uniform sampler2D {};\n",
                               sampler_binding_macro(v, s.sampler), s.sampler);
        } else {
            out += fmt::format("static thread_local AlSampler2D {};\n", s.sampler);
        }
    }
}

void emit_template(std::string& out, const std::string& path, const TemplateLookup& lookup,
                   const std::string& suffix) {
    const std::string* text = lookup(path);
    static const std::string missing = "#error missing template\n";
    if (!text) text = &missing;
    out += fmt::format("#line 1 \"{}\"\n", path);
    out += expand_literals(*text, suffix);
    if (!text->empty() && text->back() != '\n') out += '\n';
    // Back to the generated text: the next line number is the current line + 1.
    out += fmt::format("#line {} \"{}\"\n", count_lines(out) + 2, kGeneratedName);
}

// The templates of a variant's chunk, in order: shared math, the family's list
// (generator/variant.cpp), the light's library entry.
std::vector<std::string> chunk_templates(const Variant& v) {
    std::vector<std::string> files = {"templates/common/common.glsl"};
    for (const auto& name : variant_family_templates(v)) files.push_back("templates/" + name);
    if (const LightEntry* light = find_light(v.light))
        for (const auto& t : light->library_templates) files.push_back("templates/" + t);
    return files;
}

// The function a renderer calls, with the comment CONTRACT.md 5 asks for.
void emit_public_function(std::string& out, const Variant& v, const LibraryOptions& opt) {
    const LightEntry* light = find_light(v.light);
    if (!light) return;
    const std::string name = canonical_name(v);
    const auto measured = opt.measured.find(name);
    const bool exponent = v.dist == Distribution::Phong || v.dist == Distribution::Blinn;
    out += fmt::format("// {}: variant {}.\n", library_function_name(v), name);
    out += fmt::format(
        "// Domain: p, n, v, the light in one space, fp32 (n, v any length); {}; s.param {}; "
        "s.f0 in [0, 1]{}.\n",
        light->domain, exponent ? "the exponent N in [1, 1e5]" : "alpha in [0.001, 1]",
        v.dist == Distribution::Phong ? " (ignored)" : "");
    if (v.sided == Sided::One) out += "// Compiled for one-sided lights: two_sided is ignored.\n";
    if (v.sided == Sided::Two) out += "// Compiled for two-sided lights: two_sided is ignored.\n";
    out += "// Returns diffuse and specular of CONTRACT.md 2 for unit radiance: finite, >= 0.\n";
    if (measured != opt.measured.end()) {
        out += "// " + measured->second + "\n";
    } else {
        out += "// Error and cost: not in arealight's measured data (see arealight report).\n";
    }
    // The peak-function methods of Lecocq et al. are patented (README.md, Patent notice).
    if (is_peak_method(v.method))
        out += "// Patent: the peak-function method of Lecocq et al. is covered by US 10,607,404; "
               "see arealight's README.md, Patent notice.\n";
    out += fmt::format("ArealightShading {}(ArealightSurface s, {}) {{\n",
                       library_function_name(v), light->params);
    out += fmt::format("    vec4 q = al_{}_evaluate(s, {});\n", to_string(v.light), light->args);
    out += "    ArealightShading result;\n";
    out += "    result.diffuse = q.x;\n";
    out += "    result.specular = q.y;\n";
    out += "    return result;\n}\n";
}

}  // namespace

std::string kernel_light_arguments(const Variant& v) {
    const LightEntry* light = find_light(v.light);
    return light ? light->kernel_args : "";
}

std::string library_function_name(const Variant& v) {
    return fmt::format("arealight_{}_{}", to_string(v.light), to_string(v.dist));
}

std::string sampler_binding_macro(const Variant& v, const std::string& sampler) {
    const std::string bare = sampler.rfind("al_", 0) == 0 ? sampler.substr(3) : sampler;
    return fmt::format("AREALIGHT_{}_{}_BINDING", ascii_upper(library_tag(v)), ascii_upper(bare));
}

std::string sampler_register_macro(const Variant& v, const std::string& sampler) {
    const std::string bare = sampler.rfind("al_", 0) == 0 ? sampler.substr(3) : sampler;
    return fmt::format("AREALIGHT_{}_{}_REGISTER", ascii_upper(library_tag(v)), ascii_upper(bare));
}

const char* to_string(Language lang) {
    switch (lang) {
        case Language::Glsl:
            return "glsl";
        case Language::Cpp:
            return "cpp";
        case Language::Hlsl:
            return "hlsl";
    }
    return "glsl";
}

bool language_supports(Language lang, const Variant& v) {
    return lang != Language::Hlsl || effective_precision(v) == Precision::Fp32;
}

std::vector<std::string> variant_templates(const Variant& v, Language lang) {
    std::vector<std::string> files = {"templates/library/types.glsl"};
    for (auto& f : chunk_templates(v)) files.push_back(std::move(f));
    if (lang == Language::Glsl && find_light(v.light)) files.push_back("templates/library/kernel.glsl");
    return files;
}

namespace {

// Appends the library text of `variants` to `out` (whose line count the #line
// markers continue). The caller has checked that (light, dist) pairs are distinct.
void emit_library(std::string& out, const std::vector<Variant>& variants, Language lang,
                  const LibraryOptions& opt, const TemplateLookup& lookup) {
    std::string names;
    for (const auto& v : variants) names += (names.empty() ? "" : ", ") + canonical_name(v);
    out += fmt::format(
        "// generated by arealight from templates/*.glsl for variants {}; do not edit\n"
        "// The shading library of CONTRACT.md 5: include it in any stage. Names outside\n"
        "// the contract's are prefixed al_<light>_<dist>_ (AL_..., Al...) so that they\n"
        "// cannot collide with a renderer's or another arealight library's.\n",
        names);
    // A guard named from the text it guards: including one file twice is harmless, two
    // different libraries still combine. The name is filled in at the end, in place
    // (same length, so no #line number moves).
    const std::string placeholder(16, '0');
    const std::size_t guard_at = out.size();
    out += fmt::format("#ifndef AREALIGHT_LIBRARY_{0}\n#define AREALIGHT_LIBRARY_{0} 1\n",
                       placeholder);
    const std::size_t body_at = out.size();
    if (lang == Language::Hlsl) emit_hlsl_prelude(out);
    if (lang == Language::Glsl) {
        out += "#extension GL_GOOGLE_cpp_style_line_directive : enable\n";
        out += "#extension GL_EXT_control_flow_attributes : enable\n";
        for (const auto& v : variants) {
            if (effective_precision(v) == Precision::Fp16) {
                out += "#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n";
                break;
            }
        }
    }
    emit_template(out, "templates/library/types.glsl", lookup, "");
    const std::vector<LibrarySampler> plan = library_samplers(variants);
    if (lang != Language::Cpp) emit_table_slots(out, variants, plan, lang);
    for (std::size_t vi = 0; vi < variants.size(); ++vi) {
        const Variant& v = variants[vi];
        std::vector<std::pair<std::size_t, LibrarySampler>> entries;
        for (std::size_t e = 0; e < plan.size(); ++e)
            if (plan[e].variant == vi) entries.emplace_back(e, plan[e]);
        const std::size_t start = out.size();
        emit_language_macros(out, v, lang);
        emit_defines(out, v);
        const std::string suffix = literal_suffix(v, lang);
        emit_tables(out, v, lang, suffix);
        emit_samplers(out, v, lang, entries);
        for (const auto& path : chunk_templates(v)) emit_template(out, path, lookup, suffix);
        emit_public_function(out, v, opt);
        std::string chunk = library_rename(
            out.substr(start), v,
            lang == Language::Cpp ? RenameScope::Prefixed : RenameScope::EveryName);
        out.replace(start, std::string::npos,
                    lang == Language::Hlsl ? hlsl_vector_casts(hlsl_static_constants(chunk))
                                           : chunk);
        for (const auto& [entry, s] : entries) {
            if (lang == Language::Hlsl && s.shares < 0) {
                const std::string marker = hlsl_table_marker(entry);
                const std::size_t at = out.find(marker, start);
                if (at != std::string::npos)
                    out.replace(at, marker.size(),
                                hlsl_table_declaration(library_rename(s.sampler, v),
                                                       sampler_register_macro(v, s.sampler)));
            }
            if (s.shares < 0) continue;
            const LibrarySampler& first = plan[static_cast<std::size_t>(s.shares)];
            const std::string marker = shared_sampler_marker(entry);
            const std::size_t at = out.find(marker, start);
            if (at == std::string::npos) continue;
            out.replace(at, marker.size(),
                        fmt::format("#define {} {}  // the same table\n",
                                    library_rename(s.sampler, v),
                                    library_rename(first.sampler, variants[first.variant])));
        }
        // What a renderer can #ifdef on (not renamed: outside the variant's namespace).
        out += fmt::format("#define AREALIGHT_HAS_{}_{} 1\n", ascii_upper(to_string(v.light)),
                           ascii_upper(to_string(v.dist)));
    }
    if (lang == Language::Hlsl) emit_hlsl_postlude(out);
    const std::string hash = fmt::format("{:016X}", fnv1a(std::string_view(out).substr(body_at)));
    for (std::size_t at = out.find(placeholder, guard_at); at < body_at;
         at = out.find(placeholder, at + hash.size()))
        out.replace(at, hash.size(), hash);
    out += fmt::format("#endif  // AREALIGHT_LIBRARY_{}\n", hash);
}

}  // namespace

std::vector<LibrarySampler> library_samplers(const std::vector<Variant>& variants) {
    std::vector<LibrarySampler> plan;
    int next = 0;
    for (std::size_t vi = 0; vi < variants.size(); ++vi) {
        for (const auto& sampler : variant_samplers(variants[vi])) {
            LibrarySampler s;
            s.variant = vi;
            s.sampler = sampler;
            const std::string id = sampler_table_id(variants[vi], sampler);
            for (std::size_t e = 0; e < plan.size() && s.shares < 0; ++e) {
                if (plan[e].shares < 0 &&
                    sampler_table_id(variants[plan[e].variant], plan[e].sampler) == id) {
                    s.shares = static_cast<int>(e);
                    s.binding_offset = plan[e].binding_offset;
                }
            }
            if (s.shares < 0) s.binding_offset = next++;
            plan.push_back(std::move(s));
        }
    }
    return plan;
}

std::optional<std::string> generate_library(const std::vector<Variant>& variants, Language lang,
                                            const LibraryOptions& opt,
                                            const DiagnosticConsumer& diag) {
    std::set<std::string> seen;
    for (const auto& v : variants) {
        if (!find_light(v.light) || !find_family(v)) {
            if (diag)
                diag({Severity::Error, "", 0,
                      "variant " + canonical_name(v) + " has no library function"});
            return std::nullopt;
        }
        if (!seen.insert(library_function_name(v)).second) {
            if (diag)
                diag({Severity::Error, "", 0,
                      fmt::format("two variants define {}: a library holds one variant per light "
                                  "type and distribution (CONTRACT.md 5)",
                                  library_function_name(v))});
            return std::nullopt;
        }
    }
    std::string out;
    emit_library(out, variants, lang, opt,
                 [](const std::string& path) { return template_text(path); });
    return out;
}

std::string generate_source(const Variant& v, Language lang, KernelOutputs outputs) {
    return generate_source(v, lang, [](const std::string& path) { return template_text(path); },
                           outputs);
}

namespace {

// The validation kernel's text before its library: #version and the bindings the
// runner gives cases and results.
void emit_kernel_prolog(std::string& out, const Variant& v) {
    out += "#version 450\n";
    out += "#extension GL_GOOGLE_cpp_style_line_directive : enable\n";
    std::string files;
    for (const auto& t : variant_templates(v, Language::Glsl))
        files += (files.empty() ? "" : ", ") + t;
    out += fmt::format("// generated by arealight from {} for variant {}; do not edit\n", files,
                       canonical_name(v));
    out += "// The validation kernel: the variant's library, called once per case.\n";
    // Cases and results take bindings 0 and 1 (runtime/vulkan_runner.cpp).
    out += "#define AREALIGHT_SET 0\n#define AREALIGHT_BINDING 2\n";
}

// The validation kernel's text after its library: the entry point that calls the
// variant's library function once per case.
void emit_kernel_entry(std::string& out, const Variant& v, KernelOutputs outputs,
                       const TemplateLookup& lookup) {
    const LightEntry* light = find_light(v.light);
    if (!light) return;
    out += fmt::format("#define AL_KERNEL_SHADE {}\n", library_function_name(v));
    out += fmt::format("#define AL_KERNEL_EVALUATE {}\n",
                       library_rename(fmt::format("al_{}_evaluate", to_string(v.light)), v));
    out += fmt::format("#define AL_KERNEL_ARGS {}\n", light->kernel_args);
    if (outputs == KernelOutputs::All) out += "#define AL_KERNEL_SECOND 1\n";
    emit_template(out, "templates/library/kernel.glsl", lookup, "f");
}

}  // namespace

std::string generate_source(const Variant& v, Language lang, const TemplateLookup& lookup,
                            KernelOutputs outputs) {
    std::string out;
    if (lang == Language::Glsl) emit_kernel_prolog(out, v);
    emit_library(out, {v}, lang, LibraryOptions{}, lookup);
    if (lang == Language::Glsl) emit_kernel_entry(out, v, outputs, lookup);
    return out;
}

std::string generate_hlsl_kernel(const Variant& v, KernelOutputs outputs) {
    std::string out;
    out += fmt::format(
        "// generated by arealight from templates/*.glsl and templates/library/kernel.hlsl "
        "for variant {}; do not edit\n"
        "// The HLSL validation kernel: the variant's HLSL library, called once per case.\n",
        canonical_name(v));
    // Cases and results take bindings 0 and 1 (runtime/vulkan_runner.cpp): the tables
    // from 2, as in the GLSL kernel.
    out += "#define AREALIGHT_SPACE 0\n";
    for (const auto& s : library_samplers({v}))
        if (s.shares < 0)
            out += fmt::format("#define {} {}\n", sampler_register_macro(v, s.sampler),
                               2 + s.binding_offset);
    emit_library(out, {v}, Language::Hlsl, LibraryOptions{}, template_text);
    const LightEntry* light = find_light(v.light);
    if (!light) return out;
    out += fmt::format("#define AL_KERNEL_SHADE {}\n", library_function_name(v));
    out += fmt::format("#define AL_KERNEL_EVALUATE {}\n",
                       library_rename(fmt::format("al_{}_evaluate", to_string(v.light)), v,
                                      RenameScope::EveryName));
    out += fmt::format("#define AL_KERNEL_ARGS {}\n", light->kernel_args);
    if (outputs == KernelOutputs::All) out += "#define AL_KERNEL_SECOND 1\n";
    emit_template(out, "templates/library/kernel.hlsl", template_text, "f");
    return out;
}

std::string generate_kernel(const Variant& v, const std::string& library_text,
                            KernelOutputs outputs) {
    std::string out;
    emit_kernel_prolog(out, v);
    out += library_text;
    if (!library_text.empty() && library_text.back() != '\n') out += '\n';
    emit_kernel_entry(out, v, outputs, template_text);
    return out;
}

const std::string* template_text(const std::string& path) {
    for (const auto& t : embedded_templates()) {
        if (t.path == path) return &t.text;
    }
    return nullptr;
}

}  // namespace arealight
