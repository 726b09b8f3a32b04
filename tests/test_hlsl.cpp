// The HLSL library (CONTRACT.md 5, --lang hlsl): the same templates through the HLSL
// language layer (generator/stitcher.cpp). Every fp32 family's library compiles under
// glslang's HLSL front end in a shader written against the contract's HLSL form alone;
// its validation kernel (templates/library/kernel.hlsl) computes on lavapipe what the
// GLSL kernel computes; its tables take literal registers from the same slots as the
// GLSL bindings.
#include <catch2/catch.hpp>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"
#include "degenerate_cases.hpp"
#include "eval_support.hpp"
#include "fp32_families.hpp"
#include "microfacet_cases.hpp"
#include "scratch_folder.hpp"

namespace arealight::test {
namespace {

// The HLSL kernel against the GLSL kernel: both run the same fp32 math on one driver,
// so they differ only where the two front ends order an operation differently.
constexpr double kHlslGlslTol = 1e-5;  // relative, floor 1e-3 (rel_err)

std::string hlsl_library(const std::vector<Variant>& variants) {
    std::string why;
    auto text = generate_library(variants, Language::Hlsl, LibraryOptions{},
                                 [&](const Diagnostic& d) { why += d.message + "\n"; });
    INFO(why);
    REQUIRE(text);
    return *text;
}

// A quad in the shader's own q[8] (its first four corners).
const char* const kHlslQuad =
    "float3 q[8];\n    for (int i = 0; i < 8; ++i) q[i] = float3(0.0, 0.0, 0.0);\n"
    "    q[0] = float3(-1.0, -1.0, 2.0); q[1] = float3(1.0, -1.0, 2.0);\n"
    "    q[2] = float3(1.0, 1.0, 2.0); q[3] = float3(-1.0, 1.0, 2.0);\n";

// The call of each light type's function as CONTRACT.md 5's HLSL form spells it: r.
std::string hlsl_call(const Variant& v) {
    const std::string name = std::string("arealight_") + to_string(v.light) + "_" + to_string(v.dist);
    switch (v.light) {
        case LightType::Polygon:
            return std::string(kHlslQuad) + "    ArealightShading r = " + name + "(s, q, 4, true);\n";
        case LightType::Disk:
            return "ArealightShading r = " + name +
                   "(s, float3(0.0, 0.0, 2.0), float3(1.0, 0.0, 0.0), float3(0.0, 1.0, 0.0), "
                   "true);\n";
        case LightType::Sphere:
            return "ArealightShading r = " + name + "(s, float3(0.0, 0.0, 2.0), 0.5);\n";
        case LightType::Ellipsoid:
            return "float3 ax[3];\n    ax[0] = float3(0.5, 0.0, 0.0); ax[1] = float3(0.0, 0.4, "
                   "0.0);\n    ax[2] = float3(0.0, 0.0, 0.3);\n    ArealightShading r = " + name +
                   "(s, float3(0.0, 0.0, 2.0), ax);\n";
    }
    return "";
}

// A renderer's HLSL compute shader around `includes`: a surface s, `calls`, o[0] = result.
std::string hlsl_user(const std::string& includes, const std::string& calls,
                      const std::string& result = "float4(r.diffuse, r.specular, 0.0, 0.0)") {
    return includes +
           "RWStructuredBuffer<float4> o : register(u0, space1);\n"
           "[numthreads(1, 1, 1)]\nvoid shade_main(uint3 id : SV_DispatchThreadID) {\n"
           "    ArealightSurface s;\n"
           "    s.p = float3(0.0, 0.0, 0.0); s.n = float3(0.0, 0.0, 1.0);\n"
           "    s.v = float3(0.0, 0.6, 0.8); s.param = 0.3; s.f0 = 1.0;\n    " +
           calls + "    o[0] = " + result + ";\n}\n";
}

std::optional<std::vector<uint32_t>> compile_hlsl_user(const ScratchFolder& dir,
                                                       const std::string& text, std::string& why,
                                                       bool optimize = true) {
    CompileOptions options;
    options.language = SourceLanguage::Hlsl;
    options.source_entry = "shade_main";
    options.includes = true;
    options.optimize = optimize;
    options.include_dirs = {dir / ""};
    return compile_shader(text, dir / "user.comp.hlsl", options, [&](const Diagnostic& d) {
        why += d.file + ":" + std::to_string(d.line) + ": " + d.message + "\n";
    });
}

Evaluator& hlsl_evaluator() {
    static std::unique_ptr<Evaluator> e = [] {
        EvalOptions opt;
        opt.language = Language::Hlsl;
        opt.spirv_cache = spirv_cache_folder();
        std::string why;
        auto made = Evaluator::create(opt, [&](const Diagnostic& d) { why += d.message; });
        INFO(why);
        REQUIRE(made);
        return made;
    }();
    return *e;
}

// The first one-argument vector constructor (vec3(x), float3(x), al_..._rvec3(x)) outside
// comments and preprocessor lines, which dxc refuses; empty when there is none.
std::string single_argument_constructor(const std::string& text) {
    const std::regex comment(R"(//[^\n]*|/\*[\s\S]*?\*/|\n[ \t]*#[^\n]*)");
    const std::string code = std::regex_replace(text, comment, "\n");
    const std::regex call(R"(\b((float|int|uint|bool|vec|ivec|uvec|bvec)[234]|al_\w+_[rh]vec[234])\()");
    for (auto it = std::sregex_iterator(code.begin(), code.end(), call);
         it != std::sregex_iterator(); ++it) {
        std::size_t k = static_cast<std::size_t>(it->position() + it->length());
        int depth = 1;
        bool comma = false;
        for (; k < code.size() && depth > 0; ++k) {
            depth += code[k] == '(' ? 1 : code[k] == ')' ? -1 : 0;
            comma = comma || (code[k] == ',' && depth == 1);
        }
        if (!comma) return code.substr(static_cast<std::size_t>(it->position()), 60);
    }
    return "";
}

}  // namespace

TEST_CASE("every fp32 family's library compiles as HLSL in a shader written to CONTRACT.md 5",
          "[library][hlsl]") {
    const std::vector<Variant> families = fp32_families();
    REQUIRE(families.size() >= 40);
    // The check itself: the GLSL form's splats and conversions are what it finds.
    CHECK(single_argument_constructor("// vec3(0.0)\nfloat3 a = float3(1.0, 2.0, 3.0);").empty());
    CHECK_FALSE(single_argument_constructor("x = vec3(f(1.0, 2.0));").empty());
    CHECK_FALSE(single_argument_constructor("y = al_polygon_ggx_rvec3(c.v);").empty());
    ScratchFolder dir("library_hlsl");
    for (const Variant& v : families) {
        const std::string text = hlsl_library({v});
        // dxc takes no one-argument vector constructor: the layer writes casts instead.
        INFO(canonical_name(v));
        CHECK(single_argument_constructor(text) == "");
        dir.write("lib.hlsl", text);
        // Legalized and validated, not optimized: whether glslang's HLSL front end takes the
        // library is the question here (the kernel test below runs the optimized modules).
        std::string why;
        const auto spirv = compile_hlsl_user(dir, hlsl_user("#include \"lib.hlsl\"\n", hlsl_call(v)),
                                             why, false);
        INFO(canonical_name(v) << "\n" << why);
        CHECK(spirv);
    }
}

TEST_CASE("the HLSL library refuses fp64 and fp16 variants and AREALIGHT_REGISTER",
          "[library][hlsl]") {
    CHECK_FALSE(language_supports(Language::Hlsl, variant("dist=ggx,method=exact,light=polygon")));
    CHECK_FALSE(language_supports(Language::Hlsl,
                                  variant("dist=ggx,method=ltc,light=polygon,precision=fp16")));
    CHECK(language_supports(Language::Hlsl, variant("dist=ggx,method=ltc,light=polygon")));
    std::string diag;
    const auto refused = build_hlsl_spirv(variant("dist=ggx,method=exact,light=polygon"), true,
                                          [&](const Diagnostic& d) { diag += d.message; });
    CHECK_FALSE(refused);
    CHECK(diag.find("fp32 only") != std::string::npos);
    ScratchFolder dir("library_hlsl_register");
    dir.write("lib.hlsl", hlsl_library({variant("dist=ggx,method=ltc,light=polygon")}));
    std::string why;
    const auto spirv = compile_hlsl_user(
        dir, hlsl_user("#define AREALIGHT_REGISTER 4\n#include \"lib.hlsl\"\n",
                       hlsl_call(variant("dist=ggx,method=ltc,light=polygon"))),
        why);
    INFO(why);
    CHECK_FALSE(spirv);
    CHECK(why.find("_REGISTER macro of each table") != std::string::npos);
}

// Two libraries with tables take registers t0/t1 and t8/t9 (one combined image sampler
// each: glslang folds the SamplerState into its texture); a table's own macro wins, and
// AREALIGHT_SPACE moves them all to another descriptor set.
TEST_CASE("HLSL tables: literal registers by slot, the same bindings as GLSL's",
          "[library][hlsl]") {
    ScratchFolder dir("library_hlsl_tables");
    dir.write("g.hlsl", hlsl_library({variant("dist=ggx,method=ltc,light=polygon")}));
    dir.write("b.hlsl", hlsl_library({variant("dist=beckmann,method=ltc,light=polygon")}));
    auto bindings = [&](const std::string& prolog) {
        const std::string shader = hlsl_user(
            prolog + "#include \"g.hlsl\"\n#include \"b.hlsl\"\n",
            std::string(kHlslQuad) +
                "    ArealightShading a = arealight_polygon_ggx(s, q, 4, true);\n"
                "    ArealightShading b = arealight_polygon_beckmann(s, q, 4, true);\n",
            "float4(a.diffuse, a.specular, b.diffuse, b.specular)");
        std::string why;
        const auto spirv = compile_hlsl_user(dir, shader, why, false);
        INFO(why);
        REQUIRE(spirv);
        const std::string text = disassemble(*spirv);
        std::map<std::string, std::pair<int, int>> found;  // name -> (set, binding)
        const std::regex binding(R"(OpDecorate %(al_\w+_ltc_\w+)_texture Binding (\d+))");
        const std::regex set(R"(OpDecorate %(al_\w+_ltc_\w+)_texture DescriptorSet (\d+))");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), binding);
             it != std::sregex_iterator(); ++it)
            found[(*it)[1].str()].second = std::stoi((*it)[2].str());
        for (auto it = std::sregex_iterator(text.begin(), text.end(), set);
             it != std::sregex_iterator(); ++it)
            found[(*it)[1].str()].first = std::stoi((*it)[2].str());
        CHECK(text.find("OpTypeSampledImage") != std::string::npos);
        CHECK(text.find("_sampler") == std::string::npos);
        return found;
    };
    const std::map<std::string, std::pair<int, int>> plain = {
        {"al_polygon_ggx_ltc_matrix", {0, 0}}, {"al_polygon_ggx_ltc_amplitude", {0, 1}},
        {"al_polygon_beckmann_ltc_matrix", {0, 8}}, {"al_polygon_beckmann_ltc_amplitude", {0, 9}}};
    CHECK(bindings("") == plain);
    const std::map<std::string, std::pair<int, int>> moved = {
        {"al_polygon_ggx_ltc_matrix", {3, 0}}, {"al_polygon_ggx_ltc_amplitude", {3, 1}},
        {"al_polygon_beckmann_ltc_matrix", {3, 8}},
        {"al_polygon_beckmann_ltc_amplitude", {3, 20}}};
    CHECK(bindings("#define AREALIGHT_SPACE 3\n"
                   "#define AREALIGHT_POLYGON_BECKMANN_LTC_AMPLITUDE_REGISTER 20\n") == moved);
}

