// Scene-driven selection (CONTRACT.md 7): one variant per (light, distribution) that occurs,
// specialised to the scene, chosen by a measured table. The ranking tests use a small table
// made here, so that no expected value is copied from the shipped data under test; the
// shipped data is checked only for invariants.
#include <algorithm>
#include <catch2/catch.hpp>

#include "arealight/scene_select.hpp"

using namespace arealight;
using Catch::Matchers::Contains;

namespace {

Light polygon(std::size_t n, bool two_sided = false) {
    Light l;
    l.type = LightType::Polygon;
    l.two_sided = two_sided;
    const double pi = 3.14159265358979323846;
    for (std::size_t i = 0; i < n; ++i)
        l.vertices.push_back({std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 2.0});
    return l;
}

Light sphere() {
    Light l;
    l.type = LightType::Sphere;
    l.center = {0, 0, 3};
    l.radius = 0.5;
    return l;
}

Material material(Distribution d, double param) {
    Material m;
    m.distribution = d;
    (d == Distribution::Phong || d == Distribution::Blinn ? m.exponent : m.alpha) = param;
    return m;
}

MeasuredVariant row(const std::string& name, double specular, std::size_t x86,
                    double diffuse = 1e-7) {
    MeasuredVariant m;
    m.variant = name;
    m.rel_l2 = {{"diffuse", diffuse}, {"specular", specular}};
    m.error_rel_l2 = specular;
    m.x86_instructions = x86;
    m.report = "hand-made";
    return m;
}

// Made up for these tests: the ranking, not the data, is what they check.
QualityData hand_table() {
    QualityData q;
    q.variants = {
        row("dist=ggx,method=exact,light=polygon", 1e-4, 20000),
        row("dist=ggx,method=ltc,light=polygon", 0.012, 4800),
        row("dist=ggx,method=ltc,light=polygon,horizon=proxy", 0.013, 4500),
        // Cheapest and accurate on specular, but its diffuse error disqualifies it.
        row("dist=ggx,method=point,light=polygon", 0.011, 1600, 0.5),
        row("dist=phong,method=lorentz,light=polygon", 0.008, 5900),
        row("dist=phong,method=pearson,light=polygon", 0.004, 7500),
        // Measured on quads only (verts=4): not comparable, never ranked.
        row("dist=phong,method=arvo,light=polygon,verts=4", 1e-9, 100),
    };
    return q;
}

struct Selected {
    std::optional<std::vector<SelectedVariant>> variants;
    std::vector<Diagnostic> diags;
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        if (variants)
            for (const auto& s : *variants) out.push_back(canonical_name(s.variant));
        return out;
    }
    std::string all() const {
        std::string s;
        for (const auto& d : diags)
            s += std::string(to_string(d.severity)) + ": " + d.message + "\n";
        for (const auto& n : names()) s += "selected " + n + "\n";
        return s.empty() ? "(nothing)" : s;
    }
    std::size_t count(Severity sev) const {
        return std::count_if(diags.begin(), diags.end(),
                             [&](const Diagnostic& d) { return d.severity == sev; });
    }
};

Selected select(const Scene& scene, const QualityData& q = hand_table()) {
    Selected s;
    s.variants = select_variants(scene, q, [&](const Diagnostic& d) { s.diags.push_back(d); });
    return s;
}

Scene scene_of(std::vector<Light> lights, std::vector<Material> materials) {
    Scene s;
    s.lights = std::move(lights);
    s.materials = std::move(materials);
    return s;
}

bool enumerated(const Variant& v) {
    const auto all = enumerate_variants();
    return std::find(all.begin(), all.end(), v) != all.end();
}

}  // namespace

TEST_CASE("select: a GGX polygon scene yields exactly one GGX polygon variant") {
    Scene s = scene_of({polygon(4), polygon(3)},
                       {material(Distribution::Ggx, 0.3), material(Distribution::Ggx, 0.05)});
    s.quality.method = "ltc";
    const Selected sel = select(s);
    INFO(sel.all());
    REQUIRE(sel.variants);
    // GGX's ltc family offers sided=any and verts=8 only: specialisation keeps them.
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=ltc,light=polygon"});
    CHECK(sel.variants->at(0).variant.sided == Sided::Any);
    CHECK(sel.variants->at(0).variant.verts == 8);
    CHECK(enumerated(sel.variants->at(0).variant));
}

