// Stitching: exact #line provenance (golden text), determinism, and compiler
// errors that name the template file, its line and the variant.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "arealight/evaluator.hpp"
#include "arealight/generator.hpp"

using namespace arealight;

namespace {

Variant parse(const std::string& name) {
    auto v = parse_variant(name, {});
    REQUIRE(v);
    return *v;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

}  // namespace

TEST_CASE("stitched GLSL of a small variant equals the reviewed golden text", "[generator]") {
    const Variant v = parse("dist=phong,method=point,light=polygon,verts=4");
    const std::string text = generate_source(v, Language::Glsl);
    std::ifstream golden(AREALIGHT_TEST_DATA "/golden/phong_point_polygon_verts4.comp");
    REQUIRE(golden);
    std::stringstream expected;
    expected << golden.rdbuf();
    CHECK(text == expected.str());
    CHECK(text == generate_source(v, Language::Glsl));  // deterministic
}

TEST_CASE("every template chunk is bracketed by #line markers", "[generator]") {
    const Variant v = parse("dist=phong,method=exact,light=polygon");
    const auto lines = lines_of(generate_source(v, Language::Glsl));
    REQUIRE(lines.size() > 3);
    CHECK(lines[0] == "#version 450");
    CHECK(lines[1] == "#extension GL_GOOGLE_cpp_style_line_directive : enable");
    // Each template starts at its own line 1, and the marker after it points at
    // the physical line that follows in the generated text.
    const auto files = variant_templates(v, Language::Glsl);
    std::size_t next = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].rfind("#line ", 0) != 0) continue;
        if (lines[i].find("\"templates/") != std::string::npos) {
            REQUIRE(next < files.size());
            CHECK(lines[i] == "#line 1 \"" + files[next] + "\"");
            // Line 1 of the template is the next physical line.
            CHECK(lines[i + 1] == lines_of(*template_text(files[next]))[0]);
            ++next;
        } else {
            INFO("marker at physical line " << i + 1 << ": " << lines[i]);
            CHECK(lines[i] == "#line " + std::to_string(i + 2) + " \"arealight-generated\"");
        }
    }
    CHECK(next == files.size());
}

TEST_CASE("a broken template is reported at its file and line, with the variant", "[generator]") {
    const Variant v = parse("dist=phong,method=exact,light=polygon");
    std::string broken = *template_text("templates/dist/phong.glsl");
    // Line 4 of the template becomes an undeclared identifier.
    auto lines = lines_of(broken);
    REQUIRE(lines.size() > 5);
    lines[3] = "float al_broken() { return undeclared_thing; }";
    broken.clear();
    for (auto& l : lines) broken += l + "\n";
    const std::string glsl = generate_source(v, Language::Glsl, [&](const std::string& path) {
        return path == "templates/dist/phong.glsl" ? &broken : template_text(path);
    });
    std::vector<Diagnostic> diags;
    auto spv = build_spirv(v, glsl, true, [&](const Diagnostic& d) { diags.push_back(d); });
    CHECK_FALSE(spv);
    REQUIRE_FALSE(diags.empty());
    INFO("first diagnostic: " << diags[0].file << ":" << diags[0].line << ": " << diags[0].message);
    CHECK(diags[0].file == "templates/dist/phong.glsl");
    CHECK(diags[0].line == 4);
    CHECK(diags[0].message.find("dist=phong,method=exact,light=polygon") != std::string::npos);
    CHECK(diags[0].message.find("undeclared_thing") != std::string::npos);
}

TEST_CASE("Gauss-Legendre rules integrate polynomials of degree 2n-1 exactly", "[generator]") {
    for (int n : {6, 8, 12, 16, 24}) {
        std::vector<double> x, w;
        gauss_legendre(n, x, w);
        for (int deg = 0; deg <= 2 * n - 1; ++deg) {
            double sum = 0;
            for (int i = 0; i < n; ++i) sum += w[i] * std::pow(x[i], deg);
            const double exact = deg % 2 ? 0.0 : 2.0 / (deg + 1);
            INFO("n " << n << " degree " << deg << " sum " << sum);
            CHECK(std::abs(sum - exact) <= 1e-14);
        }
    }
}

TEST_CASE("a variant stitches the library types, common, its family's templates, the light's "
          "library entry, then the kernel",
          "[generator]") {
    // Today's lists, as the family table gives them.
    const auto exact =
        variant_templates(parse("dist=phong,method=exact,light=polygon"), Language::Glsl);
    CHECK(exact == std::vector<std::string>{
                       "templates/library/types.glsl", "templates/common/common.glsl",
                       "templates/dist/phong.glsl", "templates/method/phong_edge.glsl",
                       "templates/method/phong_edge_rule.glsl", "templates/method/exact_phong.glsl",
                       "templates/method/phong_boundary.glsl",
                       "templates/light/polygon.glsl", "templates/light/polygon_methods.glsl",
                       "templates/library/polygon.glsl", "templates/library/kernel.glsl"});
    CHECK(variant_templates(parse("dist=phong,method=arvo,light=polygon,verts=4"), Language::Cpp) ==
          std::vector<std::string>{"templates/library/types.glsl", "templates/common/common.glsl",
                                   "templates/dist/phong.glsl", "templates/method/phong_edge.glsl",
                                   "templates/method/arvo_phong.glsl", "templates/light/polygon.glsl",
                                   "templates/light/polygon_methods.glsl",
                                   "templates/library/polygon.glsl"});
    CHECK(variant_templates(parse("dist=phong,method=pearson,light=polygon,fit=paper"),
                            Language::Glsl)[8] == "templates/method/peak_phong.glsl");

    // Every family's templates exist, in its row's order, for both languages.
    for (const auto& v : enumerate_variants()) {
        const VariantFamily* family = find_family(v);
        REQUIRE(family);
        std::vector<std::string> want = {"templates/library/types.glsl", "templates/common/common.glsl"};
        // A key value's parts first (table=fit: its closed form), then the row's own.
        for (const auto& part : family->parts)
            if (variant_matches(v, part.key + "=" + part.value))
                for (const auto& t : part.templates) want.push_back("templates/" + t);
        for (const auto& t : family->templates) want.push_back("templates/" + t);
        // The light's entry: a polygon's own; a curved light's ellipse, its proxy
        // polygon (used by the polygon methods), then its own reduction.
        if (v.light == LightType::Polygon) {
            want.push_back("templates/library/polygon.glsl");
        } else {
            want.push_back("templates/light/ellipse_record.glsl");
            want.push_back("templates/light/spin_polygon.glsl");
            want.push_back(std::string("templates/library/") + to_string(v.light) + ".glsl");
        }
        INFO(canonical_name(v));
        CHECK(variant_templates(v, Language::Cpp) == want);
        want.push_back("templates/library/kernel.glsl");
        CHECK(variant_templates(v, Language::Glsl) == want);
        for (const auto& path : want) {
            INFO(path);
            CHECK(template_text(path) != nullptr);
        }
    }
}
