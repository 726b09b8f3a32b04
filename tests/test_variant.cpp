// The variant value type: canonical names, round trips, enumeration, errors.
#include <algorithm>
#include <catch2/catch.hpp>
#include <set>
#include <sstream>

#include "arealight/variant.hpp"

using namespace arealight;

namespace {

using Defines = std::vector<std::pair<std::string, std::string>>;

std::string show(const Defines& defines) {
    std::ostringstream s;
    for (const auto& [name, value] : defines) s << name << '=' << value << ' ';
    return s.str();
}

// The message of the single Error diagnostic a bad name must produce.
std::string error_of(const std::string& name) {
    std::vector<Diagnostic> got;
    auto v = parse_variant(name, [&](const Diagnostic& d) { got.push_back(d); });
    INFO("name: " << name);
    CHECK_FALSE(v);
    REQUIRE(got.size() == 1);
    CHECK(got[0].severity == Severity::Error);
    CHECK(got[0].file.empty());
    CHECK(got[0].line == 0);
    const std::string prefix = "variant '" + name + "': ";
    CHECK(got[0].message.rfind(prefix, 0) == 0);
    return got[0].message;
}

Variant parse_ok(const std::string& name) {
    std::string why;
    auto v = parse_variant(name, [&](const Diagnostic& d) { why += d.message; });
    INFO(name << ": " << why);
    REQUIRE(v);
    CHECK(why.empty());
    return *v;
}

}  // namespace

TEST_CASE("canonical names list the fixed keys, then non-default keys", "[variant]") {
    Variant v;
    CHECK(canonical_name(v) == "dist=phong,method=exact,light=polygon");
    v.nodes = 6;
    v.sided = Sided::Two;
    CHECK(canonical_name(v) == "dist=phong,method=exact,light=polygon,sided=two,nodes=6");
    v.verts = 4;
    CHECK(canonical_name(v) == "dist=phong,method=exact,light=polygon,sided=two,verts=4,nodes=6");

    Variant point;
    point.method = Method::Point;
    point.verts = 4;
    CHECK(canonical_name(point) == "dist=phong,method=point,light=polygon,verts=4");
    point.nodes = 12;  // not used by the point method, so not named
    CHECK(canonical_name(point) == "dist=phong,method=point,light=polygon,verts=4");

    // Keys in any order, defaults spelled out: the canonical form drops them.
    auto p = parse_ok("light=polygon,nodes=8,sided=any,dist=phong,method=exact,verts=4");
    CHECK(canonical_name(p) == "dist=phong,method=exact,light=polygon,verts=4,nodes=8");
    CHECK(canonical_name(parse_ok("method=point,light=polygon,dist=phong,sided=one")) ==
          "dist=phong,method=point,light=polygon,sided=one");
}

TEST_CASE("parsing fills the named fields and defaults the rest", "[variant]") {
    const Variant d = parse_ok("dist=phong,method=exact,light=polygon");
    CHECK(d == Variant{});
    CHECK(d.sided == Sided::Any);
    CHECK(d.verts == 8);
    CHECK(d.nodes == 16);

    const Variant v = parse_ok("dist=phong,method=exact,light=polygon,sided=two,verts=4,nodes=6");
    CHECK(v.dist == Distribution::Phong);
    CHECK(v.method == Method::Exact);
    CHECK(v.light == LightType::Polygon);
    CHECK(v.sided == Sided::Two);
    CHECK(v.verts == 4);
    CHECK(v.nodes == 6);
    CHECK(v != d);

    CHECK(std::string(to_string(Method::Exact)) == "exact");
    CHECK(std::string(to_string(Method::Point)) == "point");
    CHECK(std::string(to_string(Method::Mrp)) == "mrp");
    CHECK(std::string(to_string(Sided::Any)) == "any");
    CHECK(std::string(to_string(Sided::One)) == "one");
    CHECK(std::string(to_string(Sided::Two)) == "two");
}

