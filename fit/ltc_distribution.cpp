#include "ltc_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace arealight::ltcfit {

LtcDistribution::LtcDistribution(const M3& minv) : minv_(minv) {
    m_ = inverse(minv_);
    det_minv_ = determinant(minv_);
}

LtcDistribution LtcDistribution::from_cell(double a, double b, double c, double d) {
    M3 mi;
    mi.m[0][0] = a, mi.m[0][1] = 0, mi.m[0][2] = b;
    mi.m[1][0] = 0, mi.m[1][1] = c, mi.m[1][2] = 0;
    mi.m[2][0] = d, mi.m[2][1] = 0, mi.m[2][2] = 1;
    return LtcDistribution(mi);
}

double LtcDistribution::eval(V3 w) const {
    const V3 wo = minv_ * w;
    const double l2 = dot(wo, wo);
    if (wo.z <= 0 || !(l2 > 0)) return 0;
    const double l = std::sqrt(l2);
    // D_o(w_o / l) |det Minv| / l^3
    return wo.z / l / kPi * std::abs(det_minv_) / (l2 * l);
}

V3 LtcDistribution::sample(double u1, double u2) const {
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    const V3 wo{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u1))};
    return normalize(m_ * wo);
}

double LtcDistribution::hemisphere_integral() const {
    // {w : w.z > 0} is {w_o : (M row 2) . w_o > 0}: a hemisphere tilted by beta from the
    // cosine's axis, over which the clamped cosine / pi integrates to (1 + cos beta) / 2.
    const V3 n{m_.m[2][0], m_.m[2][1], m_.m[2][2]};
    const double l = length(n);
    if (!(l > 0)) return 0;
    return 0.5 * (1 + n.z / l);
}

double ltc_polygon_integral(const M3& minv, const std::vector<V3>& vertices) {
    std::vector<V3> in;
    in.reserve(vertices.size());
    for (const V3& v : vertices) in.push_back(minv * v);
    // Clip the cone to z > 0 (Sutherland-Hodgman; straight segments between vertex
    // vectors stay on the edges' great circles).
    std::vector<V3> out;
    out.reserve(in.size() + 2);
    for (std::size_t i = 0; i < in.size(); ++i) {
        const V3 p = in[i], q = in[(i + 1) % in.size()];
        if (p.z > 0) out.push_back(p);
        if ((p.z > 0) != (q.z > 0)) {
            const double t = p.z / (p.z - q.z);
            V3 x = p + t * (q - p);
            x.z = 0;
            out.push_back(x);
        }
    }
    if (out.size() < 3) return 0;
    double sum = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const V3 p = out[i], q = out[(i + 1) % out.size()];
        if (!(dot(p, p) > 0) || !(dot(q, q) > 0)) continue;
        const V3 a = normalize(p), b = normalize(q);
        const V3 c = cross(a, b);
        const double len = length(c);
        if (!(len > 0)) continue;
        sum += std::atan2(len, dot(a, b)) * c.z / len;
    }
    return std::abs(sum) / (2 * kPi);
}

}  // namespace arealight::ltcfit
