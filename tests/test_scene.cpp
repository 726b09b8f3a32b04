// Scene files (CONTRACT.md 7): a good file reads back every field; each kind of malformed
// input is rejected with a message naming the file, the light or material and the field;
// unknown fields are errors, "comment" and "x-..." fields ignored.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "arealight/scene.hpp"

using namespace arealight;
using Catch::Matchers::Contains;

namespace {

const char* kGood = R"({
  "format": "arealight-scene/1",
  "lights": [ {"type": "polygon", "vertices": [[0,0,2],[1,0,2],[1,1,2]], "two_sided": true},
              {"type": "sphere", "center": [0,0,3], "radius": 0.5} ],
  "materials": [ {"distribution": "ggx", "alpha": 0.3}, {"distribution": "phong", "exponent": 40} ],
  "quality": {"max_error": 0.01}
})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    REQUIRE(at != std::string::npos);  // a test edit that matches nothing tests nothing
    s.replace(at, from.size(), to);
    return s;
}

struct Parsed {
    std::optional<Scene> scene;
    std::vector<Diagnostic> diags;
    std::string all() const {
        std::string s;
        for (const auto& d : diags) s += d.message + "\n";
        return s.empty() ? "(no messages)" : s;
    }
};

Parsed parse(const std::string& text) {
    Parsed p;
    p.scene = parse_scene(text, "s.json", [&](const Diagnostic& d) { p.diags.push_back(d); });
    return p;
}

// The scene is rejected with exactly one error, which contains every fragment.
void rejected(const std::string& text, const std::vector<std::string>& fragments) {
    const Parsed p = parse(text);
    INFO(p.all());
    CHECK_FALSE(p.scene);
    REQUIRE(p.diags.size() == 1);
    CHECK(p.diags[0].severity == Severity::Error);
    CHECK(p.diags[0].file == "s.json");
    for (const auto& f : fragments) CHECK_THAT(p.diags[0].message, Contains(f));
}

}  // namespace

TEST_CASE("scene: a good file reads back every field") {
    const Parsed p = parse(kGood);
    INFO(p.all());
    REQUIRE(p.scene);
    CHECK(p.diags.empty());
    const Scene& s = *p.scene;
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].type == LightType::Polygon);
    REQUIRE(s.lights[0].vertices.size() == 3);
    CHECK(s.lights[0].vertices[1] == Vec3{1, 0, 2});
    CHECK(s.lights[0].two_sided);
    CHECK(s.lights[1].type == LightType::Sphere);
    CHECK(s.lights[1].radius == 0.5);
    CHECK(s.lights[1].center == Vec3{0, 0, 3});
    REQUIRE(s.materials.size() == 2);
    CHECK(s.materials[0].distribution == Distribution::Ggx);
    CHECK(s.materials[0].alpha == 0.3);
    CHECK(s.materials[1].distribution == Distribution::Phong);
    CHECK(s.materials[1].exponent == 40);
    REQUIRE(s.quality.max_error);
    CHECK(*s.quality.max_error == 0.01);
    CHECK_FALSE(s.quality.method);
}

TEST_CASE("scene: quality is optional, and method is read as a name") {
    const Parsed none = parse(replace(kGood, ",\n  \"quality\": {\"max_error\": 0.01}", ""));
    INFO(none.all());
    REQUIRE(none.scene);
    CHECK_FALSE(none.scene->quality.max_error);
    CHECK_FALSE(none.scene->quality.method);
    const Parsed m = parse(replace(kGood, R"("max_error": 0.01)", R"("method": "ltc")"));
    REQUIRE(m.scene);
    REQUIRE(m.scene->quality.method);
    CHECK(*m.scene->quality.method == "ltc");
    CHECK_FALSE(m.scene->quality.max_error);
}

TEST_CASE("scene: comment and x- fields are ignored at every level") {
    std::string t = replace(kGood, R"("format")", R"("comment": {"x": [1]}, "format")");
    t = replace(t, R"("radius": 0.5)", R"("radius": 0.5, "x-colour": "red")");
    t = replace(t, R"("alpha": 0.3)", R"("alpha": 0.3, "comment": "floor")");
    t = replace(t, R"("max_error": 0.01)", R"("max_error": 0.01, "x-budget_ms": 3)");
    const Parsed p = parse(t);
    INFO(p.all());
    REQUIRE(p.scene);
    CHECK(p.diags.empty());
    CHECK(p.scene->lights.size() == 2);
    CHECK(p.scene->materials[0].alpha == 0.3);
}

