#include <algorithm>
#include <cmath>

#include "ltc_brdf.hpp"
#include "ltc_check.hpp"
#include "ltc_distribution.hpp"

namespace arealight::ltcfit {

namespace {

V3 v3(const Vec3& a) { return {a[0], a[1], a[2]}; }

// The cell's Minv (include/arealight/ltc_table.hpp).
M3 minv_of(const LtcCell& c) {
    M3 m;
    m.m[0][0] = c.a, m.m[0][1] = 0, m.m[0][2] = c.b;
    m.m[1][0] = 0, m.m[1][1] = c.c, m.m[1][2] = 0;
    m.m[2][0] = c.d, m.m[2][1] = 0, m.m[2][2] = 1;
    return m;
}

}  // namespace

LtcCell ltc_lookup(const LtcTable& t, double param, double cos_theta_v) {
    const double rho = ltc_rho_of_alpha(t.dist, ltc_alpha_of_param(t.dist, param));
    const double u = (rho - t.rho_min) / (t.rho_max - t.rho_min);
    const double w = std::sqrt(std::max(0.0, 1 - cos_theta_v));
    // Texel centres at k / (size - 1): the sampler's texel-space coordinate is u (size - 1).
    auto axis = [&](double s, int& k0, int& k1, double& f) {
        const double x = std::clamp(s, 0.0, 1.0) * (t.size - 1);
        k0 = std::min(static_cast<int>(std::floor(x)), t.size - 1);
        k1 = std::min(k0 + 1, t.size - 1);
        f = x - k0;
    };
    int i0, i1, j0, j1;
    double fu, fw;
    axis(u, i0, i1, fu);
    axis(w, j0, j1, fw);
    // (a, b, c) as the matrix texture holds them (GGX: times the cell's alpha, and back over
    // the case's; include/arealight/ltc_table.hpp).
    const double s0 = ltc_matrix_scale(t, i0), s1 = ltc_matrix_scale(t, i1);
    const double alpha = ltc_matrix_scale_at(t, rho);
    auto mix_scaled = [&](double LtcCell::*m, double k0, double k1) {
        const double a = t.at(i0, j0).*m * k0 * (1 - fu) + t.at(i1, j0).*m * k1 * fu;
        const double b = t.at(i0, j1).*m * k0 * (1 - fu) + t.at(i1, j1).*m * k1 * fu;
        return a * (1 - fw) + b * fw;
    };
    auto mix = [&](double LtcCell::*m) { return mix_scaled(m, 1, 1); };
    LtcCell c;
    c.a = mix_scaled(&LtcCell::a, s0, s1) / alpha;
    c.b = mix_scaled(&LtcCell::b, s0, s1) / alpha;
    c.c = mix_scaled(&LtcCell::c, s0, s1) / alpha;
    c.d = mix(&LtcCell::d);
    c.amp_f0 = mix(&LtcCell::amp_f0);
    c.amp_one = mix(&LtcCell::amp_one);
    c.kappa = mix(&LtcCell::kappa);
    c.error = mix(&LtcCell::error);
    return c;
}

bool ltc_polygon_case(const LtcTable& t, const Case& c, double& specular, double& diffuse) {
    if (c.light.type != LightType::Polygon || c.material.distribution != t.dist) return false;
    specular = diffuse = 0;
    const V3 n = normalize(v3(c.n)), v = normalize(v3(c.v)), p = v3(c.p);
    const auto& vs = c.light.vertices;
    // Which side of the light p sees (CONTRACT 1): 0 on the plane or behind a one-sided light.
    const V3 e = cross(v3(vs[1]) - v3(vs[0]), v3(vs[2]) - v3(vs[0]));
    const double side = dot(e, p - v3(vs[0]));
    if (!(side != 0) || (!c.light.two_sided && side < 0)) return true;
    // Frame: z = n, x = normalize(v - n (n.v)), y = z x x.
    const double cv = dot(n, v);
    V3 x = v - cv * n;
    if (!(length(x) > 1e-12)) {
        x = std::abs(n.x) < 0.9 ? cross(n, V3{1, 0, 0}) : cross(n, V3{0, 1, 0});
    }
    x = normalize(x);
    const V3 y = cross(n, x);
    std::vector<V3> local;
    for (const auto& q : vs) {
        const V3 d = v3(q) - p;
        local.push_back({dot(d, x), dot(d, y), dot(d, n)});
    }
    diffuse = ltc_polygon_integral(M3{}, local);
    if (!(cv > 0)) return true;
    const bool exponent = t.dist == Distribution::Phong || t.dist == Distribution::Blinn;
    const double param = exponent ? c.material.exponent : c.material.alpha;
    const LtcCell cell = ltc_lookup(t, param, cv);
    const double f0 = t.dist == Distribution::Phong ? 1.0 : c.material.f0;
    double integral = ltc_polygon_integral(minv_of(cell), local);
    if (cell.kappa != 0) integral += cell.kappa * ltc_polygon_integral(minv_of(ltc_second_lobe(cell)), local);
    // The kernel is negative in its far tail (K < 0): a light there gets 0, as in the shader.
    specular = (f0 * cell.amp_f0 + cell.amp_one) * std::max(integral, 0.0);
    return true;
}

}  // namespace arealight::ltcfit