TEST_CASE("select: sided and verts follow the scene where the family offers them") {
    const Material phong = material(Distribution::Phong, 40);
    Scene one = scene_of({polygon(3), polygon(3)}, {phong});
    one.quality.method = "arvo";
    Selected sel = select(one);
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=phong,method=arvo,light=polygon,sided=one,verts=4"});

    Scene two = scene_of({polygon(4, true), polygon(3, true)}, {phong});
    two.quality.method = "arvo";
    sel = select(two);
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=phong,method=arvo,light=polygon,sided=two,verts=4"});

    // Mixed sidedness and a pentagon: run-time sidedness and the 8-vertex arrays.
    Scene mixed = scene_of({polygon(5, true), polygon(3, false)}, {phong});
    mixed.quality.method = "arvo";
    sel = select(mixed);
    INFO(sel.all());
    REQUIRE(sel.variants);
    CHECK(sel.names() == std::vector<std::string>{"dist=phong,method=arvo,light=polygon"});
    CHECK(sel.variants->at(0).variant.sided == Sided::Any);
    CHECK(sel.variants->at(0).variant.verts == 8);
}

TEST_CASE("select: a mixed scene yields one variant per (light, distribution) pair") {
    Scene s = scene_of({polygon(4), polygon(8, true)},
                       {material(Distribution::Ggx, 0.2), material(Distribution::Phong, 100),
                        material(Distribution::Ggx, 0.5)});
    const Selected sel = select(s);
    INFO(sel.all());
    REQUIRE(sel.variants);
    // Light type, then distribution (phong before ggx); default max_error 0.02.
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=phong,method=lorentz,light=polygon",
                                   "dist=ggx,method=ltc,light=polygon,horizon=proxy"});
    for (const auto& v : *sel.variants) {
        CHECK(v.variant.light == LightType::Polygon);  // no sphere, disk or ellipsoid
        CHECK(enumerated(v.variant));
    }
}

TEST_CASE("select: a light type without measured rows is an error, not silently dropped") {
    // The hand table has no sphere rows: the sphere's pair must be named, not skipped.
    const Selected sel =
        select(scene_of({polygon(4), sphere()}, {material(Distribution::Ggx, 0.2)}));
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    REQUIRE(sel.count(Severity::Error) == 1);
    CHECK_THAT(sel.diags[0].message, Contains("light=sphere, dist=ggx"));
}

TEST_CASE("select: a sphere light is chosen from the sphere's own rows") {
    QualityData q = hand_table();
    q.variants.push_back(row("dist=ggx,method=ltc,light=sphere", 0.012, 4000));
    q.variants.push_back(row("dist=ggx,method=point,light=sphere", 0.3, 2000));
    q.variants.push_back(row("dist=ggx,method=pearson,light=sphere", 0.05, 9000));
    const Selected sel = select(scene_of({sphere()}, {material(Distribution::Ggx, 0.2)}), q);
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=ltc,light=sphere"});
}

TEST_CASE("select: quality.method is honoured, and an unknown one rejected") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.method = "exact";
    Selected sel = select(s);
    INFO(sel.all());
    // exact's default is fp64, which a scene allows only when it says so.
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=ggx,method=exact,light=polygon,precision=fp32"});
    s.quality.fp64 = true;
    sel = select(s);
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=exact,light=polygon"});
    s.quality.fp64.reset();

    // With max_error as well: the cheapest of that method meeting it.
    s.quality.method = "ltc";
    s.quality.max_error = 0.015;
    sel = select(s);
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=ggx,method=ltc,light=polygon,horizon=proxy"});

    s.quality.method = "magic";
    sel = select(s);
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    REQUIRE(sel.count(Severity::Error) == 1);
    CHECK_THAT(sel.diags[0].message, Contains("quality.method") && Contains("'magic'"));

    // A method the pair has no family for.
    s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.method = "arvo";
    sel = select(s);
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    CHECK_THAT(sel.diags.at(0).message, Contains("light=polygon, dist=ggx") && Contains("arvo"));
}

TEST_CASE("select: max_error picks the cheapest variant that meets it") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.fp64 = true;  // the hand table's exact row is fp64
    struct Want {
        double max_error;
        const char* name;
    };
    for (const Want& w : {Want{0.0125, "dist=ggx,method=ltc,light=polygon"},
                          Want{0.02, "dist=ggx,method=ltc,light=polygon,horizon=proxy"},
                          Want{0.001, "dist=ggx,method=exact,light=polygon"},
                          // point meets it on specular and diffuse alike only here
                          Want{0.6, "dist=ggx,method=point,light=polygon"}}) {
        s.quality.max_error = w.max_error;
        const Selected sel = select(s);
        INFO("max_error " << w.max_error << "\n" << sel.all());
        CHECK(sel.names() == std::vector<std::string>{w.name});
        CHECK(sel.count(Severity::Warning) == 0);
    }
}