TEST_CASE("the HLSL kernel computes what the GLSL kernel computes, every fp32 family",
          "[hlsl][vulkan]") {
    // Seeded polygons of every distribution, curved lights like them, and the degenerate
    // set (v = n, axis-aligned lights, fp32-exact coordinates).
    CaseSet cases;
    for (Distribution d :
         {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        const Distribution from = d == Distribution::Phong ? Distribution::Blinn : d;
        CaseSet part = random_microfacet_polygons(77, 12, from, std::string(to_string(d)) + "-");
        for (auto& c : part.cases) c.material.distribution = d;
        cases.cases.insert(cases.cases.end(), part.cases.begin(), part.cases.end());
    }
    const CaseSet curved = curved_cases_like(cases, 78);
    cases.cases.insert(cases.cases.end(), curved.cases.begin(), curved.cases.end());
    const CaseSet& degenerate = degenerate_cases();
    cases.cases.insert(cases.cases.end(), degenerate.cases.begin(), degenerate.cases.end());
    std::size_t compared = 0;
    for (const Variant& v : fp32_families()) {
        std::string why;
        auto glsl = evaluator(Backend::Vulkan).run(v, cases, [&](const Diagnostic& d) {
            why += d.message;
        });
        auto hlsl = hlsl_evaluator().run(v, cases, [&](const Diagnostic& d) { why += d.message; });
        INFO(canonical_name(v) << ": " << why);
        REQUIRE(glsl);
        REQUIRE(hlsl);
        REQUIRE(glsl->results.size() == hlsl->results.size());
        double worst = 0;
        std::string where;
        for (std::size_t i = 0; i < glsl->results.size(); ++i) {
            const CaseResult &g = glsl->results[i], &h = hlsl->results[i];
            auto track = [&](const char* q, const std::optional<double>& x,
                             const std::optional<double>& y) {
                if (!x || !y || rel_err(*y, *x) <= worst) return;
                worst = rel_err(*y, *x);
                where = g.id + " " + q + ": glsl " + std::to_string(*x) + " hlsl " +
                        std::to_string(*y);
            };
            track("diffuse", g.diffuse, h.diffuse);
            track("specular", g.specular, h.specular);
            track("ndf", g.ndf, h.ndf);
            track("moment", g.moment, h.moment);
        }
        INFO("worst relative difference " << worst << " at " << where);
        CHECK(worst <= kHlslGlslTol);
        compared += glsl->results.size();
    }
    CHECK(compared > 1000);
}

}  // namespace arealight::test
