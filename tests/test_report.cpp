// The report and sweep helpers that need no device: the sweep tables, the case
// overrides of both sweep axes, the point baseline of every variant, and the
// second error quantity (moment or ndf) in the tables.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "arealight/report.hpp"

using namespace arealight;

namespace {

double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

// The text without blanks and line breaks.
std::string squeezed(const std::string& s) {
    std::string o;
    for (char ch : s)
        if (ch != ' ' && ch != '\n') o += ch;
    return o;
}

Case polygon_case(Distribution d) {
    Case c;
    c.id = "c";
    c.p = {0, 0, 0};
    c.n = {0, 0, 2};
    c.v = {1, 0, 1};
    c.light.vertices = {{-1, -1, 3}, {-1, 1, 3}, {1, 1, 3}, {1, -1, 3}};
    c.material.distribution = d;
    c.material.exponent = is_microfacet(d) && d != Distribution::Blinn ? 0 : 50;
    c.material.alpha = d == Distribution::Beckmann || d == Distribution::Ggx ? 0.3 : 0;
    return c;
}

}  // namespace

TEST_CASE("sweep tables: one row per distribution, values in the contract's range", "[report]") {
    for (Distribution d :
         {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann, Distribution::Ggx}) {
        const SweepParameter& p = sweep_parameter(d);
        CHECK(p.dist == d);
        REQUIRE(!p.values.empty());
        for (std::size_t k = 0; k < p.values.size(); ++k) {
            CHECK(p.values[k] >= p.min);
            CHECK(p.values[k] <= p.max);
            if (k) CHECK(p.values[k] > p.values[k - 1]);
        }
    }
    CHECK(sweep_parameter(Distribution::Phong).field == "exponent");
    CHECK(sweep_parameter(Distribution::Blinn).field == "exponent");
    CHECK(sweep_parameter(Distribution::Ggx).field == "alpha");
    CHECK(sweep_parameter(Distribution::Beckmann).values ==
          std::vector<double>{0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1});
    CHECK(sweep_parameter(Distribution::Phong).values.size() == 11);
    CHECK(view_sweep_cosines().front() == 1);
    CHECK(view_sweep_cosines().back() == 0.01);
    CHECK(parse_sweep_axis("param") == SweepAxis::Param);
    CHECK(parse_sweep_axis("view") == SweepAxis::View);
    CHECK(!parse_sweep_axis("none"));
    CHECK(!parse_sweep_axis("exponent"));
}

TEST_CASE("sweep_case param: the distribution's own parameter, nothing else", "[report]") {
    const Case g = sweep_case(polygon_case(Distribution::Ggx), SweepAxis::Param, 0.01);
    CHECK(g.material.alpha == 0.01);
    CHECK(g.material.exponent == 0);
    CHECK(g.v == polygon_case(Distribution::Ggx).v);
    const Case b = sweep_case(polygon_case(Distribution::Blinn), SweepAxis::Param, 1000);
    CHECK(b.material.exponent == 1000);
    CHECK(b.material.alpha == 0);
    const Case p = sweep_case(polygon_case(Distribution::Phong), SweepAxis::Param, 3);
    CHECK(p.material.exponent == 3);
    const Case n = sweep_case(polygon_case(Distribution::Phong), SweepAxis::None, 3);
    CHECK(n.material.exponent == 50);
}

TEST_CASE("sweep_case view: unit v at the angle asked, in the plane of n and v", "[report]") {
    const std::vector<std::pair<Vec3, Vec3>> nv = {
        {{0, 0, 2}, {1, 0, 1}},
        {{0.3, -0.2, 1}, {-2, 1, 0.5}},
        {{1, 1, 1}, {1, 1, 1}},       // v along n: any plane
        {{0, 1, 0}, {0.2, -1, 0.3}},  // v below the horizon
    };
    for (const auto& [n, v] : nv) {
        for (double c : view_sweep_cosines()) {
            Case in = polygon_case(Distribution::Ggx);
            in.n = n;
            in.v = v;
            const Case out = sweep_case(in, SweepAxis::View, c);
            CHECK(out.n == n);
            CHECK(out.p == in.p);
            CHECK(norm(out.v) == Approx(1).margin(1e-14));
            CHECK(dot(out.v, n) / norm(n) == Approx(c).margin(1e-14));
            const Vec3 vn = cross(n, v);
            if (norm(vn) > 1e-9 * norm(n) * norm(v)) {
                // In the plane of n and v, on v's side of n.
                CHECK(dot(out.v, vn) == Approx(0).margin(1e-12 * norm(vn)));
                CHECK(dot(cross(n, out.v), vn) >= 0);
            }
        }
    }
}

