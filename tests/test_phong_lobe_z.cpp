// The closed-form z integral of the Phong peak methods (templates/method/phong_lobe_z.glsl),
// int x^N dtau over an arc, x = c cos(tau), compiled as C++ at both working precisions
// (fp32 with AL_FAST_ARC, as the polygon variants run it), against adaptive Gauss-Kronrod
// quadrature in double over a grid of (c, N, arc).
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <sstream>
#include <string>

#define AL_INOUT(T) T&
#define AL_FREXP_EXPONENT int

#define AL_Z_WRAPPER                                                                 \
    double w_z(double c, double n, double ta, double tb) {                           \
        AlEdgeFrame E;                                                               \
        E.s = real(std::sqrt(std::max(0.0, 1 - c * c)));                             \
        E.rm = E.s;                                                                  \
        E.c = real(c);                                                               \
        E.ag = real(std::sin(ta));                                                   \
        E.af = real(std::cos(ta));                                                   \
        E.bg = real(std::sin(tb));                                                   \
        E.bf = real(std::cos(tb));                                                   \
        E.xa = E.c * E.af;                                                           \
        E.xb = E.c * E.bf;                                                           \
        E.far_edge = false;                                                          \
        const real lc = AL_R(0.5) * al_log1p(-E.s * E.s);                            \
        return double(al_lobe_z(E, lc, real(n)));                                    \
    }

#define real double
#define rvec2 dvec2
#define rvec3 dvec3
#define rvec4 dvec4
#define AL_PRECISION_FP64 1
#define AL_R(x) x
namespace z64 {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/method/phong_edge.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/method/phong_lobe_z.glsl"
AL_Z_WRAPPER
}  // namespace z64
#undef real
#undef rvec2
#undef rvec3
#undef rvec4
#undef AL_PRECISION_FP64
#undef AL_R
#undef AL_EXPM1_SERIES_BELOW  // common.glsl's; set again under AL_FAST_ARC below

// The polygon peak variants' precision and forms: fp32, AL_FAST_ARC (common/common.glsl
// defines it for a polygon light and a peak method).
#define real float
#define rvec2 vec2
#define rvec3 vec3
#define rvec4 vec4
#define AL_PRECISION_FP64 0
#define AL_R(x) x##f
#define AL_LIGHT_POLYGON 1
#define AL_METHOD_PEARSON 1
namespace z32 {
using namespace glm;
#include "templates/common/common.glsl"
#include "templates/method/phong_edge.glsl"
#include "templates/common/erfcx.glsl"
#include "templates/method/phong_lobe_z.glsl"
AL_Z_WRAPPER
}  // namespace z32
#undef AL_LIGHT_POLYGON
#undef AL_METHOD_PEARSON
#undef AL_FAST_ARC
#undef real
#undef rvec2
#undef rvec3
#undef rvec4
#undef AL_PRECISION_FP64
#undef AL_R

namespace {

// c^N int cos^N over [ta, tb], substituting tan(tau) = sigma tan(xi), sigma^2 = 4 / N: the
// lobe maps to width ~1 in xi, so a few subdivisions resolve it to 1e-13.
double exact_z(double c, double n, double ta, double tb) {
    using boost::math::quadrature::gauss_kronrod;
    const double sigma = std::sqrt(4 / n);
    auto f = [&](double xi) {
        const double sx = std::sin(xi), cx = std::cos(xi);
        const double q2 = cx * cx + sigma * sigma * sx * sx;
        return std::pow(cx * cx / q2, 0.5 * n) * sigma / q2;  // cos^N(tau) dtau/dxi
    };
    const double xa = std::atan2(std::sin(ta), sigma * std::cos(ta));
    const double xb = std::atan2(std::sin(tb), sigma * std::cos(tb));
    return std::pow(c, n) * gauss_kronrod<double, 31>::integrate(f, xa, xb, 15, 1e-13);
}

// The whole lobe, c^N sqrt(pi) Gamma((N + 1) / 2) / Gamma(N / 2 + 1): the error's scale
// (the z sum's share of the specular moment is of that order wherever it matters).
double lobe_z(double c, double n) {
    return std::pow(c, n) *
           std::exp(0.5 * std::log(M_PI) + std::lgamma(0.5 * (n + 1)) - std::lgamma(0.5 * n + 1));
}

struct Arc {
    double ta, tb;
};
const double kCs[] = {0.3, 0.9, 0.999, 1.0};
const double kNs[] = {32, 33.5, 50, 100, 316, 1000, 3162, 1e4, 1e5};
const Arc kArcs[] = {{-1.5, 1.5},  {-0.5, 0.5},  {-0.05, 0.3}, {0.1, 0.6},  {0.4, 1.5},
                     {-1.4, -0.9}, {0.0, 0.01},  {-0.002, 0.001}, {0.2, 0.25}, {-1.57, -0.3}};

// |z - quadrature| / the lobe's integral. fp64: the truncation of dt/dw's series at 1/N^2
// (measured 2.1e-5 at N = 32 in the header's check, less above); fp32 adds rounding and
// AL_FAST_ARC's erfcx (4.3e-7 relative).
constexpr double kZTol64 = 3e-5;
constexpr double kZTol32 = 3e-5;

// floor: the smallest lobe measured against (fp32 holds no result below its normal range:
// c^N = 0.999^1e5 = 4e-44 rounds to 0 there).
template <typename F>
double worst_error(F z, double floor, std::string& where) {
    double worst = 0;
    for (double c : kCs) {
        for (double n : kNs) {
            const double lobe = lobe_z(c, n);
            if (!(lobe > floor)) continue;
            for (const Arc& a : kArcs) {
                const double got = z(c, n, a.ta, a.tb);
                const double e = std::abs(got - exact_z(c, n, a.ta, a.tb)) / lobe;
                if (!(e <= worst)) {
                    worst = std::isnan(e) ? INFINITY : e;
                    std::ostringstream o;
                    o << "c " << c << " N " << n << " arc [" << a.ta << ", " << a.tb << "]: " << got;
                    where = o.str();
                }
            }
        }
    }
    return worst;
}

}  // namespace

TEST_CASE("the Phong peak methods' closed-form z integral matches quadrature, N >= 32",
          "[peak]") {
    std::string where;
    const double e64 = worst_error(z64::w_z, 1e-300, where);
    INFO("fp64 worst " << e64 << " at " << where);
    CHECK(e64 <= kZTol64);
    const double e32 = worst_error(z32::w_z, 1e-30, where);
    INFO("fp32 worst " << e32 << " at " << where);
    CHECK(e32 <= kZTol32);
}

TEST_CASE("the closed-form z integral is finite and non-negative at its extremes", "[peak]") {
    // Ends at x = 0 (tau = +-pi/2: f = 0), empty and reversed arcs, c at 0 and 1, N at both ends.
    for (double c : {0.0, 1e-6, 0.5, 1.0}) {
        for (double n : {32.0, 1e5}) {
            for (Arc a : {Arc{-M_PI / 2, M_PI / 2}, Arc{0.3, 0.3}, Arc{0.5, 0.2},
                          Arc{M_PI / 2, M_PI / 2}, Arc{-M_PI / 2, -1.0}}) {
                for (double z : {z64::w_z(c, n, a.ta, a.tb), z32::w_z(c, n, a.ta, a.tb)}) {
                    INFO("c " << c << " N " << n << " arc [" << a.ta << ", " << a.tb << "]: " << z);
                    CHECK(std::isfinite(z));
                    CHECK(z >= 0.0);
                }
            }
        }
    }
}
