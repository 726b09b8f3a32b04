// The LTC fitter (`arealight fit-ltc`): one LTC per (roughness, view) cell.
//
// What is fitted: the shapes the shader multiplies by its amplitude, over the upper
// hemisphere only,
//     g = f (n.w) / integral_H f (n.w),   h = D_ltc / integral_H D_ltc   (w.z > 0),
// since A and B make a light filling the hemisphere exact and the horizon clips both, so the
// LTC's mass below the horizon is free.
//
// Two lobes (Phong, Blinn, Beckmann; include/arealight/ltc_table.hpp): h is the LTC of the
// kernel D_o + K D_s, D_s the clamped cosine s = 1.2 times wider in x and y, normalised over
// z > 0 the same way. One transformed cosine has a power-law tail, as GGX's lobe has; these
// lobes' tails are Gaussian, and one LTC fitted core or tail but not both (phase 2's error
// per cell, median / p95: blinn 0.029 / 0.053, phong 0.045, against GGX's 0.0047). With K
// near -0.75 the kernel is a sharpened cosine (D_o minus a multiple of its width
// derivative), whose tail falls faster: blinn 0.009 / 0.015. A prototype over free s and K
// put s at 1.17-1.22 for every cell it tried, so s is fixed and K, a fifth parameter, is the
// amplitude texture's spare channel. K in [-0.95, 0]: allowed up to 3, Nelder-Mead from
// K = -0.5 ran up a flat valley to the bound in half the cells of an 8 x 8 blinn table, at
// larger errors (e.g. 0.041 there against 0.0079 with K <= 0).
//
// Fit metric, in two phases per cell (three with two lobes):
// 1. Heitz et al. 2016's L3 distance, integral over z > 0 of |g - h|^3 dw, estimated with
//    multiple importance sampling (balance heuristic) from 32 x 32 stratified samples of
//    the BRDF (fixed per cell) and 32 x 32 of the current LTC (fixed uniforms). It puts the
//    lobe in the right place with the right width, robustly, from the neighbour's solution.
// 2. From there, what the product is judged on (relL2 of `specular` over lights): the
//    relative L2 error of the integrals of g and h over a fixed family of 256 spherical
//    caps, sum_k (int_k (g - h))^2 / sum_k (int_k g)^2. Two thirds of the caps are centred
//    within 3 r50 of the lobe's mean direction (r50: the angle about it holding half of g),
//    with radii log-uniform in [r50 / 4, 8 r50]; one third anywhere in the hemisphere
//    (cosine-distributed centres) with radii uniform in [0, pi / 2], which includes lights
//    crossing the horizon. The integrals are estimated on a fixed sample set (the BRDF's
//    samples and those of the phase-1 LTC, balance heuristic), so the metric is a smooth
//    deterministic function of the LTC, and g - h is estimated on the same samples, so its
//    noise scales with the error, not with g. The caps come from a fixed seeded generator
//    (splitmix64), scaled to each cell's lobe.
//    For the four smallest roughness columns (i < 4), where rho = sqrt(alpha) steps by
//    factors of 2.2, 1.8, 1.6 in alpha (beckmann's rho = alpha^(1/3): 1.5, 1.4, 1.3),
//    phase 2 adds the same metric for the LTC the shader interpolates halfway to the
//    neighbours already fitted, (i + 1, j) and (i, j - 1), for the lobe there (the
//    shader's rule, ltc_table.hpp; for GGX (a, b, c) filtered times the cells' alphas and
//    divided by the lobe's, which interpolates a lobe that keeps its shape as it narrows
//    exactly: GGX specular relL2 at alpha = 0.002, typical set, 9.7e-3 -> 2e-4 with the
//    table refitted so. The two-lobe tables keep the bare entries: their cells at small
//    alpha are not one shape scaled (alpha a runs 0.15, 0.11, 0.12, 0.15, 0.29 over the
//    first five beckmann columns at n.v = 0.56, d 0.09 to -0.85, the valley of near-equal
//    (a, d)), and refitted with the scaled rule beckmann's public typical sets improved
//    (sphere 0.051 -> 0.030, ellipsoid 0.089 -> 0.039) but its horizon disks doubled
//    (0.038 -> 0.074)): the cell trades some accuracy at its node for the table's accuracy
//    between nodes. Two-lobe tables do so in every cell. Beckmann's alphas reach 0.001
//    (phong's and blinn's equivalents 0.0045), so its columns run over alpha^(1/3) instead
//    (sqrt before): specular relL2 on the public typical polygons 0.049 -> 0.031, glossy
//    0.0185 -> 0.0133, typical spheres 0.051 -> 0.039, ellipsoids 0.089 -> 0.032; horizon
//    polygons 0.029 -> 0.032, disks 0.038 -> 0.046 (one case, alpha 0.082 at n.v 0.25,
//    +12% -> +16%). Fitted at their own parameters, the blinn cells of the public polygon
//    cases score specular relL2 0.046 / 0.090 / 0.013 (typical / horizon / glossy), but a
//    table fitted cell by cell jumped between neighbours (the frame angle from 72 to 89
//    degrees in one step near grazing views) and its bilinear lookup scored 0.081 / 0.13 /
//    0.050.
// 3. (Two lobes.) Phase 2's metric over the LTC and K together, from phase 2's LTC and
//    the neighbour's K.
// The `error` of a cell is sqrt of the last phase's metric at the cell alone.
//
// Measured with arealight-ltc-check (fit/ltc_check.cpp: the shader's computation in double
// precision) against shared/validation and against larger sets of the same kinds (500 GGX
// polygon cases each, oracle references from `arealight reference`), GGX relL2:
//                         validation typical/horizon/glossy    larger sets
//   phase 1 only          0.018 / 0.018 / 0.0066              0.053 / 0.040 / 0.016
//   phases 1 + 2          0.024 / 0.009 / 0.0144              0.039 / 0.038 / 0.011
//   + interpolation term  0.024 / 0.009 / 0.0100              0.039 / 0.038 / 0.0098
// Phase 2 helps Phong, Blinn and Beckmann more (relL2 on the larger typical sets 0.10 ->
// 0.065, 0.096 -> 0.059, 0.091 -> 0.062). On validation/typical, whose relL2 is 78 % one
// case, phase 1 alone is better for GGX; the larger sets say otherwise.
//
// Optimizer: NLopt's Nelder-Mead (LN_NELDERMEAD): derivative-free (phase 1 is only piecewise
// smooth: its LTC samples move with the parameters), dependable on 4 parameters from the
// neighbour's start, deterministic. On 500 GGX cases fitted at their own parameters,
// LN_BOBYQA took half the time for relL2 0.046 against 0.044; on 300 of them LN_SBPLX took
// three times as long for 0.041 against 0.045.
//
// Parametrisation: M = Minv^-1 = R_y(theta) [[m11, 0, m13], [0, m22, 0], [0, 0, 1]], which
// covers every Minv = [[a, 0, b], [0, c, 0], [d, 0, 1]] of positive determinant
// (d = tan theta, a = (1 - m13 d) / m11, b = -(d + m13) / m11, c = 1 / (m22 cos theta)):
// the optimizer sees theta = theta0 + m11_0 t, log m11, log m22 and m13 = m13_0 + m11_0 s, so
// that its steps are relative to the lobe's width. The frame angle is free (fixing it at the
// lobe's average direction, as Heitz does, quadrupled the GGX error on the larger typical
// set) but bounded by |theta| <= theta_v + 0.2: beyond, the metric is flat for Phong, Blinn
// and Beckmann lobes and the fit wandered to theta near 90 degrees, where the stored form
// (normalised by Minv[2][2] = cos theta) blows up and neighbouring cells stop interpolating.
// At normal view (j = 0) the lobe is isotropic and only m11 = m22 is fitted.
//
// Views: cos theta_v = 1 - w^2 is clamped to >= kCosThetaMin = 1e-3 (the grazing row
// j = size - 1 would otherwise be n.v = 0, where the specular is 0 by definition).
//
// Order (continuity, Heitz): each cell starts from the previous view of its roughness,
// (i, j - 1), and the normal-view row from the rougher neighbour (i + 1, 0); the first cell
// is (size - 1, 0). Cells run in parallel as soon as the cells they use are done; the
// result depends only on those, not on the number of threads (bit for bit on one machine).
#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <condition_variable>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "arealight/ltc_table.hpp"
#include "ltc_brdf.hpp"
#include "ltc_distribution.hpp"
#include "ltc_fit_detail.hpp"

