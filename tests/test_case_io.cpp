// Case files: every kind of malformed input is rejected with a message naming
// the file, the case and the field; result files round-trip bit for bit.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "arealight/case_io.hpp"

using namespace arealight;
namespace fs = std::filesystem;

namespace {

const char* kGoodCase = R"({"id": "%ID%", "p": [0, 0, 0], "n": [0, 0, 1], "v": [0.3, 0, 1],
  "light": %LIGHT%, "material": %MAT%})";
const char* kQuad = R"({"type": "polygon", "vertices": [[-1,-1,2],[1,-1,2],[1,1,2],[-1,1,2]]})";
const char* kGgx = R"({"distribution": "ggx", "alpha": 0.25})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
}

std::string file_with(const std::string& case_json) {
    return std::string(R"({"format": "arealight-cases/1", "cases": [)") + case_json + "]}";
}

std::string one_case(const std::string& id, const std::string& light, const std::string& mat) {
    return replace(replace(replace(kGoodCase, "%ID%", id), "%LIGHT%", light), "%MAT%", mat);
}

// Parses text and returns all error messages (empty when it parsed).
std::vector<std::string> errors_of(const std::string& text, bool* parsed = nullptr) {
    std::vector<std::string> out;
    auto set =
        parse_cases(text, "cases.json", [&](const Diagnostic& d) { out.push_back(d.message); });
    if (parsed) *parsed = set.has_value();
    CHECK(set.has_value() == out.empty());
    return out;
}

// The first message must start with "cases.json: case 'ID': field 'FIELD'".
void expect_error(const std::string& text, const std::string& id, const std::string& field) {
    bool parsed = true;
    const auto errs = errors_of(text, &parsed);
    const std::string prefix = "cases.json: case '" + id + "': field '" + field;
    INFO("expected prefix: " << prefix << "\nmessages: " << (errs.empty() ? "(none)" : errs[0]));
    CHECK_FALSE(parsed);
    REQUIRE_FALSE(errs.empty());
    CHECK(errs[0].rfind(prefix, 0) == 0);
}

}  // namespace

TEST_CASE("a valid file with every light type parses with its values", "[io]") {
    std::string cases =
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
                 R"({"distribution":"beckmann","alpha":0.001})");
    std::vector<std::string> errs;
    auto set = parse_cases(file_with(cases), "cases.json",
                           [&](const Diagnostic& d) { errs.push_back(d.message); });
    INFO((errs.empty() ? "" : errs[0]));
    REQUIRE(set);
    REQUIRE(set->cases.size() == 4);
    CHECK(set->cases[0].light.vertices.size() == 4);
    CHECK(set->cases[0].material.alpha == 0.25);
    CHECK(set->cases[1].light.type == LightType::Disk);
    CHECK(set->cases[1].light.two_sided);
    CHECK(set->cases[1].material.exponent == 12.5);
    CHECK(set->cases[2].light.radius == 0.5);
    CHECK(set->cases[3].light.axes[1][1] == 2.0);
    CHECK(set->cases[3].material.distribution == Distribution::Beckmann);
}

TEST_CASE("file-level errors name the file and the field", "[io]") {
    auto e1 = errors_of("{ not json");
    REQUIRE(e1.size() == 1);
    CHECK(e1[0].rfind("cases.json: invalid JSON:", 0) == 0);
    auto e2 = errors_of(R"({"format": "arealight-cases/2", "cases": []})");
    REQUIRE(e2.size() == 1);
    CHECK(e2[0].rfind("cases.json: field 'format'", 0) == 0);
    auto e3 = errors_of(R"({"format": "arealight-cases/1", "cases": 3})");
    REQUIRE(e3.size() == 1);
    CHECK(e3[0].rfind("cases.json: field 'cases'", 0) == 0);
    std::vector<std::string> e4;
    CHECK_FALSE(read_cases("/nonexistent/cases.json",
                           [&](const Diagnostic& d) { e4.push_back(d.message); }));
    REQUIRE(e4.size() == 1);
    CHECK(e4[0].rfind("/nonexistent/cases.json: cannot read:", 0) == 0);
}