TEST_CASE("select: when nothing meets max_error, the most accurate, with a warning") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.max_error = 1e-6;
    s.quality.fp64 = true;
    const Selected sel = select(s);
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=exact,light=polygon"});
    REQUIRE(sel.count(Severity::Warning) == 1);
    CHECK_THAT(sel.diags[0].message, Contains("light=polygon, dist=ggx") && Contains("1e-06"));
}

TEST_CASE("select: rows measured at a non-default verts or sided are not ranked") {
    // phong arvo verts=4 claims 1e-9 at 100 instructions; a triangle scene must not take it
    // as the generic measurement.
    Scene s = scene_of({polygon(3)}, {material(Distribution::Phong, 40)});
    s.quality.max_error = 0.01;
    const Selected sel = select(s);
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=phong,method=lorentz,light=polygon,sided=one,verts=4"});
}

TEST_CASE("select: the shipped measured data parses and its choices meet max_error") {
    const QualityData& q = shipped_quality();
    INFO(q.variants.size() << " shipped rows");
    REQUIRE_FALSE(q.variants.empty());
    for (const auto& m : q.variants) {
        INFO(m.variant);
        CHECK(parse_variant(m.variant, {}));
        CHECK(m.x86_instructions > 0);
        CHECK(m.rel_l2.count("specular") == 1);
    }
    for (Distribution d :
         {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        for (double max_error : {0.001, 0.02, 0.1}) {
            Scene s = scene_of(
                {polygon(4)},
                {material(d, d == Distribution::Phong || d == Distribution::Blinn ? 40.0 : 0.2)});
            s.quality.max_error = max_error;
            const Selected sel = select(s, q);
            INFO(to_string(d) << " max_error " << max_error << "\n" << sel.all());
            REQUIRE(sel.variants);
            REQUIRE(sel.variants->size() == 1);
            const Variant& v = sel.variants->at(0).variant;
            CHECK(enumerated(v));
            // The measured row it came from: the same variant before specialisation.
            Variant generic = v;
            generic.sided = Variant{}.sided;
            generic.verts = Variant{}.verts;
            const MeasuredVariant* m = q.find(canonical_name(generic));
            REQUIRE(m);
            const bool any_meets =
                std::any_of(q.variants.begin(), q.variants.end(), [&](const auto& r) {
                    auto p = parse_variant(r.variant, {});
                    return p && p->dist == d && p->light == LightType::Polygon &&
                           p->sided == Variant{}.sided && p->verts == Variant{}.verts &&
                           effective_precision(*p) != Precision::Fp64 && r.error() <= max_error;
                });
            if (any_meets) {
                CHECK(m->error() <= max_error);
                CHECK(sel.count(Severity::Warning) == 0);
            } else {
                CHECK(sel.count(Severity::Warning) == 1);
            }
        }
    }
}

namespace {

GpuCost gpu_of(std::uint64_t cost, double ratio) {
    GpuCost g;
    g.family = "navi21";
    g.mesa = "hand-made";
    g.wave = 64;
    g.cost = g.inverse_throughput = cost;
    g.ratio_to_point = ratio;
    return g;
}

// The hand table with GPU figures that order the rows unlike their x86 counts.
QualityData gpu_table() {
    QualityData q = hand_table();
    for (auto& m : q.variants) {
        if (m.variant == "dist=ggx,method=ltc,light=polygon") m.gpu = gpu_of(1500, 3.0);
        if (m.variant == "dist=ggx,method=ltc,light=polygon,horizon=proxy") m.gpu = gpu_of(1700, 3.4);
        if (m.variant == "dist=ggx,method=exact,light=polygon") m.gpu = gpu_of(2000000, 4000);
        if (m.variant == "dist=phong,method=lorentz,light=polygon") m.gpu = gpu_of(16000, 35);
        if (m.variant == "dist=phong,method=pearson,light=polygon") m.gpu = gpu_of(18000, 40);
    }
    q.variants.push_back(row("dist=ggx,method=exact,light=polygon,precision=fp32", 2e-4, 30000));
    q.variants.back().gpu = gpu_of(40000, 80);
    q.variants.push_back(row("dist=ggx,method=lorentz,light=polygon", 0.03, 5000));
    q.variants.back().gpu = gpu_of(30000, 60);
    q.variants.push_back(row("dist=phong,method=exact,light=polygon,precision=fp32", 1e-6, 9000));
    q.variants.back().gpu = gpu_of(12000, 28);
    return q;
}

}  // namespace

TEST_CASE("select: rows rank by GPU cost where they have it") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    // By x86 count the proxy LTC (4500) is cheaper than the clipped one (4800); by GPU
    // cost (1700 against 1500) it is not.
    s.quality.max_error = 0.02;
    Selected sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=ltc,light=polygon"});
    REQUIRE(sel.variants);
    CHECK_THAT(sel.variants->at(0).why, Contains("GPU cost 1500") && Contains("navi21"));
    // Phong at 0.01: pearson (18000) and lorentz (0.008, 16000) meet it; exact fp32
    // (12000) is cheaper than both and more accurate.
    s = scene_of({polygon(4)}, {material(Distribution::Phong, 40)});
    s.quality.max_error = 0.01;
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{
                             "dist=phong,method=exact,light=polygon,sided=one,verts=4,precision=fp32"});
}