TEST_CASE("scene: an unknown field at any level is an error naming the nearest known one") {
    rejected(replace(kGood, R"("two_sided": true)", R"("two_side": true)"),
             {"s.json: light 0: field 'two_side': unknown field (did you mean 'two_sided'?)"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("max_eror": 0.01)"),
             {"s.json: field 'quality.max_eror': unknown field (did you mean "
              "'quality.max_error'?)"});
    rejected(replace(kGood, R"("exponent": 40})", R"("exponent": 40, "quality": {"presicion": "fp64"}})"),
             {"material 1: field 'quality.presicion'", "did you mean 'quality.precision'?"});
    rejected(replace(kGood, R"("format")", R"("light": [], "format")"),
             {"field 'light': unknown field (did you mean 'lights'?)"});
    // The renderer's own fields are known to the scene reader.
    const Parsed p = parse(replace(kGood, R"("radius": 0.5)", R"("radius": 0.5, "intensity": 2)"));
    INFO(p.all());
    CHECK(p.scene);
}

TEST_CASE("scene: malformed top level is rejected naming the field") {
    rejected("{", {"s.json: ", "invalid JSON"});
    rejected("[1]", {"field 'format'", "JSON object"});
    rejected(replace(kGood, R"("arealight-scene/1")", R"("arealight-cases/1")"),
             {"field 'format'", "arealight-cases/1", "expected \"arealight-scene/1\""});
    rejected(replace(kGood, R"("format": "arealight-scene/1",)", ""),
             {"field 'format'", "missing"});
    rejected(replace(kGood, R"("lights")", R"("x-lamps")"), {"field 'lights'", "missing"});
    rejected(replace(kGood, R"("lights": [)", R"("lights": "all", "x-rest": [)"),
             {"field 'lights'", "must be an array"});
    rejected(
        replace(
            kGood,
            R"("materials": [ {"distribution": "ggx", "alpha": 0.3}, {"distribution": "phong", "exponent": 40} ])",
            R"("materials": [])"),
        {"field 'materials'", "at least one"});
    rejected(replace(kGood, R"("materials": [)", R"("materials": 3, "x-rest": [)"),
             {"field 'materials'", "must be an array"});
    rejected(replace(kGood, R"({"max_error": 0.01})", "0.01"), {"field 'quality'", "object"});
    rejected(replace(kGood, "0.01", "0"), {"field 'quality.max_error'", "not a positive"});
    rejected(replace(kGood, "0.01", "\"small\""), {"field 'quality.max_error'", "number"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("method": 3)"),
             {"field 'quality.method'", "method name"});
}

TEST_CASE("scene: a bad light names the light and its field, as a case would") {
    rejected(replace(kGood, R"([[0,0,2],[1,0,2],[1,1,2]])", R"([[0,0,2],[1,0,2]])"),
             {"s.json: light 0: field 'vertices': has 2 vertices; a polygon needs 3 to 8"});
    rejected(replace(kGood, R"([1,1,2]])", R"([1,1,2],[0,1,3]])"),
             {"light 0: field 'vertices[", "not coplanar"});
    rejected(replace(kGood, R"("two_sided": true)", R"("two_sided": 1)"),
             {"light 0: field 'two_sided': must be true or false"});
    rejected(replace(kGood, R"("radius": 0.5)", R"("radius": -1)"),
             {"light 1: field 'radius': -1 is not positive"});
    rejected(replace(kGood, R"("type": "sphere")", R"("type": "tube")"),
             {"light 1: field 'type': unknown type 'tube'"});
    rejected(replace(kGood, R"({"type": "sphere", "center": [0,0,3], "radius": 0.5})", "7"),
             {"light 1: must be an object"});
    rejected(replace(kGood, R"("type": "sphere", "center": [0,0,3], "radius": 0.5)",
                     R"("type": "disk", "center": [0,0,3], "u": [1,0,0], "v": [1,1,0])"),
             {"light 1: field 'v': must be orthogonal to u"});
}

TEST_CASE("scene: a bad material names the material and its field, as a case would") {
    rejected(replace(kGood, R"("alpha": 0.3)", R"("alpha": 2)"),
             {"s.json: material 0: field 'alpha': 2 is outside [0.001, 1]"});
    rejected(replace(kGood, R"("exponent": 40)", R"("x-alpha": 0.2)"),
             {"material 1: field 'exponent': missing"});
    rejected(replace(kGood, R"("distribution": "phong")", R"("distribution": "lambert")"),
             {"material 1: field 'distribution': unknown distribution 'lambert'"});
    rejected(replace(kGood, R"("alpha": 0.3)", R"("alpha": 0.3, "f0": 1.5)"),
             {"material 0: field 'f0': 1.5 is outside [0, 1]"});
}

TEST_CASE("scene: every error of a file is reported in one pass") {
    std::string t = replace(kGood, R"("alpha": 0.3)", R"("alpha": 2)");
    t = replace(t, R"("radius": 0.5)", R"("radius": 0)");
    const Parsed p = parse(t);
    INFO(p.all());
    CHECK_FALSE(p.scene);
    REQUIRE(p.diags.size() == 2);
    CHECK_THAT(p.diags[0].message, Contains("light 1: field 'radius'"));
    CHECK_THAT(p.diags[1].message, Contains("material 0: field 'alpha'"));
}

TEST_CASE("scene: read_scene names the file it could not read, and reads a good one") {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("arealight_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = (dir / "good.scene.json").string();
    std::ofstream(path) << kGood;
    std::vector<Diagnostic> diags;
    auto sink = [&](const Diagnostic& d) { diags.push_back(d); };
    const auto s = read_scene(path, sink);
    CHECK(s);
    CHECK(diags.empty());
    const auto missing = read_scene((dir / "missing.json").string(), sink);
    CHECK_FALSE(missing);
    REQUIRE(diags.size() == 1);
    CHECK_THAT(diags[0].message, Contains("missing.json: cannot read"));
    fs::remove_all(dir);
}

TEST_CASE("scene: quality's precision, tables, patented, exclude and a material's own") {
    std::string t = replace(kGood, R"("max_error": 0.01)",
                            R"("max_error": 0.01, "precision": "fp64", "tables": false, )"
                            R"("patented": false, "exclude": ["ltc", "point"])");
    t = replace(t, R"("alpha": 0.3)", R"("alpha": 0.3, "quality": {"max_error": 0.001, "exclude": ["exact"]})");
    const Parsed p = parse(t);
    INFO(p.all());
    REQUIRE(p.scene);
    const SceneQuality& q = p.scene->quality;
    CHECK(q.fp64 == std::optional<bool>(true));
    CHECK(q.tables == std::optional<bool>(false));
    CHECK(q.patented == std::optional<bool>(false));
    CHECK(q.exclude == std::vector<std::string>{"ltc", "point"});
    REQUIRE(p.scene->material_quality.size() == 2);
    REQUIRE(p.scene->material_quality[0]);
    CHECK_FALSE(p.scene->material_quality[1]);
    // ggx: the material's max_error, the scene's other fields, both excludes.
    const SceneQuality ggx = effective_quality(*p.scene, Distribution::Ggx, nullptr);
    CHECK(ggx.max_error == std::optional<double>(0.001));
    CHECK(ggx.fp64 == std::optional<bool>(true));
    CHECK(ggx.exclude == std::vector<std::string>{"ltc", "point", "exact"});
    const SceneQuality phong = effective_quality(*p.scene, Distribution::Phong, nullptr);
    CHECK(phong.max_error == std::optional<double>(0.01));
    CHECK(phong.exclude == std::vector<std::string>{"ltc", "point"});
    // Without quality, everything is unset: fp32, tables and patented allowed.
    const Parsed none = parse(replace(kGood, ",\n  \"quality\": {\"max_error\": 0.01}", ""));
    REQUIRE(none.scene);
    CHECK_FALSE(none.scene->quality.fp64);
    CHECK_FALSE(none.scene->quality.tables);
    CHECK(none.scene->quality.exclude.empty());
}

TEST_CASE("scene: malformed quality fields are rejected naming the field") {
    rejected(replace(kGood, R"("max_error": 0.01)", R"("precision": "fp16")"),
             {"field 'quality.precision'", "fp32", "fp64"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("tables": "yes")"),
             {"field 'quality.tables'", "true or false"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("patented": 1)"),
             {"field 'quality.patented'", "true or false"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("exclude": "ltc")"),
             {"field 'quality.exclude'", "array of method names"});
    rejected(replace(kGood, R"("max_error": 0.01)", R"("exclude": ["ltc", 3])"),
             {"field 'quality.exclude'", "array of method names"});
    rejected(replace(kGood, R"("alpha": 0.3)", R"("alpha": 0.3, "quality": {"max_error": -2})"),
             {"material 0: field 'quality.max_error'", "not a positive"});
    rejected(replace(kGood, R"("alpha": 0.3)", R"("alpha": 0.3, "quality": 5)"),
             {"material 0: field 'quality'", "object"});
}
