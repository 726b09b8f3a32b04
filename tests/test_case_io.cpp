// Case files: every kind of malformed input is rejected with a message naming the file, the
// case and the field; result files round-trip bit for bit and are written atomically.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "arealight/case_io.hpp"
#include "arealight/scene.hpp"

using namespace arealight;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
namespace fs = std::filesystem;

namespace {

const char* kQuad = R"({"type": "polygon", "vertices": [[-1,-1,2],[1,-1,2],[1,1,2],[-1,1,2]]})";
const char* kGgx = R"({"distribution": "ggx", "alpha": 0.25})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    REQUIRE(at != std::string::npos);  // a test edit that matches nothing tests nothing
    s.replace(at, from.size(), to);
    return s;
}

std::string file_with(const std::string& cases_json) {
    return std::string(R"({"format": "arealight-cases/1", "cases": [)") + cases_json + "]}";
}

std::string one_case(const std::string& id, const std::string& light = kQuad,
                     const std::string& mat = kGgx) {
    return R"({"id": ")" + id + R"(", "p": [0, 0, 0], "n": [0, 0, 1], "v": [0.3, 0, 1],)" +
           R"( "light": )" + light + R"(, "material": )" + mat + "}";
}

std::string polygon(const std::string& vertices) {
    return R"({"type": "polygon", "vertices": )" + vertices + "}";
}

struct Parsed {
    std::optional<CaseSet> set;
    std::vector<Diagnostic> diags;
    std::string all() const {
        std::string s;
        for (const auto& d : diags) s += d.message + "\n";
        return s.empty() ? "(no messages)" : s;
    }
};

Parsed parse(const std::string& text) {
    Parsed p;
    p.set = parse_cases(text, "cases.json", [&](const Diagnostic& d) { p.diags.push_back(d); });
    return p;
}

// The file holds exactly one defect: it is rejected with exactly one message, which starts
// "cases.json: case 'ID': field 'FIELD': " and gives `reason`.
void expect_error(const std::string& text, const std::string& id, const std::string& field,
                  const std::string& reason) {
    const Parsed p = parse(text);
    INFO("messages:\n" << p.all());
    CHECK_FALSE(p.set);
    REQUIRE(p.diags.size() == 1);
    const Diagnostic& d = p.diags[0];
    CHECK(d.severity == Severity::Error);
    CHECK(d.file == "cases.json");
    CHECK(d.line == 0);
    CHECK_THAT(d.message, StartsWith("cases.json: case '" + id + "': field '" + field + "': "));
    CHECK_THAT(d.message, Contains(reason));
}

// File-level problems: one message "cases.json: PREFIX...".
void expect_file_error(const std::string& text, const std::string& prefix,
                       const std::string& reason = "") {
    const Parsed p = parse(text);
    INFO("messages:\n" << p.all());
    CHECK_FALSE(p.set);
    REQUIRE(p.diags.size() == 1);
    CHECK(p.diags[0].file == "cases.json");
    CHECK_THAT(p.diags[0].message, StartsWith("cases.json: " + prefix));
    CHECK_THAT(p.diags[0].message, Contains(reason));
}

