// The shading library from a renderer's side (CONTRACT.md 5): tests/data/contract_user.comp,
// written against the contract alone with its own buffer layout, includes a library of four
// polygon variants (one with tables), compiled by compile_shader with an include folder and run
// on VulkanRunner; per shading point it must give what Evaluator::run (the validation kernel)
// gives for each variant. The same shader over two libraries included together, after
// declarations of the names arealight uses internally (real, rvec3, AlCase), gives the same.
#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"
#include "arealight/library_tables.hpp"
#include "arealight/vulkan_runner.hpp"
#include "eval_support.hpp"
#include "fp32_families.hpp"
#include "microfacet_cases.hpp"
#include "scratch_folder.hpp"

namespace arealight::test {
namespace {

// contract_user.comp's material models: which arealight_polygon_<dist> a point calls.
struct UserVariant {
    const char* name;
    int model;  // kGgx, kPhong, kBeckmann, kBlinn in the shader
    Distribution dist;
};
const UserVariant kUserVariants[] = {
    {"dist=ggx,method=ltc,light=polygon", 0, Distribution::Ggx},
    {"dist=phong,method=lorentz,light=polygon,sided=any", 1, Distribution::Phong},
    {"dist=beckmann,method=exact,light=polygon,precision=fp64", 2, Distribution::Beckmann},
    {"dist=blinn,method=pearson,light=polygon", 3, Distribution::Blinn},
};
constexpr int kCasesPerVariant = 40;

// contract_user.comp's ShadingPoint, std430.
struct ShadingPoint {
    std::int32_t info[4];  // corner count, two-sided, model, unused
    float corners[8][4];
    float position[3];
    float roughness;
    float normal[3];
    float fresnel0;
    float to_eye[3];
    float unused;
};
static_assert(sizeof(ShadingPoint) == 192, "contract_user.comp's std430 ShadingPoint");

void put(const Vec3& a, float* dst) {
    for (int k = 0; k < 3; ++k) dst[k] = static_cast<float>(a[k]);
}

ShadingPoint shading_point(const Case& c, int model) {
    ShadingPoint p{};
    p.info[0] = static_cast<std::int32_t>(c.light.vertices.size());
    p.info[1] = c.light.two_sided ? 1 : 0;
    p.info[2] = model;
    for (std::size_t k = 0; k < c.light.vertices.size(); ++k)
        put(c.light.vertices[k], p.corners[k]);
    put(c.p, p.position);
    put(c.n, p.normal);
    put(c.v, p.to_eye);
    const bool exponent = c.material.distribution == Distribution::Phong ||
                          c.material.distribution == Distribution::Blinn;
    p.roughness = static_cast<float>(exponent ? c.material.exponent : c.material.alpha);
    p.fresnel0 = static_cast<float>(c.material.f0);
    return p;
}

// Seeded random polygons per variant (microfacet_cases.hpp; phong takes blinn's exponents),
// only those the variant computes, so that the evaluator returns one result per case.
CaseSet user_cases(const UserVariant& u) {
    const Distribution from = u.dist == Distribution::Phong ? Distribution::Blinn : u.dist;
    CaseSet all = random_microfacet_polygons(4242 + u.model, kCasesPerVariant, from,
                                             std::string(to_string(u.dist)) + "-");
    CaseSet set;
    for (auto& c : all.cases) {
        c.material.distribution = u.dist;
        if (case_applies(variant(u.name), c)) set.cases.push_back(c);
    }
    return set;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string library(const std::vector<Variant>& variants) {
    std::string why;
    auto text = generate_library(variants, Language::Glsl, LibraryOptions{},
                                 [&](const Diagnostic& d) { why += d.message + "\n"; });
    INFO(why);
    REQUIRE(text);
    return *text;
}

// A quad light in the test shaders' own vertices q[8] (its first four corners).
const char* const kUserQuad =
    "vec3 q[8];\n    for (int i = 0; i < 8; ++i) q[i] = vec3(0.0);\n"
    "    q[0] = vec3(-1.0, -1.0, 2.0); q[1] = vec3(1.0, -1.0, 2.0);\n"
    "    q[2] = vec3(1.0, 1.0, 2.0); q[3] = vec3(-1.0, 1.0, 2.0);\n";

// The call of each light type's CONTRACT.md 5 function in the test shaders: its result r.
std::string es_call(const Variant& v) {
    const std::string name = std::string("arealight_") + to_string(v.light) + "_" + to_string(v.dist);
    switch (v.light) {
        case LightType::Polygon:
            return std::string(kUserQuad) + "    ArealightShading r = " + name + "(s, q, 4, true);\n";
        case LightType::Disk:
            return "ArealightShading r = " + name +
                   "(s, vec3(0.0, 0.0, 2.0), vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), true);\n";
        case LightType::Sphere:
            return "ArealightShading r = " + name + "(s, vec3(0.0, 0.0, 2.0), 0.5);\n";
        case LightType::Ellipsoid:
            return "vec3 ax[3];\n    ax[0] = vec3(0.5, 0.0, 0.0); ax[1] = vec3(0.0, 0.4, 0.0);\n"
                   "    ax[2] = vec3(0.0, 0.0, 0.3);\n    ArealightShading r = " + name +
                   "(s, vec3(0.0, 0.0, 2.0), ax);\n";
    }
    return "";
}

// The rest of a test compute shader after its includes: a surface s, `calls` (declaring
// the ArealightShading values), then o[0] = `result`.
std::string user_main(const std::string& calls,
                             const std::string& result = "vec4(r.diffuse, r.specular, 0.0, 0.0)") {
    return "layout(local_size_x = 1) in;\n"
           "layout(std430, binding = 7) buffer Out { vec4 o[]; };\n"
           "void main() {\n    ArealightSurface s;\n"
           "    s.p = vec3(0.0); s.n = vec3(0.0, 0.0, 1.0); s.v = vec3(0.0, 0.6, 0.8);\n"
           "    s.param = 0.3; s.f0 = 1.0;\n    " +
           calls + "    o[0] = " + result + ";\n}\n";
}

// A user's shader `text` (named `name`) compiled with `dir` as its include folder: its
// SPIR-V, or nullopt with glslang's messages, "FILE:LINE: message", added to `why`.
std::optional<std::vector<uint32_t>> compile_user(const ScratchFolder& dir, const std::string& text,
                                                  const std::string& name, std::string& why,
                                                  bool optimize = true) {
    CompileOptions options;
    options.includes = true;
    options.optimize = optimize;
    options.include_dirs = {dir / ""};
    return compile_shader(text, name, options, [&](const Diagnostic& d) {
        why += d.file + ":" + std::to_string(d.line) + ": " + d.message + "\n";
    });
}

// contract_user.comp compiled with `dir` as its include folder (which must hold
// contract_user_library.glsl) and run over `points`: 2 floats (diffuse, specular) per point.
std::vector<float> run_contract_user(const ScratchFolder& dir,
                                     const std::vector<ShadingPoint>& points,
                                     const std::vector<const Texture2D*>& textures) {
    const std::string shader = std::string(AREALIGHT_TEST_DATA) + "/contract_user.comp";
    std::string why;
    const DiagnosticConsumer diag = [&](const Diagnostic& d) {
        why += d.file + ":" + std::to_string(d.line) + ": " + d.message + "\n";
    };
    const auto spirv = compile_user(dir, read_text(shader), shader, why);
    INFO(why);
    REQUIRE(spirv);
    static auto runner = VulkanRunner::create("", diag);
    REQUIRE(runner);
    std::vector<float> out;
    REQUIRE(runner->run(*spirv, points.data(), points.size() * sizeof(ShadingPoint), points.size(),
                        out, 2, diag, nullptr, textures));
    REQUIRE(out.size() == 2 * points.size());
    return out;
}

std::uint32_t bits(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// Every point's diffuse and specular in `got` against the validation kernel's: the count
// of values whose bits differ, each named in the report.
int compare_bits(const std::vector<float>& got, const std::vector<ResultSet>& expected,
                 std::string& report) {
    int differing = 0;
    std::size_t point = 0;
    for (const auto& set : expected) {
        for (const auto& r : set.results) {
            const float want[2] = {static_cast<float>(*r.diffuse), static_cast<float>(*r.specular)};
            for (int q = 0; q < 2; ++q) {
                const float x = got[2 * point + q];
                if (bits(x) == bits(want[q])) continue;
                if (++differing <= 8)
                    report += fmt::format("{} {} {}: {:.9g}, eval {:.9g}\n", set.variant, r.id,
                                          q ? "specular" : "diffuse", x, want[q]);
            }
            ++point;
        }
    }
    return differing;
}

struct UserRun {
    std::vector<ShadingPoint> points;
    std::vector<const Texture2D*> textures;  // library order: binding AREALIGHT_BINDING + k
    std::vector<ResultSet> expected;         // Evaluator::run, vulkan backend, per variant
    std::vector<Variant> variants;
};

UserRun prepare() {
    UserRun run;
    for (const auto& u : kUserVariants) {
        const Variant v = variant(u.name);
        run.variants.push_back(v);
        const CaseSet cases = user_cases(u);
        REQUIRE(cases.cases.size() >= kCasesPerVariant / 2);
        for (const auto& c : cases.cases) run.points.push_back(shading_point(c, u.model));
        for (const Texture2D* t : variant_textures(v)) run.textures.push_back(t);
        run.expected.push_back(arealight::test::run(Backend::Vulkan, u.name, cases));
        REQUIRE(run.expected.back().results.size() == cases.cases.size());
    }
    return run;
}

// contract_user.comp over `dir`'s contract_user_library.glsl must give, bit for bit, the
// validation kernel's diffuse and specular at every point of `run`.
void check_contract_user(const ScratchFolder& dir, const UserRun& run) {
    const auto got = run_contract_user(dir, run.points, run.textures);
    std::string report;
    const int differing = compare_bits(got, run.expected, report);
    INFO(run.points.size() << " points, " << differing << " values differ in their bits\n"
                           << report);
    CHECK(differing == 0);
}

}  // namespace

TEST_CASE("a shader written against CONTRACT 5 alone gives arealight eval's values bit for bit",
          "[vulkan][library]") {
    const UserRun run = prepare();
    REQUIRE(run.textures.size() == 2);  // the ggx LTC matrix and amplitude
    ScratchFolder dir("contract_user");
    dir.write("contract_user_library.glsl", library(run.variants));
    check_contract_user(dir, run);
}

TEST_CASE(
    "two libraries included together, after a renderer's own real, rvec3 and AlCase, "
    "give the same values",
    "[vulkan][library]") {
    const UserRun run = prepare();
    ScratchFolder dir("contract_user_two");
    // Two libraries of distinct (light, dist): the types once, each function once.
    dir.write("ggx_phong.glsl", library({run.variants[0], run.variants[1]}));
    dir.write("beckmann_blinn.glsl", library({run.variants[2], run.variants[3]}));
    // Names the templates use before the library renames them, declared first and used after
    // both includes: a macro left defined (real -> double) or a type declared again breaks
    // the compile.
    dir.write("contract_user_library.glsl", R"(
struct AlCase { vec3 real; float rvec3; };
float real(float x) { return x; }
const vec3 rvec3 = vec3(1.0);
#include "ggx_phong.glsl"
#include "beckmann_blinn.glsl"
float renderer_uses_its_names() {
    AlCase c = AlCase(rvec3, real(2.0));
    return c.real.x + c.rvec3;
}
)");
    check_contract_user(dir, run);
}

TEST_CASE("a library included twice is harmless, and its feature macros say what it holds",
          "[vulkan][library]") {
    const UserRun run = prepare();
    ScratchFolder dir("contract_user_twice");
    dir.write("all.glsl", library(run.variants));
    // The second include is empty (the guard named from the contents); a shader can
    // test for each function, and a (light, dist) the library lacks has no macro.
    std::string user = "#include \"all.glsl\"\n#include \"all.glsl\"\n";
    for (const auto& v : run.variants) {
        std::string macro = std::string("AREALIGHT_HAS_POLYGON_") + to_string(v.dist);
        for (auto& ch : macro) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        user += "#ifndef " + macro + "\n#error " + macro + " missing\n#endif\n";
    }
    user += "#ifdef AREALIGHT_HAS_SPHERE_GGX\n#error a sphere function nobody asked for\n#endif\n";
    dir.write("contract_user_library.glsl", user);
    check_contract_user(dir, run);
    const std::string text = library(run.variants);
    CHECK(text.find("#ifndef AREALIGHT_LIBRARY_") != std::string::npos);
    // Named from the contents: another library's guard differs.
    const std::string other = library({run.variants[0]});
    auto guard = [](const std::string& t) {
        const auto at = t.find("#ifndef AREALIGHT_LIBRARY_");
        return t.substr(at, t.find('\n', at) - at);
    };
    INFO(guard(text) << " / " << guard(other));
    CHECK(guard(text) != guard(other));
}

TEST_CASE("a library holds one variant per light type and distribution", "[library]") {
    std::string why;
    const auto text = generate_library({variant("dist=ggx,method=ltc,light=polygon"),
                                        variant("dist=ggx,method=pearson,light=polygon")},
                                       Language::Glsl, LibraryOptions{},
                                       [&](const Diagnostic& d) { why += d.message; });
    INFO(why);
    CHECK_FALSE(text);
    CHECK(why.find("arealight_polygon_ggx") != std::string::npos);
}

// GLSL ES 3.10 (the mobile target of Heitz et al. 2016's LTC) has no double, no C-style
// array initialisers and only literal layout ids: every family that has an fp32 variant
// (its default keys, at fp32 where the default is fp64) must compile there as a user's
// `#version 310 es` compute shader that includes its library, tables and all.
TEST_CASE("every fp32 family's library compiles as GLSL ES 3.10", "[library][es]") {
    const std::vector<Variant> families = fp32_families();
    REQUIRE(families.size() >= 40);
    ScratchFolder dir("library_es");
    for (const Variant& v : families) {
        dir.write("es_library.glsl", library({v}));
        const std::string shader =
            "#version 310 es\nprecision highp float;\nprecision highp int;\n"
            "#include \"es_library.glsl\"\n" + user_main(es_call(v));
        std::string why;
        // Validated, not optimized: whether the front end takes the library is the question.
        const auto spirv = compile_user(dir, shader, dir / "es.comp", why, false);
        INFO(canonical_name(v) << "\n" << why);
        CHECK(spirv);
    }
}

// GLSL 4.50's words (keywords, types, built-in functions, preprocessor) that the
// templates use: a renderer cannot #define these without breaking its own shader.
const std::set<std::string> kGlslWords = {
    "abs", "acos", "all", "any", "asin", "atan", "binding", "bool", "break", "buffer", "ceil",
    "clamp", "const", "continue", "cos", "cross", "define", "defined", "do", "dot", "double",
    "dvec2", "dvec3", "dvec4", "elif", "else", "enable", "endif", "error", "exp", "exp2",
    "extension", "false", "float", "float16_t", "floor", "fma", "for", "fract", "frexp",
    "f16vec2", "f16vec3", "f16vec4", "highp", "if", "ifdef", "ifndef", "in", "inout", "int",
    "inversesqrt", "isinf", "isnan", "layout", "ldexp", "length", "line", "log", "log2",
    "main", "max", "min", "mix", "mod", "normalize", "out", "pow", "precise", "return",
    "round", "sampler2D", "set", "sign", "sin", "sqrt", "std430", "step", "struct", "tan",
    "texture", "textureLod", "true", "uint", "uniform", "unroll", "vec2", "vec3", "vec4",
    "void", "while"};

bool swizzle_like(const std::string& id) {
    if (id.size() > 4) return false;
    for (const std::string set : {"xyzw", "rgba", "stpq"}) {
        bool all = true;
        for (char c : id) all = all && set.find(c) != std::string::npos;
        if (all) return true;
    }
    return false;
}

// The names of a variant's templates, comments and #line/#extension/#error lines left out.
std::set<std::string> template_names(const Variant& v) {
    std::set<std::string> names;
    const std::regex comment(R"(//[^\n]*|/\*[\s\S]*?\*/|\n[ \t]*#[ \t]*(line|extension|error)[^\n]*)");
    const std::regex word(R"((^|[^\w.])([A-Za-z_]\w*))");
    for (const auto& path : variant_templates(v, Language::Glsl)) {
        const std::string* text = template_text(path);
        REQUIRE(text);
        const std::string code = std::regex_replace("\n" + *text, comment, " ");
        for (auto it = std::sregex_iterator(code.begin(), code.end(), word);
             it != std::sregex_iterator(); ++it)
            names.insert((*it)[2].str());
    }
    return names;
}

// A renderer's shader may #define any name before the include (`#define N 16`): every
// name of the templates that is not GLSL's own, not the contract's (CONTRACT.md 5:
// Arealight*, arealight_*, AREALIGHT_*, the members p, n, v, param, f0, diffuse,
// specular) and not swizzle-shaped (x, rgb: a struct member so spelled is written after
// a dot like a swizzle and cannot be told from one) is #defined to an unknown name, and
// the library must still compile and give the same SPIR-V as without them.
TEST_CASE("a renderer's macros named like the library's internal names cannot reach it",
          "[library]") {
    const std::set<std::string> contract = {"p", "n", "v", "param", "f0", "diffuse", "specular",
                                            "kernel_main"};
    ScratchFolder dir("library_macros");
    for (const char* name :
         {"dist=phong,method=lorentz,light=polygon", "dist=ggx,method=ltc,light=polygon",
          "dist=ggx,method=ltc,light=sphere,table=fit",
          "dist=beckmann,method=exact,light=disk,precision=fp32",
          "dist=blinn,method=pearson,light=ellipsoid", "dist=phong,method=exact,light=sphere",
          "dist=ggx,method=mrp,light=polygon"}) {
        const Variant v = variant(name);
        dir.write("lib.glsl", library({v}));
        std::string defines, undefines;
        int count = 0;
        for (const auto& id : template_names(v)) {
            if (kGlslWords.count(id) || contract.count(id) || swizzle_like(id) ||
                id.rfind("Arealight", 0) == 0 || id.rfind("arealight_", 0) == 0 ||
                id.rfind("AREALIGHT_", 0) == 0 || id.rfind("GL_", 0) == 0 ||
                id.rfind("gl_", 0) == 0)
                continue;
            defines += "#define " + id + " renderer_macro_" + std::to_string(count++) + "\n";
            undefines += "#undef " + id + "\n";
        }
        INFO(name << ": " << count << " names defined before the include");
        CHECK(count > 50);
        const std::string body = "#version 450\n#include \"lib.glsl\"\n" + user_main(es_call(v));
        // Unoptimized modules keep every name glslang saw (OpName), so equal modules also
        // say that no renderer macro renamed anything.
        auto compile = [&](const std::string& text) {
            std::string why;
            auto spirv = compile_user(dir, text, dir / "user.comp", why, false);
            INFO(why);
            REQUIRE(spirv);
            return *spirv;
        };
        // Undefined again after the include: the test's own main() uses some of the names.
        const auto at = body.find("#include");
        const auto after = body.find('\n', at) + 1;
        const std::string user = body.substr(0, at) + defines + body.substr(at, after - at) +
                                 undefines + body.substr(after);
        CHECK(compile(user) == compile(body));
    }
}

// Polygon and sphere GGX LTC read the same two tables (the distribution's): one library
// of both declares and binds each once, the sphere's names aliasing the polygon's, and
// tables.json lists each once with the sphere under "also"; a third function of another
// distribution takes the next bindings. The library compiles (every alias resolves).
TEST_CASE("within one library, identical tables share one sampler", "[library]") {
    const std::vector<Variant> variants = {variant("dist=ggx,method=ltc,light=polygon"),
                                           variant("dist=ggx,method=ltc,light=sphere"),
                                           variant("dist=beckmann,method=ltc,light=disk")};
    const std::string text = library(variants);
    std::size_t declared = 0;
    for (auto at = text.find("uniform sampler2D"); at != std::string::npos;
         at = text.find("uniform sampler2D", at + 1))
        ++declared;
    CHECK(declared == 4);
    CHECK(text.find("#define al_sphere_ggx_ltc_matrix al_polygon_ggx_ltc_matrix") !=
          std::string::npos);
    const auto plan = library_samplers(variants);
    REQUIRE(plan.size() == 6);
    CHECK(plan[2].shares == 0);
    CHECK(plan[3].shares == 1);
    CHECK(plan[4].binding_offset == 2);
    CHECK(plan[5].binding_offset == 3);

    ScratchFolder dir("library_shared_tables");
    std::string why;
    REQUIRE(write_library_tables(variants, dir / "tables",
                                 [&](const Diagnostic& d) { why += d.message; }));
    std::ifstream in(dir / "tables/tables.json");
    const auto manifest = nlohmann::json::parse(in);
    const auto& tables = manifest.at("tables");
    REQUIRE(tables.size() == 4);
    CHECK(tables[0].at("also").at(0).at("sampler") == "al_sphere_ggx_ltc_matrix");
    CHECK(tables[2].at("binding_offset") == 2);
    CHECK_FALSE(tables[2].contains("also"));

    dir.write("two.glsl", text);
    const std::string shader = "#version 450\n#include \"two.glsl\"\n" +
                               user_main(es_call(variant("dist=ggx,method=ltc,light=sphere")));
    const auto spirv = compile_user(dir, shader, dir / "two.comp", why);
    INFO(why);
    CHECK(spirv);
}

// Two LTC libraries generated separately and included into one shader: the first takes
// bindings 0 and 1 (AREALIGHT_BINDING + 0, + 1 where defined), the second the next slot,
// 8 and 9, so no table is bound twice (CONTRACT.md 5); read from the SPIR-V's decorations.
TEST_CASE("two separately generated LTC libraries bind distinct tables by default",
          "[library]") {
    ScratchFolder dir("library_two_tables");
    dir.write("g.glsl", library({variant("dist=ggx,method=ltc,light=polygon")}));
    dir.write("b.glsl", library({variant("dist=beckmann,method=ltc,light=polygon")}));
    auto bindings = [&](const std::string& prolog) {
        const std::string shader =
            "#version 450\n" + prolog + "#include \"g.glsl\"\n#include \"b.glsl\"\n" +
            user_main(std::string(kUserQuad) +
                          "    ArealightShading a = arealight_polygon_ggx(s, q, 4, true);\n"
                          "    ArealightShading b = arealight_polygon_beckmann(s, q, 4, true);\n",
                      "vec4(a.diffuse, a.specular, b.diffuse, b.specular)");
        std::string why;
        // Unoptimized: keeps the samplers' names.
        const auto spirv = compile_user(dir, shader, dir / "two.comp", why, false);
        INFO(why);
        REQUIRE(spirv);
        std::map<std::string, int> found;
        const std::string text = disassemble(*spirv);
        const std::regex decoration(R"(OpDecorate %(al_\w+_ltc_\w+) Binding (\d+))");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), decoration);
             it != std::sregex_iterator(); ++it)
            found[(*it)[1].str()] = std::stoi((*it)[2].str());
        return found;
    };
    const std::map<std::string, int> plain = {
        {"al_polygon_ggx_ltc_matrix", 0}, {"al_polygon_ggx_ltc_amplitude", 1},
        {"al_polygon_beckmann_ltc_matrix", 8}, {"al_polygon_beckmann_ltc_amplitude", 9}};
    CHECK(bindings("") == plain);
    const std::map<std::string, int> moved = {
        {"al_polygon_ggx_ltc_matrix", 5}, {"al_polygon_ggx_ltc_amplitude", 6},
        {"al_polygon_beckmann_ltc_matrix", 13}, {"al_polygon_beckmann_ltc_amplitude", 20}};
    CHECK(bindings("#define AREALIGHT_BINDING 5\n"
                   "#define AREALIGHT_POLYGON_BECKMANN_LTC_AMPLITUDE_BINDING 20\n") == moved);
}

}  // namespace arealight::test
