// Moving a variant's template text into its own namespace inside a library
// (CONTRACT.md 5): every name a renderer could also use, as a macro or otherwise,
// takes the prefix al_<light>_<dist>_ (AL_..., Al...), so that neither another
// arealight library nor a renderer's `#define N 16` before the include can reach it.
// One pass over the text's tokens; comments, strings and the rest of #line,
// #extension, #error, #pragma and #version lines are kept as written.
#include <fmt/format.h>

#include <cctype>
#include <set>
#include <string>

#include "ascii_upper.hpp"
#include "arealight/generator.hpp"

namespace arealight {
namespace {


// Names the mirror's support header defines (include/arealight/mirror_support.hpp):
// shared by every variant, never renamed.
bool shared_support_name(const std::string& id) {
    static const std::set<std::string> names = {"AlSampler2D", "al_half", "al_hvec2", "al_hvec3",
                                                "al_hvec4"};
    return names.count(id) != 0;
}

bool precision_word(const std::string& id) {
    static const std::set<std::string> words = {"real",  "rvec2", "rvec3", "rvec4",
                                                "hreal", "hvec2", "hvec3", "hvec4"};
    return words.count(id) != 0;
}

// GLSL 4.50's own words that the templates use or may use: keywords, types,
// qualifiers and layout ids, built-in functions (GLSL 4.50 section 8), the
// preprocessor's words and loop attributes. Never renamed; a missing one shows
// as a compile error of every variant that uses it.
bool glsl_word(const std::string& id) {
    static const std::set<std::string> words = {
        // keywords and qualifiers
        "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile",
        "restrict", "readonly", "writeonly", "layout", "centroid", "flat", "smooth",
        "noperspective", "patch", "sample", "break", "continue", "do", "for", "while", "switch",
        "case", "default", "if", "else", "subroutine", "in", "out", "inout", "true", "false",
        "invariant", "precise", "discard", "return", "struct", "lowp", "mediump", "highp",
        "precision", "set", "binding", "std140", "std430", "push_constant", "local_size_x",
        "local_size_y", "local_size_z", "location", "offset", "row_major", "column_major",
        "main",
        // types
        "void", "bool", "int", "uint", "float", "double", "vec2", "vec3", "vec4", "dvec2",
        "dvec3", "dvec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4", "bvec2", "bvec3",
        "bvec4", "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3",
        "mat3x4", "mat4x2", "mat4x3", "mat4x4", "dmat2", "dmat3", "dmat4", "sampler2D",
        "sampler2DArray", "texture2D", "sampler", "float16_t", "f16vec2", "f16vec3", "f16vec4",
        // built-in functions
        "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh",
        "asinh", "acosh", "atanh", "pow", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt",
        "abs", "sign", "floor", "trunc", "round", "roundEven", "ceil", "fract", "mod", "modf",
        "min", "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "floatBitsToInt",
        "floatBitsToUint", "intBitsToFloat", "uintBitsToFloat", "fma", "frexp", "ldexp",
        "packHalf2x16", "unpackHalf2x16", "packDouble2x32", "unpackDouble2x32", "length",
        "distance", "dot", "cross", "normalize", "faceforward", "reflect", "refract",
        "matrixCompMult", "outerProduct", "transpose", "determinant", "inverse", "lessThan",
        "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual", "any", "all",
        "not", "texture", "textureLod", "textureSize", "texelFetch", "textureGather", "dFdx",
        "dFdy", "fwidth", "bitCount", "findLSB", "findMSB", "bitfieldExtract", "barrier",
        "memoryBarrier",
        // preprocessor and attributes
        "define", "defined", "undef", "ifdef", "ifndef", "elif", "endif", "unroll",
        "dont_unroll"};
    return words.count(id) != 0 || id.rfind("gl_", 0) == 0 || id.rfind("GL_", 0) == 0;
}

// The contract's own names (CONTRACT.md 5): the types, their members, the public
// functions and the renderer's macros.
bool contract_name(const std::string& id) {
    static const std::set<std::string> members = {"p",     "n",       "v",       "param",
                                                  "f0",    "diffuse", "specular"};
    return members.count(id) != 0 || id.rfind("Arealight", 0) == 0 ||
           id.rfind("arealight_", 0) == 0 || id.rfind("AREALIGHT_", 0) == 0;
}

// A member name that could be a swizzle (.x, .xyz, .rg, .st): written after a dot,
// it must stay as it is, so a struct member spelled so is never renamed either.
bool swizzle_shaped(const std::string& id) {
    if (id.empty() || id.size() > 4) return false;
    for (const char* set : {"xyzw", "rgba", "stpq"}) {
        bool all = true;
        for (char c : id) all = all && std::string(set).find(c) != std::string::npos;
        if (all) return true;
    }
    return false;
}

std::string camel(const std::string& tag) {
    std::string out;
    bool up = true;
    for (char c : tag) {
        if (c == '_') {
            up = true;
            continue;
        }
        out += up ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        up = false;
    }
    return out;
}

// The names every scope renames: arealight's own prefixes and the precision words.
// Returns false for any other name.
bool rename_prefixed(const std::string& id, const std::string& tag, std::string& out) {
    if (shared_support_name(id)) return false;
    if (id.rfind("al_", 0) == 0) {
        out = "al_" + tag + "_" + id.substr(3);
    } else if (id.rfind("AL_", 0) == 0) {
        out = "AL_" + ascii_upper(tag) + "_" + id.substr(3);
    } else if (id.size() > 2 && id.rfind("Al", 0) == 0 &&
               std::isupper(static_cast<unsigned char>(id[2]))) {
        out = "Al" + camel(tag) + id.substr(2);
    } else if (precision_word(id)) {
        out = "al_" + tag + "_" + id;
    } else {
        return false;
    }
    return true;
}

}  // namespace

std::string library_tag(const Variant& v) {
    return fmt::format("{}_{}", to_string(v.light), to_string(v.dist));
}

std::string library_rename(const std::string& text, const Variant& v, RenameScope scope) {
    const std::string tag = library_tag(v);
    const bool every = scope == RenameScope::EveryName;
    std::string out;
    out.reserve(text.size() + text.size() / 4);
    const std::size_t n = text.size();
    std::size_t i = 0;
    auto ident_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    bool line_start = true;     // only blanks since the last newline
    bool after_dot = false;     // the last token was a member-access '.'
    int struct_head = 0;        // 1: `struct` read, 2: and its name; '{' opens its body
    int struct_depth = -1;      // brace depth of the struct body being read, or -1
    int depth = 0;              // brace depth
    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            out += c;
            ++i;
            line_start = true;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r') {
            out += c;
            ++i;
            continue;
        }
        if (c == '#' && line_start) {
            // A directive: #line, #extension, #error, #pragma and #version are kept whole
            // (file names, extension names, messages); the others' names are renamed.
            std::size_t j = i + 1;
            while (j < n && (text[j] == ' ' || text[j] == '\t')) ++j;
            std::size_t k = j;
            while (k < n && ident_char(text[k])) ++k;
            const std::string word = text.substr(j, k - j);
            if (word == "line" || word == "extension" || word == "error" || word == "pragma" ||
                word == "version") {
                const std::size_t end = text.find('\n', i);
                const std::size_t stop = end == std::string::npos ? n : end;
                out.append(text, i, stop - i);
                i = stop;
            } else {
                out.append(text, i, k - i);
                i = k;
            }
            line_start = false;
            continue;
        }
        line_start = false;
        if (c == '/' && i + 1 < n && text[i + 1] == '/') {  // line comment: kept as written
            const std::size_t end = text.find('\n', i);
            const std::size_t stop = end == std::string::npos ? n : end;
            out.append(text, i, stop - i);
            i = stop;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            const std::size_t end = text.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? n : end + 2;
            out.append(text, i, stop - i);
            i = stop;
        } else if (c == '"') {
            const std::size_t end = text.find('"', i + 1);
            const std::size_t stop = end == std::string::npos ? n : end + 1;
            out.append(text, i, stop - i);
            i = stop;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            // A number, exponent and suffix included (1e-5f, 0.5lf): not an identifier.
            std::size_t j = i + 1;
            while (j < n && (ident_char(text[j]) || text[j] == '.' ||
                             ((text[j] == '-' || text[j] == '+') &&
                              (text[j - 1] == 'e' || text[j - 1] == 'E'))))
                ++j;
            out.append(text, i, j - i);
            i = j;
            after_dot = false;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i + 1;
            while (j < n && ident_char(text[j])) ++j;
            const std::string id = text.substr(i, j - i);
            std::string renamed;
            if (rename_prefixed(id, tag, renamed)) {
                out += renamed;
            } else if (!every || shared_support_name(id) || glsl_word(id) || contract_name(id)) {
                out += id;
            } else if ((after_dot || struct_depth == depth) && swizzle_shaped(id)) {
                // A member: after '.', or declared in a struct's body. Swizzle-shaped
                // ones stay (the dot cannot tell a struct from a vector).
                out += id;
            } else {
                out += "al_" + tag + "_" + id;
            }
            struct_head = struct_head == 1 ? 2 : (id == "struct" ? 1 : 0);
            after_dot = false;
            i = j;
        } else {
            if (c == '{') {
                ++depth;
                if (struct_head == 2) struct_depth = depth;
            } else if (c == '}') {
                if (struct_depth == depth) struct_depth = -1;
                --depth;
            }
            struct_head = 0;
            after_dot = c == '.';
            out += c;
            ++i;
        }
    }
    return out;
}

}  // namespace arealight