namespace arealight {

using namespace ltcfit;

namespace {

constexpr int kSamples = 32;  // per axis, for each of the two sample sets
constexpr int kCaps = 256;    // phase 2's regions
constexpr double kThetaMargin = 0.2;  // |theta| <= theta_v + this
constexpr double kThetaLimit = 1.5607;  // and < 89.4 degrees

// The |theta| limit of a distribution's table. Beckmann's is 1.50 (85.9 degrees, |d| <= 14):
// refitted on its cube-root axis with 89.4, the grazing cells of 10 columns (alpha 0.03 to
// 0.09, n.v below 0.2) ran to the limit along the two-lobe fit's flat valley (d = -99 where
// the sqrt-axis table had -1.3 to -5 at the same lobes, the same error), and a light filling
// the hemisphere at alpha 0.05, n.v 0.08 came out 3.5% high (tests/test_ltc_shading.cpp allows
// 1.5%) between those cells and their rougher neighbours, and the public horizon disks scored
// 0.072 (0.046 now). The other tables were fitted with 89.4 (the refit test holds them to it).
double theta_limit(Distribution d) { return d == Distribution::Beckmann ? 1.50 : kThetaLimit; }
constexpr int kInterpolatedColumns = 4;  // cells fitted for interpolation too (i < this)

// Whether cell (i, .) is also fitted for interpolation: the smallest roughnesses, and every
// cell of a two-lobe table, whose fits are otherwise free to jump between neighbours.
bool fitted_for_interpolation(Distribution d, int i) {
    return i < kInterpolatedColumns || ltc_two_lobes(d);
}
// Phase 3 (two lobes): K's bounds, its start where no neighbour has one, and Nelder-Mead's
// first step in it. D_s / D_o runs from 1 / s^2 on the axis to s^2 at the horizon, so the
// kernel is positive in its core for K > -s^2 and everywhere for K >= -1 / s^2 = -0.69;
// the fits sit at -0.75 to -0.78, negative beyond 71 degrees from the cosine's axis (the
// LTC's far tail; the shader floors the result at 0). Bounded at -1 / s^2, the blinn cells
// of the public polygon cases, each fitted at its own parameters, scored specular relL2
// 0.100 / 0.16 / 0.021 (typical / horizon / glossy) against 0.046 / 0.090 / 0.013.
constexpr double kKappaMin = -0.95, kKappaMax = 0.0, kKappaStart = -0.75, kKappaStep = 0.1;

struct Param {
    double theta = 0, m11 = 1, m22 = 1, m13 = 0;
    double kappa = 0;  // the second lobe's weight K (ltc_table.hpp)
};

LtcCell cell_of(const Param& p) {
    const double t = std::tan(p.theta), ct = std::cos(p.theta);
    LtcCell c;
    c.a = (1 - p.m13 * t) / p.m11;
    c.b = -(t + p.m13) / p.m11;
    c.c = 1 / (p.m22 * ct);
    c.d = t;
    c.kappa = p.kappa;
    return c;
}

Param param_of(const LtcCell& c) {
    Param p;
    p.theta = std::atan(c.d);
    const double ct = std::cos(p.theta);
    p.m22 = 1 / (c.c * ct);
    p.m11 = (1 + c.d * c.d) / (c.a - c.b * c.d);
    p.m13 = -c.d - c.b * p.m11;
    p.kappa = c.kappa;
    return p;
}

struct BrdfSample {
    V3 w;
    double g, pdf;
};

class CellFitter {
  public:
    CellFitter(const BrdfLobe& lobe, double norm) : lobe_(lobe), norm_(norm) {
        for (int j = 0; j < kSamples; ++j) {
            for (int i = 0; i < kSamples; ++i) {
                const double u1 = (i + 0.5) / kSamples, u2 = (j + 0.5) / kSamples;
                uv_.push_back({u1, u2});
                const V3 w = lobe.sample(u1, u2);
                if (!(w.z > 0)) continue;
                const double g = lobe.eval(w) / norm;
                const double pdf = lobe.pdf(w);
                if (!(pdf > 0)) continue;
                brdf_.push_back({w, g, pdf});
            }
        }
    }