uint64_t bits(double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// A fresh folder under the system temporary directory, removed with everything in it.
struct ScratchDir {
    fs::path path;
    ScratchDir() {
        static int counter = 0;
        path = fs::temp_directory_path() /
               ("arealight-caseio-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

// ---- valid input ---------------------------------------------------------------------------

TEST_CASE("a valid file with every light type parses with its values", "[io]") {
    const std::string cases =
        one_case("quad", kQuad, kGgx) + "," +
        one_case(
            "disk",
            R"({"type":"disk","center":[0,0,2],"u":[0.5,0,0],"v":[0,0.25,0],"two_sided":true})",
            R"({"distribution":"blinn","exponent":12.5})") +
        "," +
        one_case("sphere", R"({"type":"sphere","center":[0,1,3],"radius":0.5})",
                 R"({"distribution":"phong","exponent":100000})") +
        "," +
        one_case("ellipsoid",
                 R"({"type":"ellipsoid","center":[0,0,4],"axes":[[1,0,0],[0,2,0],[0,0,0.5]]})",
                 R"({"distribution":"beckmann","alpha":0.001})") +
        "," +
        // "comment" and "x-..." fields are ignored at every level; n and v are kept as written.
        R"({"id": "tri", "comment": "x", "p": [1, 2, 3], "n": [0, 0, 2], "v": [0.5, -1, 4],
            "light": {"type": "polygon", "vertices": [[0,0,5],[1,0,5],[0,1,5]], "x-colour": 1},
            "material": {"distribution": "ggx", "alpha": 1, "comment": {"why": [7]}}})";
    const Parsed p = parse(file_with(cases));
    INFO("messages:\n" << p.all());
    REQUIRE(p.set);
    CHECK(p.diags.empty());
    const auto& c = p.set->cases;
    REQUIRE(c.size() == 5);

    CHECK(c[0].id == "quad");
    CHECK(c[0].p == Vec3{0, 0, 0});
    CHECK(c[0].n == Vec3{0, 0, 1});
    CHECK(c[0].v == Vec3{0.3, 0, 1});
    CHECK(c[0].light.type == LightType::Polygon);
    REQUIRE(c[0].light.vertices.size() == 4);
    CHECK(c[0].light.vertices[2] == Vec3{1, 1, 2});
    CHECK_FALSE(c[0].light.two_sided);
    CHECK(c[0].material.distribution == Distribution::Ggx);
    CHECK(c[0].material.alpha == 0.25);

    CHECK(c[1].light.type == LightType::Disk);
    CHECK(c[1].light.center == Vec3{0, 0, 2});
    CHECK(c[1].light.u == Vec3{0.5, 0, 0});
    CHECK(c[1].light.v == Vec3{0, 0.25, 0});
    CHECK(c[1].light.two_sided);
    CHECK(c[1].material.distribution == Distribution::Blinn);
    CHECK(c[1].material.exponent == 12.5);

    CHECK(c[2].light.type == LightType::Sphere);
    CHECK(c[2].light.center == Vec3{0, 1, 3});
    CHECK(c[2].light.radius == 0.5);
    CHECK(c[2].material.distribution == Distribution::Phong);
    CHECK(c[2].material.exponent == 100000.0);

    CHECK(c[3].light.type == LightType::Ellipsoid);
    CHECK(c[3].light.center == Vec3{0, 0, 4});
    CHECK(c[3].light.axes[0] == Vec3{1, 0, 0});
    CHECK(c[3].light.axes[1] == Vec3{0, 2, 0});
    CHECK(c[3].light.axes[2] == Vec3{0, 0, 0.5});
    CHECK(c[3].material.distribution == Distribution::Beckmann);
    CHECK(c[3].material.alpha == 0.001);

    CHECK(c[4].p == Vec3{1, 2, 3});
    CHECK(c[4].n == Vec3{0, 0, 2});
    CHECK(c[4].v == Vec3{0.5, -1, 4});
    CHECK(c[4].light.vertices.size() == 3);
    CHECK(c[4].material.alpha == 1.0);
}

TEST_CASE("polygons pass in either orientation, far from the origin, within tolerance", "[io]") {
    // Clockwise seen from +z: convexity is judged about the polygon's own normal.
    CHECK(parse(file_with(one_case("cw", polygon("[[0,0,2],[0,1,2],[1,1,2],[1,0,2]]")))).set);
    // Size 1 at 1e9 from the origin: the plane must not be lost to cancellation.
    CHECK(parse(file_with(one_case(
                    "far", polygon("[[1e9,1e9,2],[1000000001,1e9,2],[1000000001,1000000001,2],"
                                   "[1e9,1000000001,2]]"))))
              .set);
    // 1e-8 off the plane of a polygon of diameter 2.8 is within coplanar_rel = 1e-6.
    CHECK(parse(file_with(one_case("flat", polygon("[[-1,-1,2],[1,-1,2],[1,1,2.00000001],"
                                                   "[-1,1,2]]"))))
              .set);
    // The tolerance is the caller's: tighter rejects the same polygon.
    std::vector<std::string> msgs;
    ValidationTolerances tight;
    tight.coplanar_rel = 1e-10;
    tight.fp32_ulps = 0.0;
    CHECK_FALSE(parse_cases(
        file_with(one_case("flat", polygon("[[-1,-1,2],[1,-1,2],[1,1,2.00000001],[-1,1,2]]"))),
        "cases.json", [&](const Diagnostic& d) { msgs.push_back(d.message); }, tight));
    REQUIRE(msgs.size() == 1);
    CHECK_THAT(msgs[0], Contains("not coplanar"));
}

TEST_CASE("an empty case list is a valid file", "[io]") {
    const Parsed p = parse(R"({"format": "arealight-cases/1", "cases": []})");
    INFO(p.all());
    REQUIRE(p.set);
    CHECK(p.set->cases.empty());
}

// ---- file-level errors ---------------------------------------------------------------------

TEST_CASE("malformed: bad JSON", "[io]") {
    expect_file_error("{ \"format\": ", "invalid JSON: ", "parse error");
    // A number beyond the double range: nlohmann throws out_of_range, not parse_error.
    expect_file_error(R"({"format": "arealight-cases/1", "cases": [1e400]})",
                      "invalid JSON: ", "1e400");
}

TEST_CASE("malformed: wrong or missing format, cases not an array", "[io]") {
    expect_file_error(R"({"format": "arealight-cases/2", "cases": []})",
                      "field 'format': ", "arealight-cases/2");
    expect_file_error(R"({"cases": []})", "field 'format': ", "missing");
    expect_file_error(R"([1, 2])", "field 'format': ", "JSON object");
    expect_file_error(R"({"format": "arealight-cases/1", "cases": 3})", "field 'cases': ", "array");
    expect_file_error(R"({"format": "arealight-cases/1"})", "field 'cases': ", "missing");
}

// Found while fuzzing the readers (by hand: the fuzzer's 4 kB inputs nest too little): the
// message printed the value with dump(), which recurses per level and overflowed the stack
// (a segfault) at 100000 levels, a 200 kB file.
TEST_CASE("malformed: a deeply nested format value is named, not printed", "[io]") {
    constexpr int kDepth = 200000;
    const std::string nested = std::string(kDepth, '[') + std::string(kDepth, ']');
    std::vector<std::string> msgs;
    auto collect = [&](const Diagnostic& d) { msgs.push_back(d.message); };
    CHECK_FALSE(parse_cases(R"({"format": )" + nested + R"(, "cases": []})", "deep.json", collect));
    CHECK_FALSE(parse_results(R"({"format": )" + nested + R"(, "results": []})", "deep.json",
                              collect));
    CHECK_FALSE(parse_scene(R"({"format": )" + nested + "}", "deep.json", collect));
    REQUIRE(msgs.size() == 3);
    CHECK(msgs[0] == "deep.json: field 'format': is an array, expected \"arealight-cases/1\"");
    CHECK(msgs[1] == "deep.json: field 'format': is an array, expected \"arealight-results/1\"");
    CHECK(msgs[2] == "deep.json: field 'format': is an array, expected \"arealight-scene/1\"");
}

TEST_CASE("malformed: unreadable file", "[io]") {
    std::vector<std::string> msgs;
    auto collect = [&](const Diagnostic& d) { msgs.push_back(d.message); };
    CHECK_FALSE(read_cases("/nonexistent/cases.json", collect));
    REQUIRE(msgs.size() == 1);
    CHECK(msgs[0] == std::string("/nonexistent/cases.json: cannot read: ") + std::strerror(ENOENT));
    // A folder opens but cannot be read: that is a read error, not invalid JSON.
    ScratchDir dir;
    msgs.clear();
    CHECK_FALSE(read_cases(dir.path.string(), collect));
    REQUIRE(msgs.size() == 1);
    CHECK(msgs[0] == dir.path.string() + ": cannot read: " + std::strerror(EISDIR));
}

// ---- ids and the shading point -------------------------------------------------------------

TEST_CASE("malformed: missing id is named by the case's index", "[io]") {
    const std::string no_id = replace(one_case("x"), R"("id": "x", )", "");
    const Parsed p = parse(file_with(one_case("a") + "," + no_id));
    INFO("messages:\n" << p.all());
    CHECK_FALSE(p.set);
    REQUIRE(p.diags.size() == 1);
    CHECK(p.diags[0].message == "cases.json: case #1: field 'id': missing");
    const Parsed empty = parse(file_with(replace(one_case("x"), R"("id": "x")", R"("id": "")")));
    INFO("messages:\n" << empty.all());
    REQUIRE(empty.diags.size() == 1);
    CHECK_THAT(empty.diags[0].message, StartsWith("cases.json: case #0: field 'id': "));
}

TEST_CASE("malformed: a case that is not an object", "[io]") {
    expect_file_error(file_with(one_case("a") + ", 7"), "field 'cases[1]': ", "must be an object");
}

TEST_CASE("malformed: duplicate id", "[io]") {
    expect_error(file_with(one_case("twin") + "," + one_case("twin")), "twin", "id", "duplicates");
}

TEST_CASE("malformed: missing p, n or v", "[io]") {
    const std::string c = one_case("pt");
    expect_error(file_with(replace(c, R"("p": [0, 0, 0],)", "")), "pt", "p", "missing");
    expect_error(file_with(replace(c, R"("n": [0, 0, 1],)", "")), "pt", "n", "missing");
    expect_error(file_with(replace(c, R"("v": [0.3, 0, 1],)", "")), "pt", "v", "missing");
    expect_error(file_with(replace(c, R"("v": [0.3, 0, 1])", R"("v": [0.3, "x", 1])")), "pt", "v",
                 "3 numbers");
    expect_error(file_with(replace(c, R"("p": [0, 0, 0])", R"("p": [0, 0])")), "pt", "p",
                 "3 numbers");
}

TEST_CASE("malformed: zero-length n or v", "[io]") {
    const std::string c = one_case("z");
    expect_error(file_with(replace(c, R"("n": [0, 0, 1])", R"("n": [0, 0, 0])")), "z", "n",
                 "non-zero length");
    expect_error(file_with(replace(c, R"("v": [0.3, 0, 1])", R"("v": [0, 0, 0])")), "z", "v",
                 "non-zero length");
}

TEST_CASE("malformed: huge value", "[io]") {
    expect_error(
        file_with(replace(one_case("big"), R"("v": [0.3, 0, 1])", R"("v": [0.3, 1e300, 1])")),
        "big", "v", "component 1");
    expect_error(
        file_with(one_case("bigr", R"({"type":"sphere","center":[0,0,2],"radius":1e300})")), "bigr",
        "light.radius", "1e+300");
}

// ---- lights --------------------------------------------------------------------------------

TEST_CASE("malformed: unknown light type", "[io]") {
    expect_error(file_with(one_case("t", R"({"type": "tube"})")), "t", "light.type",
                 "unknown type 'tube'");
    expect_error(file_with(one_case("t", R"({"center": [0, 0, 1]})")), "t", "light.type",
                 "missing");
}

TEST_CASE("malformed: polygon with 2 vertices", "[io]") {
    expect_error(file_with(one_case("two", polygon("[[0,0,1],[1,0,1]]"))), "two", "light.vertices",
                 "has 2 vertices");
}

TEST_CASE("malformed: polygon with 9 vertices", "[io]") {
    expect_error(file_with(one_case("nine", polygon("[[1,0,1],[0.77,0.64,1],[0.17,0.98,1],"
                                                    "[-0.5,0.87,1],[-0.94,0.34,1],[-0.94,-0.34,1],"
                                                    "[-0.5,-0.87,1],[0.17,-0.98,1],"
                                                    "[0.77,-0.64,1]]"))),
                 "nine", "light.vertices", "has 9 vertices");
}

TEST_CASE("malformed: non-coplanar polygon", "[io]") {
    expect_error(file_with(one_case("bent", polygon("[[-1,-1,2],[1,-1,2],[1,1,2.5],[-1,1,2]]"))),
                 "bent", "light.vertices[0]", "not coplanar");
}

TEST_CASE("malformed: non-convex polygon (dart)", "[io]") {
    // An arrowhead pointing at +x; vertex 2 is the notch.
    expect_error(file_with(one_case("dart", polygon("[[0,0,2],[2,-1,2],[0.5,0,2],[2,1,2]]"))),
                 "dart", "light.vertices[2]", "not convex");
}

TEST_CASE("malformed: self-intersecting polygon (pentagram, bowties)", "[io]") {
    // Every turn has the same sign, yet the outline goes around twice.
    expect_error(file_with(one_case("star", polygon("[[1,0,2],[-0.809017,0.587785,2],"
                                                    "[0.309017,-0.951057,2],"
                                                    "[0.309017,0.951057,2],"
                                                    "[-0.809017,-0.587785,2]]"))),
                 "star", "light.vertices", "edges 0-1 and 2-3 cross: the polygon is self-intersecting");
    // A symmetric bowtie has no net (Newell) area; an uneven one has some: both cross.
    expect_error(file_with(one_case("bow", polygon("[[0,0,2],[1,1,2],[1,0,2],[0,1,2]]"))), "bow",
                 "light.vertices", "edges 0-1 and 2-3 cross: the polygon is self-intersecting");
    expect_error(file_with(one_case("bow2", polygon("[[0,0,2],[2,1,2],[2,0,2],[0,1.5,2]]"))),
                 "bow2", "light.vertices", "self-intersecting");
}

TEST_CASE("malformed: an unknown field anywhere is an error naming the nearest known one",
          "[io]") {
    const std::string c = one_case("u");
    expect_error(file_with(replace(c, R"("p": [0, 0, 0],)", R"("p": [0, 0, 0], "pos": 1,)")), "u",
                 "pos", "unknown field (did you mean 'p'?)");
    expect_error(file_with(one_case("ts", R"({"type": "polygon", "two_side": true,
                                             "vertices": [[-1,-1,2],[1,-1,2],[1,1,2],[-1,1,2]]})")),
                 "ts", "light.two_side", "unknown field (did you mean 'light.two_sided'?)");
    // A field of another light type is unknown to this one.
    expect_error(file_with(one_case("sr", R"({"type":"sphere","center":[0,0,2],"radius":1,
                                             "two_sided":true})")),
                 "sr", "light.two_sided", "unknown field");
    expect_error(file_with(one_case("al", kQuad, R"({"distribution":"ggx","alpha":0.2,"alpah":1})")),
                 "al", "material.alpah", "did you mean 'material.alpha'?");
    // Phong has no Fresnel factor (CONTRACT 2): f0 is no field of a Phong material.
    expect_error(file_with(one_case("pf", kQuad, R"({"distribution":"phong","exponent":10,"f0":0.5})")),
                 "pf", "material.f0", "unknown field");
    expect_file_error(
        R"({"format": "arealight-cases/1", "cases": [], "case": []})", "field 'case': ",
        "unknown field (did you mean 'cases'?)");
}

TEST_CASE("fp32-rounded lights pass the planarity and orthogonality checks (CONTRACT 3)",
          "[io]") {
    // A small quad 4 units from the origin whose vertices were rounded to fp32: z differs
    // from 4 by one fp32 ulp there (4.77e-7), far above 1e-6 of its diameter 0.014
    // (1.4e-8) yet within 8 ulp, so it is accepted...
    const Parsed ok = parse(file_with(one_case(
        "r32", polygon("[[0.01,0.01,4],[0.02,0.01,4],[0.02,0.02,4.000000476837158],"
                       "[0.01,0.02,4]]"))));
    INFO(ok.all());
    CHECK(ok.set);
    // ...while a vertex 100 ulp off (each vertex then ~25 ulp off the best plane) is not.
    expect_error(file_with(one_case("r32far", polygon("[[0.01,0.01,4],[0.02,0.01,4],"
                                                      "[0.02,0.02,4.0000476837],[0.01,0.02,4]]"))),
                 "r32far", "light.vertices[0]", "not coplanar");
    // Disk axes 1 ulp of fp32 away from orthogonal pass.
    const Parsed disk = parse(file_with(one_case(
        "d32", R"({"type":"disk","center":[0,0,2],"u":[0.6,0.8,0],"v":[-0.800000011920929,0.6,0]})")));
    INFO(disk.all());
    CHECK(disk.set);
}

TEST_CASE("malformed: repeated consecutive vertex", "[io]") {
    expect_error(file_with(one_case("rep", polygon("[[0,0,2],[1,0,2],[1,0,2],[0,1,2]]"))), "rep",
                 "light.vertices[2]", "repeats vertex 1");
    // The closing edge, last to first, counts too.
    expect_error(file_with(one_case("wrap", polygon("[[0,0,2],[1,0,2],[0,1,2],[0,0,2]]"))), "wrap",
                 "light.vertices[0]", "repeats vertex 3");
}

TEST_CASE("malformed: collinear consecutive vertices", "[io]") {
    expect_error(file_with(one_case("col", polygon("[[0,0,2],[1,0,2],[2,0,2],[0,1,2]]"))), "col",
                 "light.vertices[1]", "collinear");
}

TEST_CASE("malformed: disk with non-orthogonal u and v", "[io]") {
    expect_error(
        file_with(one_case("d", R"({"type":"disk","center":[0,0,2],"u":[1,0,0],"v":[0.5,1,0]})")),
        "d", "light.v", "orthogonal to light.u");
    expect_error(
        file_with(one_case("d0", R"({"type":"disk","center":[0,0,2],"u":[0,0,0],"v":[0,1,0]})")),
        "d0", "light.u", "non-zero length");
}

TEST_CASE("malformed: sphere with radius 0 or negative", "[io]") {
    expect_error(file_with(one_case("s0", R"({"type":"sphere","center":[0,0,2],"radius":0})")),
                 "s0", "light.radius", "not positive");
    expect_error(file_with(one_case("sneg", R"({"type":"sphere","center":[0,0,2],"radius":-1})")),
                 "sneg", "light.radius", "not positive");
}

TEST_CASE("malformed: ellipsoid with 2 axes", "[io]") {
    expect_error(file_with(one_case(
                     "e2", R"({"type":"ellipsoid","center":[0,0,3],"axes":[[1,0,0],[0,1,0]]})")),
                 "e2", "light.axes", "has 2 vectors");
}

TEST_CASE("malformed: ellipsoid with non-orthogonal axes", "[io]") {
    expect_error(
        file_with(one_case(
            "eo", R"({"type":"ellipsoid","center":[0,0,3],"axes":[[1,0,0],[0.5,1,0],[0,0,1]]})")),
        "eo", "light.axes[1]", "orthogonal to light.axes[0]");
}

// ---- materials -----------------------------------------------------------------------------

TEST_CASE("malformed: unknown distribution", "[io]") {
    expect_error(file_with(one_case("m", kQuad, R"({"distribution":"lambert"})")), "m",
                 "material.distribution", "unknown distribution 'lambert'");
}

TEST_CASE("malformed: phong exponent out of range or missing", "[io]") {
    expect_error(file_with(one_case("lo", kQuad, R"({"distribution":"phong","exponent":0.5})")),
                 "lo", "material.exponent", "0.5 is outside [1, 100000]");
    expect_error(file_with(one_case("hi", kQuad, R"({"distribution":"phong","exponent":200000})")),
                 "hi", "material.exponent", "200000 is outside [1, 100000]");
    expect_error(file_with(one_case("nx", kQuad, R"({"distribution":"blinn"})")), "nx",
                 "material.exponent", "missing");
}

TEST_CASE("malformed: ggx alpha out of range or missing", "[io]") {
    expect_error(file_with(one_case("al", kQuad, R"({"distribution":"ggx","alpha":0.0001})")), "al",
                 "material.alpha", "0.0001 is outside [0.001, 1]");
    expect_error(file_with(one_case("ah", kQuad, R"({"distribution":"ggx","alpha":2})")), "ah",
                 "material.alpha", "2 is outside [0.001, 1]");
    expect_error(file_with(one_case("na", kQuad, R"({"distribution":"beckmann"})")), "na",
                 "material.alpha", "missing");
}

TEST_CASE("f0 of a microfacet material is read in [0, 1]; absent means F = 1", "[io]") {
    const std::string cases =
        one_case("ggx-0", kQuad, R"({"distribution":"ggx","alpha":0.25,"f0":0})") + "," +
        one_case("beckmann-004", kQuad, R"({"distribution":"beckmann","alpha":0.1,"f0":0.04})") +
        "," + one_case("blinn-1", kQuad, R"({"distribution":"blinn","exponent":50,"f0":1})") + "," +
        one_case("none") + "," +
        one_case("phong", kQuad, R"({"distribution":"phong","exponent":10})");
    const Parsed p = parse(file_with(cases));
    INFO("messages:\n" << p.all());
    REQUIRE(p.set);
    CHECK(p.diags.empty());
    const auto& c = p.set->cases;
    REQUIRE(c.size() == 5);
    CHECK(c[0].material.has_f0);
    CHECK(c[0].material.f0 == 0.0);
    CHECK(c[1].material.has_f0);
    CHECK(c[1].material.f0 == 0.04);
    CHECK(c[2].material.has_f0);
    CHECK(c[2].material.f0 == 1.0);
    CHECK_FALSE(c[3].material.has_f0);
    CHECK(c[3].material.f0 == 1.0);
    CHECK_FALSE(c[4].material.has_f0);
    CHECK(c[4].material.f0 == 1.0);
}

TEST_CASE("malformed: f0 out of [0, 1] or not a number", "[io]") {
    expect_error(
        file_with(one_case("neg", kQuad, R"({"distribution":"ggx","alpha":0.25,"f0":-0.1})")),
        "neg", "material.f0", "-0.1 is outside [0, 1]");
    expect_error(
        file_with(one_case("big", kQuad, R"({"distribution":"beckmann","alpha":0.2,"f0":1.5})")),
        "big", "material.f0", "1.5 is outside [0, 1]");
    expect_error(
        file_with(one_case("str", kQuad, R"({"distribution":"blinn","exponent":20,"f0":"x"})")),
        "str", "material.f0", "must be a number");
    expect_error(
        file_with(one_case("null", kQuad, R"({"distribution":"ggx","alpha":0.25,"f0":null})")),
        "null", "material.f0", "must be a number");
}

TEST_CASE("every error in a file is reported, not just the first", "[io]") {
    const std::string text =
        file_with(one_case("good") + "," +
                  one_case("two-bad", R"({"type":"sphere","center":[0,0,2],"radius":-1})",
                           R"({"distribution":"ggx","alpha":5})") +
                  "," + one_case("dart", polygon("[[0,0,2],[2,-1,2],[0.5,0,2],[2,1,2]]")));
    const Parsed p = parse(text);
    INFO("messages:\n" << p.all());
    CHECK_FALSE(p.set);
    REQUIRE(p.diags.size() == 3);
    CHECK_THAT(p.diags[0].message, StartsWith("cases.json: case 'two-bad': field 'light.radius'"));
    CHECK_THAT(p.diags[1].message,
               StartsWith("cases.json: case 'two-bad': field 'material.alpha'"));
    CHECK_THAT(p.diags[2].message,
               StartsWith("cases.json: case 'dart': field 'light.vertices[2]'"));
}

// ---- results -------------------------------------------------------------------------------

namespace {

ResultSet sample_results() {
    ResultSet rs;
    rs.variant = "dist=ggx,method=exact,light=polygon";
    rs.backend = "cpu";
    const double values[] = {0.1,
                             1.0 / 3.0,
                             1e-300,
                             5e-324,
                             1.7976931348623157e308,
                             0.0,
                             -0.0,
                             2.2250738585072014e-308,
                             123456.789e-7,
                             std::nextafter(1.0, 2.0)};
    const std::size_t n = std::size(values);
    for (std::size_t i = 0; i < n; ++i) {
        CaseResult r;
        r.id = "c" + std::to_string(i);
        r.diffuse = values[i];
        r.specular = values[(i + 1) % n];
        r.ndf = values[(i + 2) % n];
        r.moment = values[(i + 3) % n];
        r.error = values[(i + 4) % n];
        r.error_diffuse = values[(i + 5) % n];
        r.error_ndf = values[(i + 6) % n];
        r.error_moment = values[(i + 7) % n];
        r.converged = i % 2 == 0;
        rs.results.push_back(r);
    }
    return rs;
}

void check_same_bits(const std::optional<double>& a, const std::optional<double>& b) {
    REQUIRE(a.has_value() == b.has_value());
    if (a) {
        INFO("wrote " << *a << " read " << *b);
        CHECK(bits(*a) == bits(*b));
    }
}

}  // namespace

TEST_CASE("results round-trip bit for bit through write_results and read_results", "[io]") {
    ScratchDir dir;
    const ResultSet rs = sample_results();
    const std::string path = (dir.path / "out.json").string();
    std::vector<std::string> msgs;
    auto collect = [&](const Diagnostic& d) { msgs.push_back(d.message); };
    REQUIRE(write_results(path, rs, collect));
    auto back = read_results(path, collect);
    INFO("messages: " << (msgs.empty() ? "(none)" : msgs[0]));
    REQUIRE(back);
    CHECK(msgs.empty());
    CHECK(back->variant == rs.variant);
    CHECK(back->backend == rs.backend);
    REQUIRE(back->results.size() == rs.results.size());
    for (std::size_t i = 0; i < rs.results.size(); ++i) {
        const auto &a = rs.results[i], &b = back->results[i];
        INFO("case " << a.id);
        CHECK(b.id == a.id);
        check_same_bits(a.diffuse, b.diffuse);
        check_same_bits(a.specular, b.specular);
        check_same_bits(a.ndf, b.ndf);
        check_same_bits(a.moment, b.moment);
        check_same_bits(a.error, b.error);
        check_same_bits(a.error_diffuse, b.error_diffuse);
        check_same_bits(a.error_ndf, b.error_ndf);
        check_same_bits(a.error_moment, b.error_moment);
        CHECK(b.converged == a.converged);
    }
}

TEST_CASE("format_results prints digits that strtod reads back exactly", "[io]") {
    // Independent of nlohmann's own parser: the printed text alone must carry every bit.
    for (double x : {0.1, 1.0 / 3.0, 1e-300, 5e-324, 1.7976931348623157e308, 2.0 / 3.0 * 1e-5}) {
        ResultSet rs;
        CaseResult r;
        r.id = "x";
        r.diffuse = x;
        rs.results.push_back(r);
        const std::string text = format_results(rs);
        const std::string key = "\"diffuse\": ";
        const auto at = text.find(key);
        REQUIRE(at != std::string::npos);
        const std::string number =
            text.substr(at + key.size(), text.find('\n', at) - at - key.size());
        INFO("printed " << number);
        CHECK(bits(std::strtod(number.c_str(), nullptr)) == bits(x));
    }
}

TEST_CASE("format_results writes keys in contract order, only the present fields", "[io]") {
    ResultSet rs;
    rs.variant = "v";
    rs.backend = "vulkan";
    CaseResult r;
    r.id = "a";
    r.diffuse = 0.5;
    r.specular = 0.25;
    rs.results.push_back(r);
    CaseResult full;
    full.id = "b";
    full.diffuse = full.specular = full.ndf = full.moment = 1.0;
    full.error = full.error_diffuse = full.error_ndf = full.error_moment = 2.0;
    full.converged = false;
    rs.results.push_back(full);
    const std::string expected = R"({
 "format": "arealight-results/1",
 "variant": "v",
 "backend": "vulkan",
 "results": [
  {
   "id": "a",
   "diffuse": 0.5,
   "specular": 0.25
  },
  {
   "id": "b",
   "diffuse": 1.0,
   "specular": 1.0,
   "ndf": 1.0,
   "moment": 1.0,
   "error": 2.0,
   "error_diffuse": 2.0,
   "error_ndf": 2.0,
   "error_moment": 2.0,
   "converged": false
  }
 ]
}
)";
    CHECK(format_results(rs) == expected);
}