TEST_CASE("each kind of malformed case is rejected naming case and field", "[io]") {
    const std::string good = one_case("ok", kQuad, kGgx);
    SECTION("ids") {
        // A case without an id is named by its index.
        const auto errs = errors_of(file_with(replace(good, R"("id": "ok", )", "")));
        REQUIRE_FALSE(errs.empty());
        INFO(errs[0]);
        CHECK(errs[0].rfind("cases.json: case #0: field 'id': missing", 0) == 0);
        expect_error(file_with(good + "," + good), "ok", "id");
    }
    SECTION("p, n, v") {
        expect_error(file_with(replace(good, R"("p": [0, 0, 0], )", "")), "ok", "p");
        expect_error(file_with(replace(good, R"("n": [0, 0, 1])", R"("n": [0, 0, 0])")), "ok", "n");
        expect_error(file_with(replace(good, R"("v": [0.3, 0, 1])", R"("v": [0.3, 1e300, 1])")),
                     "ok", "v");
        expect_error(file_with(replace(good, R"("v": [0.3, 0, 1])", R"("v": [0.3, "x", 1])")), "ok",
                     "v");
    }
    SECTION("light type") {
        expect_error(file_with(one_case("t", R"({"type": "tube"})", kGgx)), "t", "light.type");
    }
    SECTION("polygon vertex counts") {
        expect_error(
            file_with(one_case("two", R"({"type":"polygon","vertices":[[0,0,1],[1,0,1]]})", kGgx)),
            "two", "light.vertices");
        expect_error(
            file_with(one_case(
                "nine",
                R"({"type":"polygon","vertices":[[1,0,1],[0.77,0.64,1],[0.17,0.98,1],[-0.5,0.87,1],[-0.94,0.34,1],[-0.94,-0.34,1],[-0.5,-0.87,1],[0.17,-0.98,1],[0.77,-0.64,1]]})",
                kGgx)),
            "nine", "light.vertices");
    }
    SECTION("non-coplanar, non-convex, repeated, collinear") {
        expect_error(
            file_with(one_case(
                "bent", R"({"type":"polygon","vertices":[[-1,-1,2],[1,-1,2],[1,1,2.5],[-1,1,2]]})",
                kGgx)),
            "bent", "light.vertices[");
        expect_error(
            file_with(one_case(
                "dart", R"({"type":"polygon","vertices":[[0,0,2],[2,-1,2],[0.5,0,2],[2,1,2]]})",
                kGgx)),
            "dart", "light.vertices[");
        expect_error(
            file_with(one_case(
                "rep", R"({"type":"polygon","vertices":[[0,0,2],[1,0,2],[1,0,2],[0,1,2]]})", kGgx)),
            "rep", "light.vertices[2]");
        expect_error(
            file_with(one_case(
                "col", R"({"type":"polygon","vertices":[[0,0,2],[1,0,2],[2,0,2],[0,1,2]]})", kGgx)),
            "col", "light.vertices[1]");
    }
    SECTION("disk, sphere, ellipsoid") {
        expect_error(
            file_with(one_case("d", R"({"type":"disk","center":[0,0,2],"u":[1,0,0],"v":[0.5,1,0]})",
                               kGgx)),
            "d", "light.v");
        expect_error(
            file_with(one_case("s0", R"({"type":"sphere","center":[0,0,2],"radius":0})", kGgx)),
            "s0", "light.radius");
        expect_error(
            file_with(one_case("s-", R"({"type":"sphere","center":[0,0,2],"radius":-1})", kGgx)),
            "s-", "light.radius");
        expect_error(
            file_with(one_case(
                "e2", R"({"type":"ellipsoid","center":[0,0,3],"axes":[[1,0,0],[0,1,0]]})", kGgx)),
            "e2", "light.axes");
        expect_error(
            file_with(one_case(
                "eo", R"({"type":"ellipsoid","center":[0,0,3],"axes":[[1,0,0],[0.5,1,0],[0,0,1]]})",
                kGgx)),
            "eo", "light.axes[1]");
    }
    SECTION("materials") {
        expect_error(file_with(one_case("m", kQuad, R"({"distribution":"lambert"})")), "m",
                     "material.distribution");
        expect_error(file_with(one_case("lo", kQuad, R"({"distribution":"phong","exponent":0.5})")),
                     "lo", "material.exponent");
        expect_error(
            file_with(one_case("hi", kQuad, R"({"distribution":"phong","exponent":200000})")), "hi",
            "material.exponent");
        expect_error(file_with(one_case("nx", kQuad, R"({"distribution":"blinn"})")), "nx",
                     "material.exponent");
        expect_error(file_with(one_case("al", kQuad, R"({"distribution":"ggx","alpha":0.0001})")),
                     "al", "material.alpha");
        expect_error(file_with(one_case("ah", kQuad, R"({"distribution":"ggx","alpha":2})")), "ah",
                     "material.alpha");
        expect_error(file_with(one_case("na", kQuad, R"({"distribution":"beckmann"})")), "na",
                     "material.alpha");
    }
}

TEST_CASE("results round-trip bit for bit and are written atomically", "[io]") {
    const fs::path dir = fs::temp_directory_path() / ("arealight-io-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    ResultSet rs;
    rs.variant = "oracle";
    rs.backend = "cpu";
    const double values[] = {0.1, 1.0 / 3.0,    1e-300, 5e-324, 1.7976931348623157e308,
                             0.0, 123456.789e-7};
    for (std::size_t i = 0; i < std::size(values); ++i) {
        CaseResult r;
        r.id = "c" + std::to_string(i);
        r.diffuse = values[i];
        r.specular = values[(i + 1) % std::size(values)];
        r.moment = values[(i + 2) % std::size(values)];
        r.error = 1e-13;
        r.converged = i % 2 == 0;
        rs.results.push_back(r);
    }
    const std::string path = (dir / "out.json").string();
    { std::ofstream(path) << "old"; }
    REQUIRE(write_results(path, rs, {}));
    auto back = read_results(path, {});
    REQUIRE(back);
    REQUIRE(back->results.size() == rs.results.size());
    for (std::size_t i = 0; i < rs.results.size(); ++i) {
        const auto &a = rs.results[i], &b = back->results[i];
        INFO(a.id << " wrote " << *a.diffuse << " read " << *b.diffuse);
        CHECK(std::memcmp(&*a.diffuse, &*b.diffuse, sizeof(double)) == 0);
        CHECK(std::memcmp(&*a.specular, &*b.specular, sizeof(double)) == 0);
        CHECK(std::memcmp(&*a.moment, &*b.moment, sizeof(double)) == 0);
        CHECK(*b.converged == *a.converged);
        CHECK_FALSE(b.ndf);
    }
    // Only the destination remains: no temporary file beside it.
    int files = 0;
    for (auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    CHECK(files == 1);
    // A destination in a missing folder fails, reports the path, and creates nothing.
    std::vector<std::string> errs;
    CHECK_FALSE(write_results((dir / "missing" / "out.json").string(), rs,
                              [&](const Diagnostic& d) { errs.push_back(d.message); }));
    REQUIRE(errs.size() == 1);
    CHECK(errs[0].find("cannot write") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "missing"));
    fs::remove_all(dir);
}