TEST_CASE("baseline_of: the point variant of the same distribution and shape", "[report]") {
    for (const auto& v : enumerate_variants()) {
        const Variant b = baseline_of(v);
        INFO(canonical_name(v));
        CHECK(is_valid(b));
        CHECK(b.method == Method::Point);
        CHECK(b.dist == v.dist);
        CHECK(b.light == v.light);
    }
    auto base = [](const std::string& name) {
        return canonical_name(baseline_of(*parse_variant(name, {})));
    };
    CHECK(base("dist=ggx,method=exact,light=polygon,nodes=2,precision=fp32,radial=2") ==
          "dist=ggx,method=point,light=polygon");
    CHECK(base("dist=beckmann,method=exact,light=polygon") ==
          "dist=beckmann,method=point,light=polygon");
    CHECK(base("dist=phong,method=lorentz,light=polygon,sided=one,verts=4") ==
          "dist=phong,method=point,light=polygon,sided=one,verts=4");
}

TEST_CASE("report tables: moment for phong rows, ndf for microfacet rows", "[report]") {
    auto row = [](const std::string& name, const std::string& second, double e2) {
        ReportRow r;
        r.variant = *parse_variant(name, {});
        r.name = name;
        r.baseline = canonical_name(baseline_of(r.variant));
        r.cases = 3;
        r.ratio = 2;
        QuantityScore s;
        s.quantity = "specular";
        s.n = 3;
        s.rel_l2 = 1e-4;
        QuantityScore q = s;
        q.quantity = second;
        q.rel_l2 = e2;
        r.scores = {s, q};
        return r;
    };
    Report r;
    r.pattern = "dist=ggx";
    r.rows = {row("dist=ggx,method=exact,light=polygon", "ndf", 3e-3)};
    CHECK(r.rows[0].error() == 3e-3);
    std::string md = report_markdown(r);
    CHECK(md.find("| ndf median / p95 / max / relL2 |") != std::string::npos);
    CHECK(md.find("| moment median") == std::string::npos);
    CHECK(squeezed(report_json(r)).find("\"error_quantities\":[\"specular\",\"ndf\"]") !=
          std::string::npos);

    // A phong row's error ignores an ndf score, a microfacet row's a moment score.
    r.rows.push_back(row("dist=phong,method=exact,light=polygon", "ndf", 5e-2));
    CHECK(r.rows[1].error() == 1e-4);
    md = report_markdown(r);
    CHECK(md.find("| moment or ndf median / p95 / max / relL2 |") != std::string::npos);

    // A sweep names its axis in the tables and the plots.
    Report s;
    s.pattern = "dist=ggx";
    s.axis = SweepAxis::View;
    s.parameter = "cos_theta_v";
    s.symbol = "cos θ_v";
    s.axis_label = "cos θ_v";
    for (double c : {1.0, 0.1}) {
        s.rows.push_back(row("dist=ggx,method=exact,light=polygon", "ndf", 3e-3));
        s.rows.back().value = c;
    }
    md = report_markdown(s);
    CHECK(md.find("| variant | cos θ_v | cases |") != std::string::npos);
    CHECK(md.find("| variant | cos θ_v = 1 | cos θ_v = 0.1 |") != std::string::npos);
    CHECK(md.find("| `dist=ggx,method=exact,light=polygon` | 0.1 |") != std::string::npos);
    CHECK(squeezed(report_json(s)).find("\"cos_theta_v\":0.1") != std::string::npos);
    const auto pics = report_pictures(s);
    REQUIRE(pics.size() == 2);
    CHECK(pics[0].first == "sweep_time.svg");
    CHECK(pics[1].second.find("cos θ_v") != std::string::npos);
}
