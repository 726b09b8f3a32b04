// The microfacet distribution vocabulary (templates/dist_{blinn,beckmann,ggx}.glsl and
// templates/dist/microfacet.glsl) compiled as C++ at both working precisions, against
// references written here from CONTRACT.md 2 in long double: quadrature of D for
// G, T and y, the contract's Lambda formulas, and Boost's erfc for erfcx.
#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/math/special_functions/sqrt1pm1.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// Each wrapper takes and returns double; the fp32 namespaces round the inputs to
// float first (the callers pass float-representable values).
#define AL_TEST_WRAPPERS                                                            \
    double w_gmax(double p) {                                                       \
        return double(al_dist_make(real(p)).gmax);                                  \
    }                                                                               \
    double w_width(double p) {                                                      \
        return double(al_dist_make(real(p)).width);                                 \
    }                                                                               \
    double w_smith_alpha(double p) {                                                \
        return double(al_dist_make(real(p)).smith_alpha);                           \
    }                                                                               \
    double w_ndf(double p, double c, double s2) {                                   \
        return double(al_ndf(al_dist_make(real(p)), real(c), real(s2)));            \
    }                                                                               \
    double w_cumulative(double p, double c, double s2) {                            \
        return double(al_ndf_cumulative(al_dist_make(real(p)), real(c), real(s2))); \
    }                                                                               \
    double w_tail(double p, double c, double s2) {                                  \
        return double(al_ndf_tail(al_dist_make(real(p)), real(c), real(s2)));       \
    }                                                                               \
    double w_y(double p, double c, double s2) {                                     \
        return double(al_ndf_y(al_dist_make(real(p)), real(c), real(s2)));          \
    }                                                                               \
    double w_lambda(double p, double c, double s2) {                                \
        return double(al_smith_lambda(al_dist_make(real(p)), real(c), real(s2)));   \
    }                                                                               \
    void w_y_inverse(double p, double y, double& c, double& s) {                    \
        rvec2 r = al_ndf_y_inverse(al_dist_make(real(p)), real(y));                 \
        c = double(r.x);                                                            \
        s = double(r.y);                                                            \
    }                                                                               \
    double w_erfcx(double x) {                                                      \
        return double(al_erfcx(real(x)));                                           \
    }                                                                               \
    double w_g2(double a, double b) {                                               \
        return double(al_smith_g2(real(a), real(b)));                               \
    }                                                                               \
    double w_schlick(double f0, double hv) {                                        \
        return double(al_schlick(real(f0), real(hv)));                              \
    }

#define AL_INOUT(T) T&
#define AL_FREXP_EXPONENT int