TEST_CASE("enumeration: every variant valid, unique, and round-trips", "[variant]") {
    const auto all = enumerate_variants();
    const std::size_t sided = 3;      // any, one, two
    const std::size_t verts = 2;      // 4, 8
    const std::size_t nodes = 3;      // 6, 8, 16
    const std::size_t precision = 2;  // fp64, fp32
    const std::size_t fits = 2;       // tuned, paper
    const std::size_t specular = 2;   // twoaxis, sg
    const std::size_t phong_exact_polygon = sided * verts * nodes * precision;
    const std::size_t phong_arvo_polygon = sided * verts;
    const std::size_t phong_point_polygon = sided * verts;
    // lorentz, pearson, ellipsoid
    const std::size_t phong_peak_polygon = 3 * sided * verts * fits * specular;
    // blinn, beckmann, ggx: exact with nodes 2, 3, 16 x precision x radial 2, 16, and
    // the point baseline; one shape each (sided=any, verts=8).
    const std::size_t microfacet_polygon = 3 * (3 * precision * 2 + 1);
    // blinn, beckmann, ggx x lorentz, pearson, ellipsoid: split single, halved x factor
    // closest, blend; one shape, fit=tuned.
    const std::size_t microfacet_peak_polygon = 3 * 3 * 2 * 2;
    // phong, blinn, beckmann, ggx x ltc: precision fp32, fp16 x horizon clip, proxy x
    // edge acos, poly; one shape; ggx also x table texture, fit.
    const std::size_t ltc_polygon = 4 * 2 * 2 * 2 + 2 * 2 * 2;
    // Curved lights (disk, sphere, ellipsoid), each: phong lorentz, pearson, ellipsoid
    // with proxy 4, 16 x orient rim, paper; the microfacet peak methods with the
    // default proxy; the point baseline of each distribution; ltc of each distribution,
    // horizon clip or proxy (ggx also x table texture, fit); exact of each distribution at
    // its default keys, fp64 or fp32.
    const std::size_t curved = 3 * (3 * 2 * 2 + 3 * 3 + 4 + 4 * 2 + 2 + 4 * 2);
    // mrp: every distribution and light, one shape each.
    const std::size_t mrp = 4 * 4;
    INFO("enumerated " << all.size());
    CHECK(all.size() == phong_exact_polygon + phong_arvo_polygon + phong_peak_polygon +
                            phong_point_polygon + microfacet_polygon + microfacet_peak_polygon +
                            ltc_polygon + curved + mrp);

    std::set<std::string> names;
    for (const auto& v : all) {
        const std::string name = canonical_name(v);
        INFO(name);
        CHECK(is_valid(v));
        CHECK(names.insert(name).second);
        const Variant back = parse_ok(name);
        CHECK(back == v);
        CHECK(canonical_name(back) == name);
    }
    CHECK(names.size() == all.size());

    // Fixed order: family first, then sided, verts, nodes, precision.
    REQUIRE(all.size() >= 3);
    CHECK(canonical_name(all.front()) == "dist=phong,method=exact,light=polygon,verts=4,nodes=6");
    CHECK(canonical_name(all[1]) ==
          "dist=phong,method=exact,light=polygon,verts=4,nodes=6,precision=fp32");
    CHECK(canonical_name(all[2]) == "dist=phong,method=exact,light=polygon,verts=4,nodes=8");
    CHECK(canonical_name(all.back()) == "dist=ggx,method=mrp,light=ellipsoid");
    CHECK(enumerate_variants() == all);
}

TEST_CASE("validity: implemented family, keys in range, unused keys at default", "[variant]") {
    CHECK(is_valid(Variant{}));
    Variant v;
    v.verts = 9;
    CHECK_FALSE(is_valid(v));
    v.verts = 3;  // triangles take verts=4
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.nodes = 24;  // dominated by 16
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.nodes = 10;
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.dist = Distribution::Ggx;  // the exact microfacet reference
    CHECK(is_valid(v));
    v.nodes = 8;  // not among the microfacet family's 2, 3, 16
    CHECK_FALSE(is_valid(v));
    v.nodes = 2;
    v.sided = Sided::One;  // microfacet families compile sided=any only
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.radial = 2;  // a microfacet-only key on phong
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.dist = Distribution::Ggx;
    v.method = Method::Arvo;  // no such family
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.method = Method::Point;
    CHECK(is_valid(v));
    v.nodes = 24;  // names the same shader as nodes=16 would: only one of them is valid
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.precision = Precision::Fp32;
    CHECK(is_valid(v));
    v.method = Method::Point;  // fp32 only: its precision key keeps the default
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.verts = 5;  // compiled sizes are 3, 4 and 8 only
    CHECK_FALSE(is_valid(v));
    v = Variant{};
    v.fit = Fit::Paper;  // a peak-method key
    CHECK_FALSE(is_valid(v));
    v.method = Method::Pearson;
    CHECK(is_valid(v));
    v.specular = SpecularForm::Sg;
    CHECK(is_valid(v));
    v.method = Method::Arvo;
    CHECK_FALSE(is_valid(v));
}