TEST_CASE("select: no fp64 variant unless the scene's precision is fp64") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.max_error = 1e-4;
    // Only the fp64 exact row meets 1e-4; in fp32 the most accurate allowed, with a
    // warning that names the error it reaches.
    Selected sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=ggx,method=exact,light=polygon,precision=fp32"});
    REQUIRE(sel.count(Severity::Warning) == 1);
    CHECK_THAT(sel.diags[0].message, Contains("0.0002") && Contains("0.0001"));
    s.quality.fp64 = true;
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=exact,light=polygon"});
    CHECK(sel.count(Severity::Warning) == 0);
}

TEST_CASE("select: tables, patented and exclude narrow the choice") {
    Scene s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2)});
    s.quality.max_error = 0.05;
    s.quality.tables = false;  // no ltc: lorentz (0.03) is then the cheapest meeting 0.05
    Selected sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() == std::vector<std::string>{"dist=ggx,method=lorentz,light=polygon"});
    s.quality.patented = false;  // nor the peak functions: exact in fp32
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=ggx,method=exact,light=polygon,precision=fp32"});
    s.quality.tables.reset();
    s.quality.patented.reset();
    s.quality.exclude = {"ltc", "lorentz"};
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=ggx,method=exact,light=polygon,precision=fp32"});
    // quality.method naming a refused method is an error that says which rule refused it.
    s.quality.exclude.clear();
    s.quality.max_error.reset();
    s.quality.method = "ltc";
    s.quality.tables = false;
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    REQUIRE(sel.count(Severity::Error) == 1);
    CHECK_THAT(sel.diags[0].message, Contains("quality.tables"));
    // A misspelt exclude name is an error, not silently nothing excluded.
    s.quality = {};
    s.quality.exclude = {"ltcs"};
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    CHECK_THAT(sel.diags.at(0).message, Contains("quality.exclude") && Contains("'ltcs'"));
}

TEST_CASE("select: a material's quality overrides the scene's for its distribution") {
    Scene s = scene_of({polygon(4)},
                       {material(Distribution::Ggx, 0.2), material(Distribution::Phong, 40)});
    s.quality.max_error = 0.02;
    SceneQuality strict;
    strict.max_error = 1e-4;
    strict.fp64 = true;
    s.material_quality = {strict, std::nullopt};
    Selected sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK(sel.names() ==
          std::vector<std::string>{"dist=phong,method=exact,light=polygon,sided=one,verts=4,precision=fp32",
                                   "dist=ggx,method=exact,light=polygon"});
    // Two materials of one distribution: the stricter max_error; different methods are an
    // error naming both.
    s = scene_of({polygon(4)}, {material(Distribution::Ggx, 0.2), material(Distribution::Ggx, 0.5)});
    SceneQuality a, b;
    a.method = "ltc";
    b.method = "exact";
    s.material_quality = {a, b};
    sel = select(s, gpu_table());
    INFO(sel.all());
    CHECK_FALSE(sel.variants);
    CHECK_THAT(sel.diags.at(0).message, Contains("materials 0 and 1") && Contains("'exact'"));
}

TEST_CASE("select: the shipped data never selects fp64 at the default quality") {
    const QualityData& q = shipped_quality();
    const Light lights[] = {polygon(4), sphere()};
    for (Distribution d :
         {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        for (const Light& l : lights) {
            Scene s = scene_of(
                {l}, {material(d, d == Distribution::Phong || d == Distribution::Blinn ? 40.0 : 0.2)});
            Selected sel = select(s, q);
            INFO(to_string(d) << " " << to_string(l.type) << "\n" << sel.all());
            REQUIRE(sel.variants);
            CHECK(effective_precision(sel.variants->at(0).variant) != Precision::Fp64);
            // A scene that allows fp64 and asks for more than any variant reaches gets the
            // most accurate: an exact one.
            s.quality.fp64 = true;
            s.quality.max_error = 1e-7;
            sel = select(s, q);
            INFO(sel.all());
            REQUIRE(sel.variants);
            CHECK(sel.variants->at(0).variant.method == Method::Exact);
        }
    }
}