    double l3(const LtcDistribution& ltc) const {
        const double hn = ltc.hemisphere_integral();
        if (!(hn > 1e-12)) return std::numeric_limits<double>::max();
        double e = 0;
        for (const auto& s : brdf_) {
            const double pl = ltc.eval(s.w);
            const double d = std::abs(s.g - pl / hn);
            e += d * d * d / (s.pdf + pl);
        }
        for (const auto& u : uv_) {
            const V3 w = ltc.sample(u[0], u[1]);
            if (!(w.z > 0)) continue;
            const double pl = ltc.eval(w);
            const double g = lobe_.eval(w) / norm_;
            const double pb = lobe_.pdf(w);
            const double d = std::abs(g - pl / hn);
            e += d * d * d / (pb + pl);
        }
        return e / (kSamples * kSamples);
    }

    // Average direction of the normalized lobe (for the first cell's start).
    V3 average_direction() const {
        V3 s;
        for (const auto& b : brdf_) s = s + (b.g / b.pdf) * b.w;
        return normalize(s);
    }

  private:
    const BrdfLobe& lobe_;
    double norm_;
    std::vector<BrdfSample> brdf_;
    std::vector<std::array<double, 2>> uv_;
};

// Deterministic pseudo-random numbers in [0, 1) (splitmix64), identical on every platform.
class Random {
  public:
    explicit Random(std::uint64_t seed) : s_(seed) {}
    double next() {
        std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    }