TEST_CASE("non-finite results are written as null and read back as absent", "[io]") {
    ScratchDir dir;
    ResultSet rs;
    rs.variant = "v";
    rs.backend = "cpu";
    CaseResult r;
    r.id = "nan";
    r.diffuse = std::numeric_limits<double>::quiet_NaN();
    r.specular = std::numeric_limits<double>::infinity();
    r.ndf = -std::numeric_limits<double>::infinity();
    r.moment = 0.5;
    rs.results.push_back(r);
    const std::string text = format_results(rs);
    INFO(text);
    CHECK_THAT(text, Contains("\"diffuse\": null"));
    CHECK_THAT(text, Contains("\"specular\": null"));
    CHECK_THAT(text, Contains("\"ndf\": null"));
    const std::string path = (dir.path / "nan.json").string();
    REQUIRE(write_results(path, rs, {}));
    auto back = read_results(path, {});
    REQUIRE(back);
    REQUIRE(back->results.size() == 1);
    CHECK_FALSE(back->results[0].diffuse);
    CHECK_FALSE(back->results[0].specular);
    CHECK_FALSE(back->results[0].ndf);
    CHECK(back->results[0].moment == 0.5);
}

TEST_CASE("read_results tolerates missing fields and rejects wrong types", "[io]") {
    ScratchDir dir;
    const fs::path path = dir.path / "r.json";
    std::vector<std::string> msgs;
    auto collect = [&](const Diagnostic& d) { msgs.push_back(d.message); };

    std::ofstream(path) << R"({"format": "arealight-results/1", "results": [
        {"id": "a"}, {"id": "b", "specular": 0.5, "error": null, "converged": null}]})";
    auto ok = read_results(path.string(), collect);
    INFO("messages: " << (msgs.empty() ? "(none)" : msgs[0]));
    REQUIRE(ok);
    CHECK(ok->variant.empty());
    REQUIRE(ok->results.size() == 2);
    CHECK_FALSE(ok->results[0].diffuse);
    CHECK(ok->results[1].specular == 0.5);
    CHECK_FALSE(ok->results[1].error);
    CHECK_FALSE(ok->results[1].converged);

    // Wrong types are reported, never thrown.
    std::ofstream(path) << R"({"format": 3, "results": []})";
    msgs.clear();
    CHECK_FALSE(read_results(path.string(), collect));
    REQUIRE(msgs.size() == 1);
    CHECK_THAT(msgs[0], StartsWith(path.string() + ": field 'format': "));

    std::ofstream(path) << R"({"format": "arealight-results/1", "variant": 1,
        "results": [3, {"id": "x", "diffuse": "big"}]})";
    msgs.clear();
    CHECK_FALSE(read_results(path.string(), collect));
    REQUIRE(msgs.size() == 3);
    CHECK_THAT(msgs[0], StartsWith(path.string() + ": field 'variant': "));
    CHECK_THAT(msgs[1], StartsWith(path.string() + ": field 'results[0]': "));
    CHECK_THAT(msgs[2], StartsWith(path.string() + ": field 'results[1].diffuse': "));

    msgs.clear();
    CHECK_FALSE(read_results((dir.path / "absent.json").string(), collect));
    REQUIRE(msgs.size() == 1);
    CHECK_THAT(msgs[0], Contains("cannot read: "));
}