TEST_CASE("peak keys: fit and specular name and parse", "[variant]") {
    const Variant v =
        parse_ok("dist=phong,method=pearson,light=polygon,specular=sg,fit=paper,verts=4");
    CHECK(v.method == Method::Pearson);
    CHECK(v.fit == Fit::Paper);
    CHECK(v.specular == SpecularForm::Sg);
    CHECK(canonical_name(v) ==
          "dist=phong,method=pearson,light=polygon,verts=4,fit=paper,specular=sg");
    CHECK(canonical_name(parse_ok("dist=phong,method=ellipsoid,light=polygon,fit=tuned")) ==
          "dist=phong,method=ellipsoid,light=polygon");
    CHECK(variant_matches(v, "method=pearson,fit=paper"));
    CHECK_FALSE(variant_matches(v, "fit=tuned"));
    CHECK_FALSE(variant_matches(parse_ok("dist=phong,method=arvo,light=polygon"), "fit=tuned"));
    CHECK(effective_precision(parse_ok("dist=phong,method=arvo,light=polygon")) == Precision::Fp32);
}

TEST_CASE("precision: fp64 by default for method=exact, fp32 for the rest", "[variant]") {
    const Variant d = parse_ok("dist=phong,method=exact,light=polygon");
    CHECK(d.precision == Precision::Fp64);
    CHECK(effective_precision(d) == Precision::Fp64);
    const Variant f = parse_ok("dist=phong,method=exact,light=polygon,precision=fp32");
    CHECK(f.precision == Precision::Fp32);
    CHECK(canonical_name(f) == "dist=phong,method=exact,light=polygon,precision=fp32");
    CHECK(canonical_name(parse_ok("dist=phong,method=exact,light=polygon,precision=fp64")) ==
          "dist=phong,method=exact,light=polygon");
    const Variant p = parse_ok("dist=phong,method=point,light=polygon");
    CHECK(effective_precision(p) == Precision::Fp32);
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,precision=fp16"),
               Catch::Matchers::Contains("key 'precision': value 'fp16' is not offered for "
                                         "dist=phong,method=exact,light=polygon (expected fp64, "
                                         "fp32)"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,precision=fp8"),
               Catch::Matchers::Contains(
                   "key 'precision': unknown value 'fp8' (expected fp64, fp32, fp16)"));
    CHECK_THAT(error_of("dist=phong,method=point,light=polygon,precision=fp32"),
               Catch::Matchers::Contains("key 'precision' applies to method=exact, ltc only"));
}

TEST_CASE("precision: a family's own default (ltc: fp32, offers fp16)", "[variant]") {
    // The key's default is fp64, which ltc does not offer: its row names fp32 instead.
    const Variant d = parse_ok("dist=ggx,method=ltc,light=polygon");
    CHECK(d.precision == Precision::Fp32);
    CHECK(effective_precision(d) == Precision::Fp32);
    CHECK(is_valid(d));
    CHECK(canonical_name(d) == "dist=ggx,method=ltc,light=polygon");
    CHECK(parse_ok("dist=ggx,method=ltc,light=polygon,precision=fp32") == d);
    const Variant h = parse_ok("dist=ggx,method=ltc,light=polygon,precision=fp16");
    CHECK(h.precision == Precision::Fp16);
    CHECK(canonical_name(h) == "dist=ggx,method=ltc,light=polygon,precision=fp16");
    CHECK(variant_matches(d, "precision=fp32"));
    CHECK(variant_matches(h, "precision=fp16"));
    CHECK_THAT(error_of("dist=ggx,method=ltc,light=polygon,precision=fp64"),
               Catch::Matchers::Contains("key 'precision': value 'fp64' is not offered for "
                                         "dist=ggx,method=ltc,light=polygon (expected fp32, "
                                         "fp16)"));
    Variant raw = d;
    raw.precision = Precision::Fp64;  // the key's default is not this family's
    CHECK_FALSE(is_valid(raw));
}

