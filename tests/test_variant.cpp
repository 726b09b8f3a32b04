// The variant value type: canonical names, round trips, enumeration, errors.
#include <catch2/catch.hpp>
#include <set>

#include "arealight/variant.hpp"

using namespace arealight;

namespace {

std::string error_of(const std::string& name) {
    std::string msg;
    auto v = parse_variant(name, [&](const Diagnostic& d) { msg += d.message; });
    CHECK_FALSE(v);
    return msg;
}

}  // namespace

TEST_CASE("canonical names list the fixed keys, then non-default keys", "[variant]") {
    Variant v;
    CHECK(canonical_name(v) == "dist=phong,method=exact,light=polygon");
    v.nodes = 24;
    v.sided = Sided::Two;
    CHECK(canonical_name(v) == "dist=phong,method=exact,light=polygon,sided=two,nodes=24");
    v.method = Method::Point;  // nodes does not apply to the point method
    v.verts = 4;
    CHECK(canonical_name(v) == "dist=phong,method=point,light=polygon,sided=two,verts=4");
    auto p = parse_variant("light=polygon,nodes=8,dist=phong,method=exact,verts=5", {});
    REQUIRE(p);
    CHECK(canonical_name(*p) == "dist=phong,method=exact,light=polygon,verts=5,nodes=8");
}

TEST_CASE("enumeration: every variant valid, unique, and round-trips", "[variant]") {
    const auto all = enumerate_variants();
    // phong exact: 3 sided x 6 verts x 4 nodes; phong point: 3 sided x 6 verts.
    CHECK(all.size() == 3 * 6 * 4 + 3 * 6);
    std::set<std::string> names;
    for (const auto& v : all) {
        const std::string name = canonical_name(v);
        std::string why;
        auto back = parse_variant(name, [&](const Diagnostic& d) { why += d.message; });
        INFO(name << ": " << why);
        REQUIRE(back);
        CHECK(*back == v);
        CHECK(names.insert(name).second);
    }
}

TEST_CASE("bad variant names are rejected naming the key", "[variant]") {
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,color=red"),
               Catch::Matchers::Contains("unknown key 'color'"));
    CHECK_THAT(error_of("dist=lambert,method=exact,light=polygon"),
               Catch::Matchers::Contains("key 'dist': unknown value 'lambert'"));
    CHECK_THAT(error_of("dist=phong,method=exact,light=polygon,verts=9"),
               Catch::Matchers::Contains("key 'verts': value '9' out of range 3..8"));
    CHECK_THAT(error_of("method=exact,light=polygon"),
               Catch::Matchers::Contains("key 'dist' is required"));
    CHECK_THAT(error_of("dist=phong,light=polygon"),
               Catch::Matchers::Contains("key 'method' is required"));
    CHECK_THAT(error_of("dist=phong,method=exact"),
               Catch::Matchers::Contains("key 'light' is required"));
    CHECK_THAT(error_of("dist=phong,dist=phong,method=exact,light=polygon"),
               Catch::Matchers::Contains("key 'dist' given twice"));
    CHECK_THAT(error_of("dist=phong,method=point,light=polygon,nodes=8"),
               Catch::Matchers::Contains("key 'nodes' applies to method=exact only"));
    CHECK_THAT(error_of("dist=ggx,method=exact,light=polygon"),
               Catch::Matchers::Contains("no variant for dist=ggx,method=exact,light=polygon"));
    CHECK_THAT(error_of("dist=phong, method=exact,light=polygon"),
               Catch::Matchers::Contains("not key=value"));
}

TEST_CASE("defines and pattern matching", "[variant]") {
    auto v = parse_variant("dist=phong,method=exact,light=polygon,sided=one,verts=4,nodes=12", {});
    REQUIRE(v);
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"AL_DIST_PHONG", "1"}, {"AL_METHOD_EXACT", "1"}, {"AL_LIGHT_POLYGON", "1"},
        {"AL_SIDED", "1"},      {"AL_MAX_VERTS", "4"},    {"AL_NODES", "12"}};
    CHECK(variant_defines(*v) == expected);
    CHECK(variant_matches(*v, ""));
    CHECK(variant_matches(*v, "dist=phong,light=polygon"));
    CHECK(variant_matches(*v, "nodes=12"));
    CHECK_FALSE(variant_matches(*v, "method=point"));
    CHECK_FALSE(variant_matches(*v, "colour=red"));
}