TEST_CASE("write_results into a missing folder fails and creates nothing", "[io]") {
    ScratchDir dir;
    const fs::path dest = dir.path / "missing" / "out.json";
    std::vector<Diagnostic> diags;
    CHECK_FALSE(write_results(dest.string(), sample_results(),
                              [&](const Diagnostic& d) { diags.push_back(d); }));
    REQUIRE(diags.size() == 1);
    CHECK(diags[0].severity == Severity::Error);
    CHECK(diags[0].file == dest.string());
    CHECK(diags[0].message == dest.string() + ": cannot write: " + std::strerror(ENOENT));
    CHECK_FALSE(fs::exists(dir.path / "missing"));
    CHECK(dir.entries().empty());
}

TEST_CASE("write_results replaces an existing file atomically and leaves no temporary", "[io]") {
    ScratchDir dir;
    const fs::path dest = dir.path / "out.json";
    std::ofstream(dest) << "old contents";
    struct stat before {};
    REQUIRE(::stat(dest.c_str(), &before) == 0);
    const ResultSet rs = sample_results();
    REQUIRE(write_results(dest.string(), rs, {}));
    CHECK(slurp(dest) == format_results(rs));
    // A new inode: the file was renamed into place, not rewritten where readers could see
    // it half-written (the old inode still exists while the temporary is created).
    struct stat after {};
    REQUIRE(::stat(dest.c_str(), &after) == 0);
    CHECK(after.st_ino != before.st_ino);
    CHECK(dir.entries() == std::vector<std::string>{"out.json"});
}

TEST_CASE("a failed write_results leaves the destination untouched", "[io]") {
    ScratchDir dir;
    // A folder in the destination's place: the temporary is written, the rename fails.
    const fs::path dest = dir.path / "out.json";
    fs::create_directories(dest / "inside");
    std::vector<std::string> msgs;
    CHECK_FALSE(write_results(dest.string(), sample_results(),
                              [&](const Diagnostic& d) { msgs.push_back(d.message); }));
    REQUIRE(msgs.size() == 1);
    CHECK_THAT(msgs[0], StartsWith(dest.string() + ": cannot write: "));
    CHECK(fs::is_directory(dest / "inside"));
    CHECK(dir.entries() == std::vector<std::string>{"out.json"});
}