TEST_CASE("bad variant names are rejected naming the key", "[variant]") {
    using Catch::Matchers::Contains;
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,color=red"),
               Contains("unknown key 'color'"));
    CHECK_THAT(error_of("dist=lambert,method=exact,light=polygon"),
               Contains("key 'dist': unknown value 'lambert' (expected phong, blinn, beckmann, "
                        "ggx)"));
    CHECK_THAT(
        error_of("dist=phong,method=ltcx,light=polygon"),
        Contains("key 'method': unknown value 'ltcx' (expected exact, arvo, lorentz, pearson, "
                 "ellipsoid, ltc, mrp, point)"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=quad"),
               Contains("key 'light': unknown value 'quad' (expected polygon, disk, sphere, "
                        "ellipsoid)"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,sided=both"),
               Contains("key 'sided': unknown value 'both' (expected any, one, two)"));
    CHECK(error_of("dist=phong,method=exact,light=polygon,verts=9") ==
          "variant 'dist=phong,method=exact,light=polygon,verts=9': key 'verts': value '9' is "
          "not one of 4, 8");
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,verts=5"),
               Contains("key 'verts': value '5' is not one of 4, 8"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,verts=-4"),
               Contains("key 'verts': value '-4' is not one of 4, 8"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,fit=paper"),
               Contains("key 'fit' applies to method=lorentz, pearson, ellipsoid only"));
    CHECK_THAT(error_of("dist=phong,method=arvo,light=polygon,specular=sg"),
               Contains("key 'specular' applies to dist=phong and method=lorentz, pearson, "
                        "ellipsoid only"));
    CHECK_THAT(error_of("dist=phong,method=pearson,light=polygon,fit=best"),
               Contains("key 'fit': unknown value 'best' (expected tuned, paper)"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,nodes=10"),
               Contains("key 'nodes': value '10' is not one of 2, 3, 6, 8, 16"));
    CHECK_THAT(error_of("method=exact,light=polygon"), Contains("key 'dist' is required"));
    CHECK_THAT(error_of("dist=phong,light=polygon"), Contains("key 'method' is required"));
    CHECK_THAT(error_of("dist=phong,method=exact"), Contains("key 'light' is required"));
    CHECK_THAT(error_of(""), Contains("key 'dist' is required"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,dist=phong"),
               Contains("key 'dist' given twice"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,verts=4,verts=5"),
               Contains("key 'verts' given twice"));
    CHECK_THAT(error_of("dist=phong,method=point,light=polygon,nodes=8"),
               Contains("key 'nodes' applies to method=exact only"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=disk,verts=4"),
               Contains("key 'verts' applies to light=polygon only"));
    CHECK_THAT(error_of("dist=ggx,method=arvo,light=polygon"),
               Contains("no variant for dist=ggx,method=arvo,light=polygon yet"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,nodes=2"),
               Contains("key 'nodes': value '2' is not offered for dist=phong,method=exact"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,radial=2"),
               Contains("key 'radial' applies to"));
    CHECK_THAT(error_of("dist=phong,method=arvo,light=sphere"),
               Contains("no variant for dist=phong,method=arvo,light=sphere yet"));
}

TEST_CASE("malformed variant names are rejected", "[variant]") {
    using Catch::Matchers::Contains;
    for (const std::string name :
         {"dist=phong, method=exact,light=polygon", "dist=phong,method=exact,light=polygon ",
          " dist=phong,method=exact,light=polygon", "dist =phong,method=exact,light=polygon",
          "dist=phong,method=exact,light=polygon\n", "dist=phong,,method=exact,light=polygon",
          "dist=phong,method=exact,light=polygon,", "dist=phong,method,light=polygon",
          "dist=phong,method=exact=point,light=polygon", "=phong,method=exact,light=polygon",
          "dist=,method=exact,light=polygon"}) {
        CHECK_THAT(error_of(name), Contains("is not key=value"));
    }
    // No consumer: still rejected, nothing thrown or printed.
    CHECK_FALSE(parse_variant("dist=phong", {}));
}

TEST_CASE("defines name the chosen values and only the keys that apply", "[variant]") {
    const Variant exact =
        parse_ok("dist=phong,method=exact,light=polygon,sided=one,verts=4,nodes=6");
    const Defines want_exact = {{"AL_DIST_PHONG", "1"},    {"AL_METHOD_EXACT", "1"},
                                {"AL_LIGHT_POLYGON", "1"}, {"AL_SIDED", "1"},
                                {"AL_MAX_VERTS", "4"},     {"AL_NODES", "6"},
                                {"AL_PRECISION_FP64", "1"}};
    INFO("exact: " << show(variant_defines(exact)));
    CHECK(variant_defines(exact) == want_exact);

    const Variant point = parse_ok("dist=phong,method=point,light=polygon,sided=two");
    const Defines want_point = {{"AL_DIST_PHONG", "1"},    {"AL_METHOD_POINT", "1"},
                                {"AL_LIGHT_POLYGON", "1"}, {"AL_SIDED", "2"},
                                {"AL_MAX_VERTS", "8"},     {"AL_PRECISION_FP64", "0"}};
    INFO("point: " << show(variant_defines(point)));
    CHECK(variant_defines(point) == want_point);

    const Defines any = variant_defines(Variant{});
    INFO("default: " << show(any));
    CHECK(std::count(any.begin(), any.end(),
                     std::make_pair(std::string("AL_SIDED"), std::string("0"))) == 1);
}

TEST_CASE("pattern matching compares effective values", "[variant]") {
    const Variant v = parse_ok("dist=phong,method=exact,light=polygon,sided=one,verts=4,nodes=6");
    CHECK(variant_matches(v, ""));
    CHECK(variant_matches(v, "dist=phong"));
    CHECK(variant_matches(v, "dist=phong,light=polygon"));
    CHECK(variant_matches(v, "nodes=6,verts=4,sided=one"));
    CHECK_FALSE(variant_matches(v, "nodes=16"));
    CHECK_FALSE(variant_matches(v, "method=point"));
    CHECK_FALSE(variant_matches(v, "dist=phong,method=point"));
    CHECK_FALSE(variant_matches(v, "colour=red"));
    CHECK_FALSE(variant_matches(v, "dist=lambert"));
    CHECK_FALSE(variant_matches(v, "dist=phong,"));
    CHECK_FALSE(variant_matches(v, "dist = phong"));

    // Defaults count as values when the name left them out.
    const Variant d = parse_ok("dist=phong,method=exact,light=polygon");
    CHECK(variant_matches(d, "sided=any,verts=8,nodes=16"));
    // A key the variant does not use has no value to match.
    const Variant p = parse_ok("dist=phong,method=point,light=polygon");
    CHECK(variant_matches(p, "method=point,verts=8"));
    CHECK_FALSE(variant_matches(p, "nodes=16"));
    // Precision always has an effective value: fp32 for a method without the key.
    CHECK(variant_matches(p, "precision=fp32"));
    CHECK(variant_matches(d, "precision=fp64"));

    std::size_t exact = 0, point = 0, all = 0;
    for (const auto& e : enumerate_variants()) {
        all += variant_matches(e, "");
        exact += variant_matches(e, "method=exact,sided=two");
        point += variant_matches(e, "method=point,verts=4");
    }
    INFO("all " << all << ", exact sided=two " << exact << ", point verts=4 " << point);
    CHECK(all == enumerate_variants().size());
    CHECK(exact == 2 * 3 * 2);  // verts 4, 8; nodes 6, 8, 16; precision
    CHECK(point == 3);          // sided any, one, two
}

// The tables the functions above loop over (variant_keys, variant_families): each
// test below runs over every row, so a new key, value or family is checked by them
// without a test edit.
namespace {

std::string family_base(const VariantFamily& f) {
    return std::string("dist=") + to_string(f.dist) + ",method=" + to_string(f.method) +
           ",light=" + to_string(f.light);
}

const FamilyKey* family_key(const VariantFamily& f, const std::string& key) {
    for (const auto& fk : f.keys)
        if (fk.key == key) return &fk;
    return nullptr;
}

}  // namespace

TEST_CASE("key table: names in canonical order, required keys, defaults, docs", "[variant]") {
    std::vector<std::string> names;
    for (const auto& k : variant_keys()) {
        INFO("key " << k.name);
        names.push_back(k.name);
        CHECK_FALSE(k.doc.empty());
        REQUIRE_FALSE(k.values.empty());
        std::set<std::string> unique(k.values.begin(), k.values.end());
        CHECK(unique.size() == k.values.size());
        if (k.required) {
            CHECK(k.default_value.empty());
            CHECK(k.applies_to.empty());
        } else {
            CHECK(std::count(k.values.begin(), k.values.end(), k.default_value) == 1);
        }
    }
    // Today's keys lead, in today's canonical order; a new key goes after them.
    const std::vector<std::string> today = {"dist",  "method",    "light", "sided",   "verts",
                                            "nodes", "precision", "fit",   "specular"};
    REQUIRE(names.size() >= today.size());
    CHECK(std::vector<std::string>(names.begin(), names.begin() + today.size()) == today);
    // Where each key applies, as its error message names it: derived from the families.
    auto scope = [](const std::string& name) {
        for (const auto& k : variant_keys())
            if (k.name == name) return k.applies_to;
        return std::string("?");
    };
    CHECK(scope("sided") == "light=polygon");
    CHECK(scope("proxy") == "method=lorentz, pearson, ellipsoid and light=disk, sphere, ellipsoid");
    CHECK(scope("verts") == "light=polygon");
    CHECK(scope("nodes") == "method=exact");
    CHECK(scope("precision") == "method=exact, ltc");
    CHECK(scope("horizon") == "method=ltc");
    CHECK(scope("edge") == "method=ltc and light=polygon");  // curved lights have no edges
    CHECK(scope("fit") == "method=lorentz, pearson, ellipsoid");
    CHECK(scope("specular") == "dist=phong and method=lorentz, pearson, ellipsoid");
    CHECK(scope("split") == "dist=blinn, beckmann, ggx and method=lorentz, pearson, ellipsoid");
    CHECK(scope("factor") == "dist=blinn, beckmann, ggx and method=lorentz, pearson, ellipsoid");
    // The unknown-key message lists the table.
    std::string listed;
    for (const auto& name : names) listed += (listed.empty() ? "" : ", ") + name;
    CHECK(error_of("dist=phong,method=exact,light=polygon,color=red") ==
          "variant 'dist=phong,method=exact,light=polygon,color=red': unknown key 'color' (keys: " +
              listed + ")");
}

TEST_CASE("family table: every family's keys and values are the key table's", "[variant]") {
    std::set<std::string> families;
    for (const auto& f : variant_families()) {
        const std::string base = family_base(f);
        INFO("family " << base);
        CHECK(families.insert(base).second);
        // Its bare name is valid: every key it uses offers the key's default.
        const Variant v = parse_ok(base);
        CHECK(is_valid(v));
        CHECK(find_family(v) == &f);
        CHECK_FALSE(f.templates.empty());
        for (const auto& fk : f.keys) {
            INFO("key " << fk.key);
            auto k = std::find_if(variant_keys().begin(), variant_keys().end(),
                                  [&](const KeyInfo& i) { return i.name == fk.key; });
            REQUIRE(k != variant_keys().end());
            CHECK_FALSE(k->required);
            REQUIRE_FALSE(fk.values.empty());
            // A subset of the key's values, in the key's order.
            std::size_t at = 0;
            for (const auto& x : fk.values) {
                while (at < k->values.size() && k->values[at] != x) ++at;
                CHECK(at < k->values.size());
            }
            // Its default: the key's, or the row's own, offered once.
            const std::string fallback = fk.default_value.empty() ? k->default_value
                                                                  : fk.default_value;
            CHECK(std::count(fk.values.begin(), fk.values.end(), fallback) == 1);
        }
    }
    // A (dist, method, light) with no row has no variant.
    Variant none;
    none.method = Method::Arvo;
    none.light = LightType::Sphere;
    CHECK(find_family(none) == nullptr);
}

TEST_CASE("enumeration is the product of each family's key values, in table order", "[variant]") {
    const auto all = enumerate_variants();
    std::size_t expected = 0;
    for (const auto& f : variant_families()) {
        std::size_t n = 1;
        for (const auto& fk : f.keys) n *= fk.values.size();
        std::size_t got = 0;
        for (const auto& v : all) got += find_family(v) == &f;
        INFO("family " << family_base(f));
        CHECK(got == n);
        expected += n;
    }
    CHECK(all.size() == expected);
    // Families in table order, each contiguous.
    std::vector<const VariantFamily*> order;
    for (const auto& v : all)
        if (order.empty() || order.back() != find_family(v)) order.push_back(find_family(v));
    REQUIRE(order.size() == variant_families().size());
    for (std::size_t i = 0; i < order.size(); ++i) CHECK(order[i] == &variant_families()[i]);
}

TEST_CASE("every value of every key parses, names, matches and is enumerated", "[variant]") {
    const auto all = enumerate_variants();
    std::set<std::string> enumerated;
    for (const auto& v : all) enumerated.insert(canonical_name(v));
    for (const auto& k : variant_keys()) {
        if (k.required) continue;
        for (const auto& f : variant_families()) {
            const FamilyKey* fk = family_key(f, k.name);
            const std::string base = family_base(f);
            const Variant bare = parse_ok(base);
            if (!fk) {
                // Not used: named anywhere, rejected saying where it applies.
                INFO("family " << base << ", key " << k.name);
                CHECK(error_of(base + "," + k.name + "=" + k.default_value) ==
                      "variant '" + base + "," + k.name + "=" + k.default_value + "': key '" +
                          k.name + "' applies to " + k.applies_to + " only");
                continue;
            }
            for (const auto& value : k.values) {
                const std::string name = base + "," + k.name + "=" + value;
                INFO(name);
                const bool offered =
                    std::find(fk->values.begin(), fk->values.end(), value) != fk->values.end();
                if (!offered) {
                    CHECK_THAT(error_of(name), Catch::Matchers::Contains("is not offered"));
                    continue;
                }
                const Variant v = parse_ok(name);
                CHECK(is_valid(v));
                CHECK(variant_matches(v, k.name + "=" + value));
                CHECK(parse_ok(canonical_name(v)) == v);
                CHECK(enumerated.count(canonical_name(v)) == 1);
                // The default is dropped from the name; any other value is named, and
                // makes a different variant (operator== sees the field).
                const bool is_default =
                    value == (fk->default_value.empty() ? k.default_value : fk->default_value);
                CHECK((canonical_name(v) == base) == is_default);
                CHECK((v == bare) == is_default);
                if (!is_default) {
                    CHECK(canonical_name(v) == name);
                    CHECK_FALSE(variant_matches(bare, k.name + "=" + value));
                }
            }
        }
    }
}

TEST_CASE("a key a family does not use stays at its default", "[variant]") {
    for (const auto& v : enumerate_variants()) {
        const VariantFamily* f = find_family(v);
        REQUIRE(f);
        for (const auto& k : variant_keys()) {
            if (k.required || family_key(*f, k.name)) continue;
            INFO(canonical_name(v) << ", key " << k.name);
            // No value to match, except precision's effective value, fp32.
            if (k.name == "precision")
                CHECK(variant_matches(v, "precision=fp32"));
            else
                CHECK_FALSE(variant_matches(v, k.name + "=" + k.default_value));
            CHECK(canonical_name(v).find("," + k.name + "=") == std::string::npos);
        }
    }
}

TEST_CASE("where a key applies, as its message says, is the families that name it", "[variant]") {
    for (const auto& k : variant_keys()) {
        if (k.required) continue;
        // "method=lorentz, pearson, ellipsoid", several joined by " and "; empty: all.
        std::vector<std::pair<std::string, std::vector<std::string>>> parts;
        for (std::size_t at = 0; at < k.applies_to.size();) {
            std::size_t end = k.applies_to.find(" and ", at);
            if (end == std::string::npos) end = k.applies_to.size();
            const std::string part = k.applies_to.substr(at, end - at);
            const std::size_t eq = part.find('=');
            REQUIRE(eq != std::string::npos);
            std::vector<std::string> values;
            std::istringstream in(part.substr(eq + 1));
            for (std::string x; std::getline(in, x, ',');) values.push_back(x.substr(x[0] == ' '));
            parts.emplace_back(part.substr(0, eq), values);
            at = end + 5;
        }
        for (const auto& f : variant_families()) {
            bool inside = true;
            for (const auto& [axis, values] : parts) {
                const std::string value = axis == "dist"     ? to_string(f.dist)
                                          : axis == "method" ? to_string(f.method)
                                                             : to_string(f.light);
                inside = inside && std::count(values.begin(), values.end(), value) == 1;
            }
            INFO("key " << k.name << " (" << k.applies_to << "), family " << family_base(f));
            CHECK(inside == (family_key(f, k.name) != nullptr));
        }
    }
}

TEST_CASE("a pattern matches a number as parse_variant reads it", "[variant]") {
    // fuzz/crashes/fuzz_variant/matches-own-name-nodes-02.txt: "nodes=02" parses as nodes=2.
    const auto v = parse_variant("dist=phong,method=exact,light=polygon,nodes=08", {});
    REQUIRE(v);
    CHECK(v->nodes == 8);
    CHECK(variant_matches(*v, "method=exact,nodes=08"));
    CHECK(variant_matches(*v, "nodes=8"));
    CHECK_FALSE(variant_matches(*v, "nodes=016"));
    CHECK_FALSE(variant_matches(*v, "nodes=x"));
}