  private:
    std::uint64_t s_;
};

// Orthonormal frame around a unit vector.
void frame_of(V3 z, V3& x, V3& y) {
    x = std::abs(z.z) < 0.999 ? normalize(cross(V3{0, 0, 1}, z)) : normalize(cross(V3{1, 0, 0}, z));
    y = cross(z, x);
}

V3 rotate_from(V3 c, double theta, double phi) {
    V3 x, y;
    frame_of(c, x, y);
    const double st = std::sin(theta);
    return normalize(std::cos(theta) * c + (st * std::cos(phi)) * x + (st * std::sin(phi)) * y);
}

LtcDistribution ltc_of(const LtcCell& c) { return LtcDistribution::from_cell(c.a, c.b, c.c, c.d); }

// The lobe the shader integrates for a cell (include/arealight/ltc_table.hpp): its LTC,
// plus K times the LTC of diag(1 / s, 1 / s, 1) Minv, the same lobe s times wider.
struct Lobe {
    LtcDistribution l1, l2;
    double kappa;
    explicit Lobe(const LtcCell& c) : l1(ltc_of(c)), l2(ltc_of(ltc_second_lobe(c))), kappa(c.kappa) {}
    double eval(V3 w) const { return kappa == 0 ? l1.eval(w) : l1.eval(w) + kappa * l2.eval(w); }
    double hemisphere_integral() const {
        const double h1 = l1.hemisphere_integral();
        return kappa == 0 ? h1 : h1 + kappa * l2.hemisphere_integral();
    }
};

// Phase 2's metric (see the top of the file): relative L2 error of cap integrals.
class RegionMetric {
  public:
    RegionMetric(const BrdfLobe& lobe, double norm, const LtcDistribution& ltc0) {
        const int n = kSamples;
        for (int set = 0; set < 2; ++set) {
            for (int j = 0; j < n; ++j) {
                for (int i = 0; i < n; ++i) {
                    const double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n;
                    const V3 w = set == 0 ? lobe.sample(u1, u2) : ltc0.sample(u1, u2);
                    if (!(w.z > 0)) continue;
                    const double pm = lobe.pdf(w) + ltc0.eval(w);
                    if (!(pm > 0)) continue;
                    w_.push_back(w);
                    weight_.push_back(1 / (n * n * pm));
                    g_.push_back(lobe.eval(w) / norm);
                }
            }
        }
        // Lobe centre and spread: g-weighted mean direction and median angle from it.
        V3 mean;
        std::vector<std::pair<double, double>> ang;
        for (std::size_t s = 0; s < w_.size(); ++s) mean = mean + (g_[s] * weight_[s]) * w_[s];
        mean = normalize(mean);
        double tot = 0;
        for (std::size_t s = 0; s < w_.size(); ++s) {
            ang.push_back({std::acos(std::clamp(dot(w_[s], mean), -1.0, 1.0)), g_[s] * weight_[s]});
            tot += g_[s] * weight_[s];
        }
        std::sort(ang.begin(), ang.end());
        double acc = 0, r50 = ang.empty() ? 0.1 : ang.back().first;
        for (const auto& a : ang) {
            acc += a.second;
            if (acc >= 0.5 * tot) {
                r50 = a.first;
                break;
            }
        }
        r50 = std::max(r50, 1e-4);
        // Caps (see the top of the file).
        Random rnd(0x5eed1a7eULL);
        for (int k = 0; k < kCaps; ++k) {
            V3 c;
            double r;
            const double a = rnd.next(), b = rnd.next(), e = rnd.next(), sel = rnd.next();
            if (sel < 2.0 / 3.0) {
                c = rotate_from(mean, 3 * r50 * a, 2 * kPi * b);
                r = r50 * std::exp(std::log(0.25) + e * std::log(32.0));
            } else {
                const double rr = std::sqrt(a), phi = 2 * kPi * b;
                c = {rr * std::cos(phi), rr * std::sin(phi), std::sqrt(std::max(0.0, 1 - a))};
                r = e * kPi / 2;
            }
            r = std::min(r, kPi / 2);
            const double cr = std::cos(r);
            std::vector<int> members;
            double gk = 0;
            for (std::size_t s = 0; s < w_.size(); ++s) {
                if (dot(w_[s], c) >= cr) {
                    members.push_back(static_cast<int>(s));
                    gk += g_[s] * weight_[s];
                }
            }
            if (members.empty()) continue;
            caps_.push_back(std::move(members));
            norm2_ += gk * gk;
        }
    }