#define real double
#define rvec2 dvec2
#define rvec3 dvec3
#define rvec4 dvec4
#define AL_PRECISION_FP64 1
#define AL_R(x) x
#define AL_DIST_BLINN 1  // dist/microfacet.glsl defines the Beckmann Lambda only then
namespace mf64_blinn {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/blinn.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf64_blinn
#undef AL_DIST_BLINN
#define AL_DIST_BECKMANN 1  // dist/microfacet.glsl defines the Beckmann Lambda only then
namespace mf64_beckmann {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/beckmann.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf64_beckmann
#undef AL_DIST_BECKMANN
namespace mf64_ggx {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/ggx.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf64_ggx
#undef real
#undef rvec2
#undef rvec3
#undef rvec4
#undef AL_PRECISION_FP64
#undef AL_R

// The stitcher gives fp32 literals the f suffix; so does this.
#define real float
#define rvec2 vec2
#define rvec3 vec3
#define rvec4 vec4
#define AL_PRECISION_FP64 0
#define AL_R(x) x##f
#define AL_DIST_BLINN 1  // dist/microfacet.glsl defines the Beckmann Lambda only then
namespace mf32_blinn {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/blinn.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf32_blinn
#undef AL_DIST_BLINN
#define AL_DIST_BECKMANN 1  // dist/microfacet.glsl defines the Beckmann Lambda only then
namespace mf32_beckmann {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/beckmann.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf32_beckmann
#undef AL_DIST_BECKMANN
namespace mf32_ggx {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/dist/ggx.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/dist/microfacet.glsl"
AL_TEST_WRAPPERS
}  // namespace mf32_ggx
#undef real
#undef rvec2
#undef rvec3
#undef rvec4
#undef AL_PRECISION_FP64
#undef AL_R
#undef AL_INOUT

namespace {

using ld = long double;
const ld kPi = 3.141592653589793238462643383279502884L;

enum class Dist { Blinn, Beckmann, Ggx };

struct Impl {
    const char* name;
    Dist dist;
    bool fp64;
    double (*gmax)(double);
    double (*width)(double);
    double (*smith_alpha)(double);
    double (*ndf)(double, double, double);
    double (*cumulative)(double, double, double);
    double (*tail)(double, double, double);
    double (*y)(double, double, double);
    double (*lambda)(double, double, double);
    void (*y_inverse)(double, double, double&, double&);
    double (*erfcx)(double);
    double (*g2)(double, double);
    double (*schlick)(double, double);
};

#define AL_IMPL(ns, label, dist, fp64)                                                         \
    Impl {                                                                                     \
        label, dist, fp64, ns::w_gmax, ns::w_width, ns::w_smith_alpha, ns::w_ndf,              \
            ns::w_cumulative, ns::w_tail, ns::w_y, ns::w_lambda, ns::w_y_inverse, ns::w_erfcx, \
            ns::w_g2, ns::w_schlick                                                            \
    }

const std::vector<Impl>& impls() {
    static const std::vector<Impl> all = {
        AL_IMPL(mf64_blinn, "blinn fp64", Dist::Blinn, true),
        AL_IMPL(mf64_beckmann, "beckmann fp64", Dist::Beckmann, true),
        AL_IMPL(mf64_ggx, "ggx fp64", Dist::Ggx, true),
        AL_IMPL(mf32_blinn, "blinn fp32", Dist::Blinn, false),
        AL_IMPL(mf32_beckmann, "beckmann fp32", Dist::Beckmann, false),
        AL_IMPL(mf32_ggx, "ggx fp32", Dist::Ggx, false),
    };
    return all;
}

// Rounds to the working precision of an implementation.
double to_working(double x, bool fp64) {
    return fp64 ? x : double(float(x));
}

// ---- References, from CONTRACT.md 2, in long double -------------------------------

// D at the direction with sine s and cosine c (both accurate). GGX's
// (n.h)^2 (alpha^2 - 1) + 1 is written as the identical s^2 + alpha^2 c^2 (no
// cancellation near the pole at alpha = 0.001); blinn's c^N as exp(N log c), log c
// from log1p(-s^2) near the pole.
ld ref_ndf(Dist dist, ld p, ld s, ld c) {
    if (c <= 0) return 0;
    switch (dist) {
        case Dist::Blinn: {
            const ld lc = s < 0.7L ? 0.5L * std::log1p(-s * s) : std::log(c);
            return (p + 2) / (2 * kPi) * std::exp(p * lc);
        }
        case Dist::Beckmann: {
            const ld t2 = (s / c) * (s / c);
            return std::exp(-t2 / (p * p)) / (kPi * p * p * c * c * c * c);
        }
        case Dist::Ggx: {
            const ld q = s * s + p * p * c * c;
            return p * p / (kPi * q * q);
        }
    }
    return 0;
}

ld lobe_width(Dist dist, ld p) {
    return dist == Dist::Blinn ? std::sqrt(2 / (p + 2)) : p;
}

// An angle from n held as t and phi = pi/2 - t, the smaller one exact: near the horizon
// cos t = sin(phi), where cos(t) itself would carry long double's 1e-19 absolute error
// of t (1e-13 relative at cos = 1e-6, times N in c^N).
struct Angle {
    ld t, phi;
    ld sin() const { return t <= phi ? std::sin(t) : std::cos(phi); }
    ld cos() const { return t <= phi ? std::cos(t) : std::sin(phi); }
};
Angle from_t(ld t) {
    return {t, kPi / 2 - t};
}
Angle from_phi(ld phi) {
    return {kPi / 2 - phi, phi};
}
const Angle kPole = from_t(0), kHorizon = from_phi(0);

// The angle the inputs (c, s2) describe, from the better-conditioned of the two.
Angle angle_of(double c, double s2) {
    if (c <= 0) return kHorizon;
    return s2 < 0.5 ? from_t(std::asin(std::sqrt(ld(s2)))) : from_phi(std::asin(ld(c)));
}

// int_a^b f(x) dx over the pieces between the cuts. Each piece is mapped onto
// [-1, 1]: Boost 1.74's adaptive GK compares the error of the unscaled rule with a
// tolerance of the scaled integral, so on a short interval it would never converge.
// Its |K - G| estimate is pessimistic (K is far more accurate), so 1e-16 suffices; a
// stricter one is unreachable where exp(N log c) carries |N log c| ulp of noise.
template <class F>
ld integrate_pieces(F f, ld a, ld b, std::vector<ld> cuts) {
    if (!(b > a)) return 0;
    cuts.erase(std::remove_if(cuts.begin(), cuts.end(), [&](ld x) { return !(x > a && x < b); }),
               cuts.end());
    cuts.push_back(a);
    cuts.push_back(b);
    std::sort(cuts.begin(), cuts.end());
    ld sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const ld mid = (cuts[i] + cuts[i + 1]) / 2, half = (cuts[i + 1] - cuts[i]) / 2;
        auto g = [&](ld x) { return half * f(mid + half * x); };
        ld err = 0;
        sum += boost::math::quadrature::gauss_kronrod<ld, 31>::integrate(g, -1.0L, 1.0L, 10, 1e-16L,
                                                                         &err);
    }
    return sum;
}

// int_a^b f(sin t, cos t) dt: in t up to pi/4, cut at w 2^k so a narrow lobe is always
// resolved; in phi beyond, cut at (pi/4) 2^-k for the c^N-like behaviour at phi -> 0.
template <class F>
ld integrate_dir(F f, Angle a, Angle b, ld w) {
    const ld quarter = kPi / 4;
    ld sum = 0;
    if (a.t < quarter) {
        std::vector<ld> cuts;
        for (int k = -24; k <= 12; ++k) cuts.push_back(w * std::ldexp(1.0L, k));
        sum += integrate_pieces([&](ld t) { return f(std::sin(t), std::cos(t)); }, a.t,
                                std::min(b.t, quarter), cuts);
    }
    if (b.t > quarter) {
        std::vector<ld> cuts;
        for (int k = 1; k <= 60; ++k) cuts.push_back(quarter * std::ldexp(1.0L, -k));
        sum += integrate_pieces([&](ld phi) { return f(std::cos(phi), std::sin(phi)); }, b.phi,
                                std::min(a.phi, quarter), cuts);
    }
    return sum;
}

struct RefIntegrals {
    ld G, T, y;
};

RefIntegrals ref_integrals(Dist dist, ld p, Angle theta) {
    const ld w = lobe_width(dist, p);
    auto dsin = [&](ld s, ld c) { return ref_ndf(dist, p, s, c) * s; };
    auto dcossin = [&](ld s, ld c) { return 2 * kPi * ref_ndf(dist, p, s, c) * c * s; };
    return {integrate_dir(dsin, kPole, theta, w), integrate_dir(dsin, theta, kHorizon, w),
            integrate_dir(dcossin, theta, kHorizon, w)};
}

// erfcx in long double: Boost's erfc below 10, the asymptotic series beyond (terms
// fall below 1e-23 relative by the 20th).
ld ref_erfcx(ld x) {
    if (x < 10) return boost::math::erfc(x) * std::exp(x * x);
    ld term = 1, sum = 1;
    for (int n = 1; n <= 30; ++n) {
        term *= -(2 * n - 1) / (2 * x * x);
        sum += term;
    }
    return sum / (x * std::sqrt(kPi));
}

// CONTRACT.md 2's Lambda at (c, s2). Beckmann's (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi))
// is evaluated with erfc (the same expression; erf(a) - 1 itself would lose all digits
// in long double at a = 10); the difference loses at most 2 a^2 <= 1500x there.
ld ref_lambda(Dist dist, ld alpha, ld c, ld s2) {
    if (s2 <= 0) return 0;
    if (dist == Dist::Ggx) return boost::math::sqrt1pm1(alpha * alpha * s2 / (c * c)) / 2;
    const ld a = c / (alpha * std::sqrt(s2));
    return (std::exp(-a * a) / (a * std::sqrt(kPi)) - boost::math::erfc(a)) / 2;
}

// ---- Grids ---------------------------------------------------------------------------

std::vector<double> params(Dist dist) {
    std::vector<double> v;
    if (dist == Dist::Blinn) {
        for (int k = 0; k <= 10; ++k) v.push_back(std::pow(10.0, k / 2.0));  // 1 .. 1e5
        v.push_back(7.3);
    } else {
        for (int k = 0; k <= 6; ++k) v.push_back(std::pow(10.0, -3.0 + k / 2.0));  // 1e-3 .. 1
        v.push_back(0.5);
        v.push_back(0.9999);
    }
    return v;
}

// Angles from the pole to the horizon: tiny ones, a coarse sweep, the horizon's
// neighbourhood (as phi = pi/2 - theta), and multiples of the lobe width w.
std::vector<Angle> thetas(ld w) {
    std::vector<Angle> v;
    for (ld t :
         {0.0L, 1e-6L, 1e-5L, 1e-4L, 1e-3L, 1e-2L, 0.05L, 0.1L, 0.2L, 0.3L, 0.4L, 0.5L, 0.6L, 0.7L})
        v.push_back(from_t(t));
    for (ld phi : {0.0L, 1e-6L, 1e-4L, 1e-2L, 0.1L, 0.3L, 0.5L, 0.7L}) v.push_back(from_phi(phi));
    for (ld k : {1e-3L, 0.01L, 0.1L, 0.3L, 0.35L, 0.36L, 0.5L, 0.7L, 1.0L, 1.5L, 2.0L, 3.0L, 4.0L,
                 6.0L, 10.0L, 20.0L})
        if (k * w < kPi / 4) v.push_back(from_t(k * w));
    return v;
}

// ---- Bookkeeping ---------------------------------------------------------------------

ld rel_err(ld got, ld want) {
    return std::fabs(got - want) / std::fabs(want);
}

struct Worst {
    double err = 0;
    std::string where = "none";
    void add(ld e, const std::string& at) {
        if (!(e <= err)) {  // also catches NaN
            err = std::isnan(double(e)) ? std::numeric_limits<double>::infinity() : double(e);
            where = at;
        }
    }
};

std::string describe(const Impl& im, double p, double c, double s2, ld got, ld want) {
    std::ostringstream o;
    o.precision(17);
    o << im.name << " param=" << p << " c=" << c << " s2=" << s2 << " got=" << double(got)
      << " want=" << double(want);
    return o.str();
}

// Values below these are outside the range where relative accuracy is asked: fp64's
// exp(-745) and fp32's denormals (which a GPU may flush).
double tiny(bool fp64) {
    return fp64 ? 1e-290 : 1e-30;
}

// Relative error where the reference is a normal number of the working precision
// (beyond, the value must be as tiny), and the same per unit of 1 + |log want|: a value
// exp(-U) from a U with a few ulp carries |U| ulp, the conditioning of exp.
struct Accuracy {
    Worst rel, per_log;
    void add(double got, ld want, bool fp64, const std::string& at) {
        const double lim = tiny(fp64);
        if (want > lim) {
            const ld e = rel_err(got, want);
            rel.add(e, at);
            per_log.add(e / (1 + std::fabs(std::log(want))), at);
        } else {
            const ld e = want == 0 ? (got == 0 ? 0 : 1) : (got <= 2 * lim ? 0 : 1);
            rel.add(e, at);
            per_log.add(e, at);
        }
    }
};

// One assertion per worst case, printing it and where it occurred.
#define CHECK_WORST(worst, bound, label)                                            \
    do {                                                                            \
        INFO(label << ": worst " << (worst).err << " (bound " << (bound) << ") at " \
                   << (worst).where);                                               \
        CHECK((worst).err <= (bound));                                              \
    } while (0)

bool finite_nonneg(double x) {
    return std::isfinite(x) && x >= 0;
}

}  // namespace

TEST_CASE("D is normalized: 2 pi int D cos sin = 1 and y(0) = 1", "[microfacet]") {
    Worst norm, y0;
    for (const Impl& im : impls()) {
        for (double p0 : params(im.dist)) {
            const double p = to_working(p0, im.fp64);
            if (im.fp64) {  // the contract's D itself: once per distribution
                const ld total = integrate_dir(
                    [&](ld s, ld c) { return 2 * kPi * ref_ndf(im.dist, p, s, c) * c * s; }, kPole,
                    kHorizon, lobe_width(im.dist, p));
                norm.add(std::fabs(total - 1), describe(im, p, 1, 0, total, 1));
            }
            const double y = im.y(p, 1, 0);
            y0.add(std::fabs(y - 1), describe(im, p, 1, 0, y, 1));
        }
    }
    // Measured: quadrature within 1.6e-19 (long double rounding), y(0) exactly 1.
    CHECK_WORST(norm, 1e-17, "contract's D by quadrature: |2 pi int D cos sin - 1|");
    CHECK_WORST(y0, 0.0, "|y(0) - 1|");
}

TEST_CASE("G, T and y match quadrature of the contract's D", "[microfacet]") {
    // Asserted: the relative error, and that per unit of 1 + |log value| (the tails
    // exp(-U) carry U ulp: fp64 1.8e-13 where the value is 1e-280), each at about 1.5x
    // the worst measured on a 5x denser grid with random angles. [dist] for G, T, y, D.
    struct Bounds {
        double G, T, y, D;
    };
    const Bounds rel64[3] = {{7.5e-16, 2.7e-13, 2.7e-13, 2.2e-13},   // blinn
                             {4.5e-15, 2.5e-13, 2.5e-13, 2.5e-13},   // beckmann
                             {7.5e-16, 7.5e-16, 6.5e-16, 1.3e-15}};  // ggx
    const Bounds log64[3] = {{7.5e-16, 6.5e-16, 6.5e-16, 3e-15},
                             {1e-15, 5.1e-16, 5.1e-16, 3e-15},
                             {7.5e-16, 7.5e-16, 6.5e-16, 1.3e-15}};
    const Bounds rel32[3] = {{4e-7, 1.5e-5, 1.5e-5, 2e-5},
                             {2.2e-6, 1.3e-5, 1.3e-5, 1.8e-5},
                             {4.5e-7, 4.5e-7, 3.3e-7, 7e-7}};
    const Bounds log32[3] = {{4e-7, 3e-7, 3.4e-7, 1.2e-6},
                             {2.2e-6, 3e-7, 3.4e-7, 1.4e-6},
                             {4.5e-7, 4.5e-7, 3.3e-7, 7e-7}};
    for (const Impl& im : impls()) {
        Accuracy ag, at, ay, ad;
        Worst wsum, bad;
        const int di = int(im.dist);
        for (double p0 : params(im.dist)) {
            const double p = to_working(p0, im.fp64);
            const double gmax = im.gmax(p);
            const ld w = lobe_width(im.dist, p);
            const RefIntegrals whole = ref_integrals(im.dist, p, kPole);
            ag.add(gmax, whole.T, im.fp64, describe(im, p, 1, 0, gmax, whole.T) + " (gmax)");
            for (const Angle& theta : thetas(w)) {
                const double c = to_working(double(theta.cos()), im.fp64);
                const double s2 = to_working(double(theta.sin() * theta.sin()), im.fp64);
                const Angle th = angle_of(c, s2);
                const RefIntegrals r = ref_integrals(im.dist, p, th);
                const ld d_ref = ref_ndf(im.dist, p, th.sin(), th.cos());
                const double G = im.cumulative(p, c, s2), T = im.tail(p, c, s2), y = im.y(p, c, s2),
                             D = im.ndf(p, c, s2);
                for (double v : {G, T, y, D})
                    if (!finite_nonneg(v)) bad.add(1, describe(im, p, c, s2, v, 0));
                ag.add(G, r.G, im.fp64, describe(im, p, c, s2, G, r.G) + " (G)");
                at.add(T, r.T, im.fp64, describe(im, p, c, s2, T, r.T) + " (T)");
                ay.add(y, r.y, im.fp64, describe(im, p, c, s2, y, r.y) + " (y)");
                if (c > 0) ad.add(D, d_ref, im.fp64, describe(im, p, c, s2, D, d_ref) + " (D)");
                wsum.add(std::fabs(G + T - gmax) / gmax, describe(im, p, c, s2, G + T, gmax));
            }
        }
        const Bounds& br = im.fp64 ? rel64[di] : rel32[di];
        const Bounds& bl = im.fp64 ? log64[di] : log32[di];
        const std::string n = im.name;
        CHECK_WORST(ag.rel, br.G, n + " G (and gmax) relative error");
        CHECK_WORST(at.rel, br.T, n + " T relative error");
        CHECK_WORST(ay.rel, br.y, n + " y relative error");
        CHECK_WORST(ad.rel, br.D, n + " D relative error");
        CHECK_WORST(ag.per_log, bl.G, n + " G relative error / (1 + |log G|)");
        CHECK_WORST(at.per_log, bl.T, n + " T relative error / (1 + |log T|)");
        CHECK_WORST(ay.per_log, bl.y, n + " y relative error / (1 + |log y|)");
        CHECK_WORST(ad.per_log, bl.D, n + " D relative error / (1 + |log D|)");
        CHECK_WORST(wsum, im.fp64 ? 1e-15 : 4e-7, n + " |G + T - gmax| / gmax");
        CHECK_WORST(bad, 0.0, n + " non-finite or negative");
        if (im.fp64) {  // the task's target, whatever the bounds above say
            for (const Accuracy* a : {&ag, &at, &ay, &ad})
                CHECK_WORST(a->rel, 1e-12, n + " fp64 target");
        }
    }
}

TEST_CASE("the closed forms as stated, in long double, match quadrature", "[microfacet]") {
    // The forms of the brief, literally (the templates use rearrangements of them):
    //   blinn G = (N+2)/(2 pi (N+1)) (1 - c^(N+1)),  y = c^(N+2);
    //   beckmann G = alpha/(2 pi) [A(1/alpha^2) - exp(-tan^2/alpha^2) A(1/(alpha c)^2)],
    //     A(x) = sqrt(x) + sqrt(pi)/2 erfcx(sqrt(x)),  y = exp(-s2/(alpha c)^2);
    //   ggx G = alpha^2/pi (F(1) - F(c)), F(c) = c/(2(1 - b c^2)) + atanh(sqrt(b) c)/(2 sqrt b),
    //     b = 1 - alpha^2,  y = alpha^2 c^2/(alpha^2 c^2 + s2).
    // At angles where the differences cancel little (theta >= width/2).
    Worst wg, wy;
    for (Dist dist : {Dist::Blinn, Dist::Beckmann, Dist::Ggx}) {
        for (double p : params(dist)) {
            if (dist == Dist::Ggx && p == 1) continue;  // F's atanh(sqrt b)/sqrt b at b = 0: 0/0
            const ld w = lobe_width(dist, p);
            for (const Angle& a : thetas(w)) {
                if (a.t < w / 2) continue;
                const ld c = a.cos(), s = a.sin(), s2 = s * s, P = p;
                ld g = 0, y = 0;
                if (dist == Dist::Blinn) {
                    g = (P + 2) / (2 * kPi * (P + 1)) * (1 - std::pow(c, P + 1));
                    y = std::pow(c, P + 2);
                } else if (dist == Dist::Beckmann) {
                    auto A = [](ld x) {
                        return std::sqrt(x) + std::sqrt(kPi) / 2 * ref_erfcx(std::sqrt(x));
                    };
                    const ld u = s2 / (P * P * c * c);
                    g = c > 0 ? P / (2 * kPi) *
                                    (A(1 / (P * P)) - std::exp(-u) * A(1 / (P * P * c * c)))
                              : P / (2 * kPi) * A(1 / (P * P));
                    y = c > 0 ? std::exp(-u) : 0;
                } else {
                    const ld b = 1 - P * P, rb = std::sqrt(b);
                    auto F = [&](ld x) {
                        return x / (2 * (1 - b * x * x)) + std::atanh(rb * x) / (2 * rb);
                    };
                    g = P * P / kPi * (F(1) - F(c));
                    y = P * P * c * c / (P * P * c * c + s2);
                }
                const RefIntegrals r = ref_integrals(dist, P, a);
                std::ostringstream at;
                at.precision(17);
                at << "dist " << int(dist) << " param " << p << " theta " << double(a.t);
                wg.add(rel_err(g, r.G), at.str() + " G " + std::to_string(double(g)));
                if (r.y > 1e-4000L)
                    wy.add(rel_err(y, r.y), at.str() + " y " + std::to_string(double(y)));
            }
        }
    }
    // A typo would be off by O(1). Measured: G 1.5e-13 (the literal GGX form's atanh at
    // sqrt(b) c = 1 - 5e-7, alpha = 0.001, loses digits even in long double), y 2.5e-15
    // (pow(c, N + 2) at N = 1e5).
    CHECK_WORST(wg, 1e-12, "stated closed-form G vs quadrature");
    CHECK_WORST(wy, 1e-14, "stated closed-form y vs quadrature");
}

TEST_CASE("Smith Lambda matches the contract's formulas", "[microfacet]") {
    // The Beckmann family carries 2 a^2 ulp of exp(-a^2) (fp64 2.8e-13 at Lambda =
    // 1e-248, a^2 = 570) and, in fp32, up to 36x cancellation of 1/(a sqrt(pi)) - erfcx(a)
    // just below a = 4; GGX a few ulp. Asserted at about 1.5x the worst measured on a
    // 5x denser grid: [dist] relative, and relative per unit of 1 + |log Lambda|.
    const double rel64[3] = {4.2e-13, 4.2e-13, 1e-15}, log64[3] = {1.7e-15, 1.7e-15, 1e-15};
    const double rel32[3] = {2.2e-5, 2.2e-5, 3e-7}, log32[3] = {7.5e-7, 7.5e-7, 3e-7};
    for (const Impl& im : impls()) {
        Accuracy al;
        Worst bad;
        for (double p0 : params(im.dist)) {
            const double p = to_working(p0, im.fp64);
            const ld alpha = im.dist == Dist::Blinn ? std::sqrt(2 / (ld(p) + 2)) : ld(p);
            std::vector<Angle> angles = thetas(lobe_width(im.dist, p));
            for (ld phi : {1e-12L, 1e-9L, 1e-3L}) angles.push_back(from_phi(phi));
            for (const Angle& a : angles) {
                const double c = to_working(double(a.cos()), im.fp64);
                const double s2 = to_working(double(a.sin() * a.sin()), im.fp64);
                if (c <= 0) continue;  // the horizon: only finiteness (below)
                const double got = im.lambda(p, c, s2);
                const ld want = ref_lambda(im.dist, alpha, c, s2);
                const std::string at = describe(im, p, c, s2, got, want);
                if (!finite_nonneg(got)) bad.add(1, at);
                al.add(got, want, im.fp64, at);
            }
        }
        const std::string n = im.name;
        const int di = int(im.dist);
        CHECK_WORST(al.rel, im.fp64 ? rel64[di] : rel32[di], n + " Lambda relative error");
        CHECK_WORST(al.per_log, im.fp64 ? log64[di] : log32[di],
                    n + " Lambda relative error / (1 + |log Lambda|)");
        CHECK_WORST(bad, 0.0, n + " Lambda non-finite or negative");
    }
}

TEST_CASE("erfcx matches Boost's erfc in long double", "[microfacet]") {
    std::vector<double> xs = {0.0, 1e-300, 1e-12, 1e-6, 1e-3, 0.46875, 4.0, 1e3, 1e6, 1e8, 1e12};
    for (double x : {0.46875, 4.0}) {
        xs.push_back(std::nextafter(x, 0.0));
        xs.push_back(std::nextafter(x, 10.0));
    }
    for (int k = 0; k <= 3000; ++k) xs.push_back(k * 0.01);                      // 0 .. 30
    for (int k = 0; k <= 160; ++k) xs.push_back(std::pow(10.0, -4 + k / 20.0));  // 1e-4 .. 1e4
    for (const Impl& im : impls()) {
        if (im.dist != Dist::Beckmann) continue;  // one copy per precision suffices
        Worst we;
        for (double x0 : xs) {
            const double x = to_working(x0, im.fp64);
            if (!im.fp64 && x0 > 1e30) continue;
            const double got = im.erfcx(x);
            const ld want = ref_erfcx(x);
            we.add(rel_err(got, want), describe(im, x, 0, 0, got, want));
        }
        // Measured: fp64 6.4e-16, fp32 3.6e-7.
        CHECK_WORST(we, im.fp64 ? 1e-15 : 5.4e-7, std::string(im.name) + " erfcx relative error");
    }
}

TEST_CASE("y_inverse inverts y", "[microfacet]") {
    // The exact inverse of the given y (the closed forms the quadrature test verified,
    // in long double), and the round trip y(y_inverse(y)), whose error is relative to
    // 1 + |log y| (y's own conditioning in the angle).
    for (const Impl& im : impls()) {
        Worst wc, ws, wr, bad;
        for (double p0 : params(im.dist)) {
            const double p = to_working(p0, im.fp64);
            std::vector<double> ys = {0.0,
                                      1.0,
                                      1 - 1e-12,
                                      0.999,
                                      0.9,
                                      0.5,
                                      0.1,
                                      1e-3,
                                      1e-10,
                                      1e-30,
                                      im.fp64 ? 1e-300 : 1e-37};
            for (const Angle& a : thetas(lobe_width(im.dist, p)))
                ys.push_back(im.y(p, a.cos(), a.sin() * a.sin()));
            for (double y0 : ys) {
                const double y = to_working(y0, im.fp64);
                double c = 0, s = 0;
                im.y_inverse(p, y, c, s);
                ld cw = 0, sw = 1;
                const ld yl = y;
                if (y > 0) {
                    if (im.dist == Dist::Blinn) {
                        const ld lc = std::log(yl) / (ld(p) + 2);
                        cw = std::exp(lc);
                        sw = std::sqrt(-std::expm1(2 * lc));
                    } else if (im.dist == Dist::Beckmann) {
                        const ld t2 = -ld(p) * ld(p) * std::log(yl);
                        cw = 1 / std::sqrt(1 + t2);
                        sw = std::sqrt(t2 / (1 + t2));
                    } else {
                        const ld t = ld(p) * ld(p) * (1 - yl), den = yl + t;
                        cw = std::sqrt(yl / den);
                        sw = std::sqrt(t / den);
                    }
                }
                const std::string at = describe(im, p, c, s * s, y, 0) + " inverse (" +
                                       std::to_string(double(cw)) + ", " +
                                       std::to_string(double(sw)) + ")";
                if (!(finite_nonneg(c) && finite_nonneg(s) && c <= 1 && s <= 1)) bad.add(1, at);
                // exp(log(y)/(N+2)) carries |log c| ulp of log y's rounding: c = 1e-100
                // (y = 1e-300 at N = 1) is 2e-14 off, relative to 1 + |log c| a few ulp.
                wc.add(cw > 0 ? rel_err(c, cw) / (1 + std::fabs(std::log(cw))) : (c == 0 ? 0 : 1),
                       at);
                ws.add(sw > 0 ? rel_err(s, sw) : (s == 0 ? 0 : 1), at);
                if (y > tiny(im.fp64) && c > 0) {
                    const double back = im.y(p, c, s * s);
                    wr.add(rel_err(back, y) / (1 + std::fabs(std::log(y))), at);
                }
            }
        }
        // Measured on a 5x denser grid (fp64 / fp32): cos 2.4e-16 / 1.1e-7 per unit of
        // 1 + |log cos|, sin 3.3e-16 / 1.9e-7, round trip 7.2e-16 / 3.7e-7 per unit of
        // 1 + |log y|; asserted at about 1.5x.
        const std::string n = im.name;
        const double e = im.fp64 ? 1.1e-15 : 5.6e-7;
        CHECK_WORST(wc, e, n + " y_inverse cos relative error / (1 + |log cos|)");
        CHECK_WORST(ws, e, n + " y_inverse sin relative error");
        CHECK_WORST(wr, e, n + " y(y_inverse(y)) relative error / (1 + |log y|)");
        CHECK_WORST(bad, 0.0, n + " y_inverse outside [0, 1]");
    }
}

TEST_CASE("finite and non-negative at the ends of the domain", "[microfacet]") {
    for (const Impl& im : impls()) {
        Worst bad;
        const std::vector<double> ps =
            im.dist == Dist::Blinn ? std::vector<double>{1, 1e5} : std::vector<double>{1e-3, 1};
        // The corners (c, s2) in {0, 1}^2 (two of them not a direction: still finite),
        // and grazing directions.
        std::vector<std::pair<double, double>> inputs = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
        for (double c : {1e-30, 1e-20, 1e-10, 1e-5}) inputs.push_back({c, 1 - c * c});
        if (im.fp64) inputs.push_back({1e-300, 1});
        for (double p : ps) {
            for (double v : {im.gmax(p), im.width(p), im.smith_alpha(p)})
                if (!(finite_nonneg(v) && v > 0)) bad.add(1, describe(im, p, 0, 0, v, 0));
            for (auto [c, s2] : inputs) {
                for (double v : {im.ndf(p, c, s2), im.cumulative(p, c, s2), im.tail(p, c, s2),
                                 im.y(p, c, s2), im.lambda(p, c, s2)})
                    if (!finite_nonneg(v)) bad.add(1, describe(im, p, c, s2, v, 0));
                if (im.cumulative(p, c, s2) > im.gmax(p) * (1 + 1e-6))
                    bad.add(1, describe(im, p, c, s2, im.cumulative(p, c, s2), im.gmax(p)));
            }
            for (double y : {0.0, 1e-45, 1e-38, 1.0}) {
                double c = -1, s = -1;
                im.y_inverse(p, y, c, s);
                if (!(finite_nonneg(c) && finite_nonneg(s) && c <= 1 && s <= 1))
                    bad.add(1, describe(im, p, c, s, y, 0));
            }
            // Grazing gives a large Lambda (the exact one is infinite at c = 0).
            const double graze = im.lambda(p, 1e-10, 1), horizon = im.lambda(p, 0, 1);
            if (!(graze > 1e5 && horizon >= graze))
                bad.add(1, describe(im, p, 0, 1, horizon, graze) + " (Lambda at the horizon)");
            if (im.lambda(p, 1, 0) != 0) bad.add(1, describe(im, p, 1, 0, im.lambda(p, 1, 0), 0));
        }
        CHECK_WORST(bad, 0.0, std::string(im.name) + " bad value");
    }
}

TEST_CASE("AlDist constants, G2 and Schlick", "[microfacet]") {
    for (const Impl& im : impls()) {
        const double tol = im.fp64 ? 1e-15 : 2e-7;
        for (double p0 : params(im.dist)) {
            const double p = to_working(p0, im.fp64);
            const double alpha = im.dist == Dist::Blinn ? std::sqrt(2 / (p + 2)) : p;
            INFO(im.name << " param " << p << " width " << im.width(p) << " smith_alpha "
                         << im.smith_alpha(p));
            CHECK(std::fabs(im.width(p) - alpha) <= tol * alpha);
            CHECK(std::fabs(im.smith_alpha(p) - alpha) <= tol * alpha);
        }
        INFO(im.name);
        CHECK(im.g2(0, 0) == 1);
        CHECK(std::fabs(im.g2(1, 2) - 0.25) <= tol);
        CHECK(im.schlick(0.04, 1) == Approx(0.04).epsilon(tol));
        CHECK(im.schlick(0.04, 0) == Approx(1).epsilon(tol));
        CHECK(im.schlick(0.04, 1.5) == Approx(0.04).epsilon(tol));  // h.v rounded above 1
        CHECK(im.schlick(0.04, 0.5) == Approx(0.04 + 0.96 / 32).epsilon(tol));
    }
}