    // sum_k (integral over cap k of g - h)^2 / sum_k (integral over cap k of g)^2
    double operator()(const LtcCell& cell) const {
        const Lobe lobe(cell);
        const double hn = lobe.hemisphere_integral();
        if (!(hn > 1e-12) || !(norm2_ > 0)) return std::numeric_limits<double>::max();
        thread_local std::vector<double> d;
        d.resize(w_.size());
        for (std::size_t s = 0; s < w_.size(); ++s) d[s] = (g_[s] - lobe.eval(w_[s]) / hn) * weight_[s];
        double e = 0;
        for (const auto& cap : caps_) {
            double x = 0;
            for (int s : cap) x += d[s];
            e += x * x;
        }
        return e / norm2_;
    }

  private:
    std::vector<V3> w_;
    std::vector<double> weight_, g_;
    std::vector<std::vector<int>> caps_;
    double norm2_ = 0;
};

struct Problem {
    std::function<double(const LtcCell&)> metric;
    Param start;
    bool isotropic;
    bool fit_kappa = false;          // phase 3: K is the last parameter
    double theta_max = kThetaLimit;  // |theta| bound

    unsigned dimension() const { return (isotropic ? 1u : 4u) + (fit_kappa ? 1u : 0u); }

    Param decode(const double* x) const {
        Param p;
        p.kappa = fit_kappa ? start.kappa + x[dimension() - 1] : start.kappa;
        if (isotropic) {
            p.m11 = p.m22 = start.m11 * std::exp(x[0]);
            return p;
        }
        p.theta = start.theta + start.m11 * x[0];
        p.m11 = start.m11 * std::exp(x[1]);
        p.m22 = start.m22 * std::exp(x[2]);
        p.m13 = start.m13 + start.m11 * x[3];
        return p;
    }
};

double objective(const std::vector<double>& x, std::vector<double>&, void* data) {
    auto* pr = static_cast<Problem*>(data);
    const Param p = pr->decode(x.data());
    if (!(std::abs(p.theta) < pr->theta_max) || !(p.m11 > 1e-9) || !(p.m22 > 1e-9) ||
        !(p.m11 < 1e6) || !(p.m22 < 1e6) || !std::isfinite(p.m13) || !(p.kappa >= kKappaMin) ||
        !(p.kappa <= kKappaMax))
        return 1e300;
    const LtcCell c = cell_of(p);
    if (!(c.a > 0) || !(c.a - c.b * c.d > 0)) return 1e300;
    const double e = pr->metric(c);
    return std::isfinite(e) ? e : 1e300;
}

Param run_nelder_mead(Problem& pr, double step_size) {
    const unsigned n = pr.dimension();
    nlopt::opt opt(nlopt::LN_NELDERMEAD, n);
    opt.set_min_objective(objective, &pr);
    std::vector<double> x(n, 0.0), step(n, step_size);
    if (pr.fit_kappa) step[n - 1] = kKappaStep;
    opt.set_initial_step(step);
    opt.set_xtol_abs(1e-5);
    opt.set_ftol_rel(1e-7);
    opt.set_maxeval(1500);
    double f = 0;
    try {
        opt.optimize(x, f);
    } catch (const std::exception&) {
        // roundoff_limited and the like: x holds the best point found.
    }
    return pr.decode(x.data());
}

}  // namespace

namespace ltcfit {

double fit_cos_theta(int size, int j) {
    return std::max(ltc_cell_cos_theta(size, j), kCosThetaMin);
}

double fit_alpha(Distribution d, int size, int i) {
    LtcTable t;
    t.dist = d;
    t.size = size;
    ltc_rho_range(d, t.rho_min, t.rho_max);
    return ltc_cell_alpha(t, i);
}

}  // namespace ltcfit

namespace {

// What the shader samples halfway between two cells x and y fitted at alpha_x and alpha_y,
// at alpha_m: the texture holds (a, b, c) times the cell's alpha, the shader divides by the
// case's (GGX; include/arealight/ltc_table.hpp; 1, 1, 1 for the bare entries); d and K are
// interpolated as they are.
LtcCell halfway(const LtcCell& x, double alpha_x, const LtcCell& y, double alpha_y, double alpha_m) {
    const double sx = 0.5 * alpha_x / alpha_m, sy = 0.5 * alpha_y / alpha_m;
    LtcCell m;
    m.a = sx * x.a + sy * y.a;
    m.b = sx * x.b + sy * y.b;
    m.c = sx * x.c + sy * y.c;
    m.d = 0.5 * (x.d + y.d);
    m.kappa = 0.5 * (x.kappa + y.kappa);
    return m;
}

// A lobe and phase 2's metric for it, sampled from a given LTC.
struct LobeMetric {
    BrdfLobe lobe;
    BrdfLobe::Moments moments;
    RegionMetric region;
    LobeMetric(Distribution d, double alpha, double cos_v, const LtcCell& ltc0)
        : lobe(d, alpha, cos_v),
          moments(lobe.hemisphere_moments()),
          region(lobe, moments.total, ltc_of(ltc0)) {}
};

// The fit of one lobe (alpha, cos_v) from `start`; with neighbours (the cell's table
// position given), phase 2 also weighs the LTCs interpolated halfway to them.
struct Neighbours {
    int size = 0, i = 0, j = 0;
    const LtcCell* next_u = nullptr;  // (i + 1, j)
    const LtcCell* prev_w = nullptr;  // (i, j - 1)
};

LtcCell fit_lobe(Distribution d, double alpha, double cos_v, const LtcCell* start, bool isotropic,
                 const Neighbours* nb) {
    const BrdfLobe lobe(d, alpha, cos_v);
    const BrdfLobe::Moments mom = lobe.hemisphere_moments();
    const CellFitter fitter(lobe, mom.total);

    // Phase 1: L3 from the neighbour's solution.
    Problem pr;
    pr.metric = [&](const LtcCell& c) { return fitter.l3(ltc_of(c)); };
    pr.isotropic = isotropic;
    if (start) {
        pr.start = param_of(*start);
        pr.start.kappa = 0;
    } else {
        const V3 avg = fitter.average_direction();
        pr.start.theta = std::atan2(avg.x, avg.z);
        pr.start.m11 = pr.start.m22 = std::max(alpha, 1e-3);
        pr.start.m13 = 0;
    }
    pr.theta_max = std::min(theta_limit(d), std::acos(std::clamp(cos_v, 0.0, 1.0)) + kThetaMargin);
    pr.start.theta = std::clamp(pr.start.theta, -0.999 * pr.theta_max, 0.999 * pr.theta_max);
    if (pr.isotropic) {
        pr.start.theta = 0;
        pr.start.m13 = 0;
        pr.start.m11 = pr.start.m22 = std::sqrt(pr.start.m11 * pr.start.m22);
    }
    Param p = run_nelder_mead(pr, 0.1);

    // Phase 2: relative L2 error of cap integrals, from phase 1's solution; for the cells
    // of small roughness also halfway to the neighbours already fitted.
    const LtcCell cell1 = cell_of(p);
    const RegionMetric region(lobe, mom.total, ltc_of(cell1));
    std::unique_ptr<LobeMetric> mid_u, mid_w;
    // The matrix texture's factors of this cell and of its neighbour (i + 1, j), and the
    // shader's divisor halfway between them (1, 1, 1 where the bare entries are filtered).
    double alpha_i = 1, alpha_next = 1, alpha_mid = 1;
    if (nb && nb->next_u) {
        LtcTable grid;
        grid.dist = d;
        grid.size = nb->size;
        ltc_rho_range(d, grid.rho_min, grid.rho_max);
        const double rho = 0.5 * (ltc_cell_rho(grid, nb->i) + ltc_cell_rho(grid, nb->i + 1));
        alpha_i = ltc_matrix_scale(grid, nb->i);
        alpha_next = ltc_matrix_scale(grid, nb->i + 1);
        alpha_mid = ltc_matrix_scale_at(grid, rho);
        mid_u = std::make_unique<LobeMetric>(
            d, ltc_alpha_of_rho(d, rho), cos_v,
            halfway(cell1, alpha_i, *nb->next_u, alpha_next, alpha_mid));
    }
    if (nb && nb->prev_w) {
        const double w = (nb->j - 0.5) / (nb->size - 1);
        mid_w = std::make_unique<LobeMetric>(d, alpha, std::max(1 - w * w, kCosThetaMin),
                                             halfway(cell1, 1, *nb->prev_w, 1, 1));
    }
    Problem pr2 = pr;
    pr2.metric = [&](const LtcCell& c) {
        double e = region(c);
        if (mid_u) e += mid_u->region(halfway(c, alpha_i, *nb->next_u, alpha_next, alpha_mid));
        if (mid_w) e += mid_w->region(halfway(c, 1, *nb->prev_w, 1, 1));
        return e;
    };
    pr2.start = p;
    p = run_nelder_mead(pr2, 0.05);

    // Phase 3 (two lobes): the same metric over the LTC and K together, K from the
    // neighbour's.
    if (ltc_two_lobes(d)) {
        Problem pr3 = pr2;
        pr3.fit_kappa = true;
        pr3.start = p;
        pr3.start.kappa =
            start && start->kappa != 0 ? std::clamp(start->kappa, kKappaMin, kKappaMax) : kKappaStart;
        p = run_nelder_mead(pr3, 0.05);
    }

    LtcCell cell = cell_of(p);
    const double hn = Lobe(cell).hemisphere_integral();
    if (d == Distribution::Phong) {
        cell.amp_f0 = mom.total / hn;
        cell.amp_one = 0;
    } else {
        cell.amp_f0 = (mom.total - mom.schlick) / hn;
        cell.amp_one = mom.schlick / hn;
    }
    cell.error = std::sqrt(region(cell));
    // -0 would print as "-0".
    cell.a += 0.0, cell.b += 0.0, cell.c += 0.0, cell.d += 0.0, cell.kappa += 0.0;
    return cell;
}

}  // namespace

LtcCell fit_ltc_cell(Distribution d, int size, int i, int j, const LtcCell* start) {
    return fit_ltc_cell(d, size, i, j, start, nullptr, nullptr);
}

LtcCell fit_ltc_cell(Distribution d, int size, int i, int j, const LtcCell* start,
                     const LtcCell* next_u, const LtcCell* prev_w) {
    Neighbours nb;
    nb.size = size, nb.i = i, nb.j = j;
    if (fitted_for_interpolation(d, i)) {
        nb.next_u = i + 1 < size ? next_u : nullptr;
        nb.prev_w = j > 0 ? prev_w : nullptr;
    }
    return fit_lobe(d, ltcfit::fit_alpha(d, size, i), ltcfit::fit_cos_theta(size, j), start, j == 0,
                    &nb);
}

LtcCell ltcfit::fit_ltc_at(Distribution d, double alpha, double cos_v, const LtcCell* start,
                           bool isotropic) {
    return fit_lobe(d, alpha, cos_v, start, isotropic, nullptr);
}

double ltcfit::ltc_fit_error(Distribution d, double alpha, double cos_v, const LtcCell& c) {
    const BrdfLobe lobe(d, alpha, cos_v);
    const RegionMetric region(lobe, lobe.hemisphere_moments().total, ltc_of(c));
    return std::sqrt(region(c));
}

std::optional<LtcTable> fit_ltc(Distribution d, const LtcFitOptions& opt,
                                const DiagnosticConsumer& diag) {
    if (opt.size < 2 || opt.size > 1024) {
        if (diag) diag({Severity::Error, "", 0, "fit-ltc: size must be in [2, 1024]"});
        return std::nullopt;
    }
    LtcTable t;
    t.dist = d;
    t.size = opt.size;
    ltc_rho_range(d, t.rho_min, t.rho_max);
    const int n = opt.size;
    t.cells.assign(static_cast<std::size_t>(n) * n, LtcCell{});
    auto cell = [&](int i, int j) -> LtcCell& { return t.cells[static_cast<std::size_t>(j) * n + i]; };

    // Each cell waits for the cells it starts from or is fitted against: (i, j - 1) and, on
    // the row j = 0 and in the columns fitted for interpolation, (i + 1, j). A cell's
    // result depends only on those, so the table does not depend on the scheduling.
    auto needs_u = [&](int i, int j) {
        return i + 1 < n && (j == 0 || fitted_for_interpolation(d, i));
    };
    const int total = n * n;
    std::vector<int> missing(static_cast<std::size_t>(total), 0);
    std::vector<int> ready;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            int& m = missing[static_cast<std::size_t>(j) * n + i];
            m = (j > 0 ? 1 : 0) + (needs_u(i, j) ? 1 : 0);
            if (m == 0) ready.push_back(j * n + i);
        }
    }
    std::mutex mu;
    std::condition_variable cv;
    int done = 0;
    auto worker = [&]() {
        std::unique_lock<std::mutex> lock(mu);
        for (;;) {
            cv.wait(lock, [&] { return !ready.empty() || done == total; });
            if (ready.empty()) return;
            const int k = ready.back();
            ready.pop_back();
            lock.unlock();
            const int i = k % n, j = k / n;
            const LtcCell* start = j > 0 ? &cell(i, j - 1) : i + 1 < n ? &cell(i + 1, 0) : nullptr;
            const LtcCell result =
                fit_ltc_cell(d, n, i, j, start, i + 1 < n ? &cell(i + 1, j) : nullptr,
                             j > 0 ? &cell(i, j - 1) : nullptr);
            lock.lock();
            cell(i, j) = result;
            ++done;
            // Dependents: (i, j + 1) and (i - 1, j).
            if (j + 1 < n && --missing[static_cast<std::size_t>(k + n)] == 0) ready.push_back(k + n);
            if (i > 0 && needs_u(i - 1, j) && --missing[static_cast<std::size_t>(k - 1)] == 0)
                ready.push_back(k - 1);
            cv.notify_all();
        }
    };
    unsigned threads = opt.threads > 0 ? static_cast<unsigned>(opt.threads)
                                       : std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, static_cast<unsigned>(n));
    std::vector<std::thread> pool;
    for (unsigned q = 0; q < threads; ++q) pool.emplace_back(worker);
    {
        std::unique_lock<std::mutex> lock(mu);
        int reported = 0;
        while (reported < total) {
            cv.wait(lock, [&] { return done != reported; });
            reported = done;
            if (opt.progress) {
                lock.unlock();
                opt.progress(reported, total);
                lock.lock();
            }
        }
    }
    for (auto& th : pool) th.join();

    for (int k = 0; k < total; ++k) {
        const LtcCell& c = t.cells[k];
        const double v[] = {c.a, c.b, c.c, c.d, c.amp_f0, c.amp_one, c.kappa, c.error};
        bool ok = c.a > 0 && c.c > 0;
        for (double x : v) ok = ok && std::isfinite(x);
        if (!ok) {
            if (diag)
                diag({Severity::Error, "", 0,
                      "fit-ltc: cell (" + std::to_string(k % n) + ", " + std::to_string(k / n) +
                          ") of " + to_string(d) + " did not converge to a finite LTC"});
            return std::nullopt;
        }
    }
    return t;
}

}  // namespace arealight
