// Shared vocabulary of every variant: the case record the host uploads, the
// result record, and numerically careful helpers. Valid GLSL 4.50 and, through
// the mirror prolog, C++ with GLM (one source of truth for both backends). The
// math is written over `real`/`rvec3` (the variant's precision), and the stitcher
// gives every literal wrapped in AL_R the suffix of that precision (stitcher.cpp).

// The peak-function methods on polygons at fp32 (errors ~1e-2 by construction) take
// cheaper forms of atan2 and log (AL_FAST_ARC below): on RDNA2 (navi21, `arealight
// gpu-cost`) they cut GGX lorentz from 29 124 to 24 555 cycles per wave, Phong lorentz
// from 11 480 to 9 509, and change no public set's relL2 by more than 0.5%. So do the
// microfacet exact methods at O(1) node counts (fp32, nodes <= 3: errors 1e-3 to 1e-2 by
// construction): ggx nodes=2 radial=2 23 687 -> 20 937 cycles a wave, beckmann 23 545 ->
// 21 886, every public set's specular, ndf and diffuse relL2 unchanged to 3 digits. The
// other methods keep the ulp-accurate forms their bars need: the exact ones at their
// default node counts went from ~1e-6 to ~5e-6 with them and Phong's two-sided horizon
// cases from 6.6e-5 to 1.7e-3 (the swept azimuths' 1.7e-6 rad); and so do curved lights,
// where the Phong boundary's horizon cases went from 0.0024 to 0.021.
#if !AL_PRECISION_FP64 && defined(AL_LIGHT_POLYGON) && \
    (defined(AL_METHOD_LORENTZ) || defined(AL_METHOD_PEARSON) || defined(AL_METHOD_ELLIPSOID) || \
     (defined(AL_METHOD_EXACT) && !defined(AL_DIST_PHONG) && AL_NODES <= 3))
#define AL_FAST_ARC 1
#endif

const real AL_PI = AL_R(3.14159265358979323846);
const real AL_TWO_PI = AL_R(6.28318530717958647692);
const real AL_HALF_PI = AL_R(1.57079632679489661923);
// The smallest normal number of the working precision, for guards that must keep a
// divisor non-zero: 1e-300 rounds to 0 at fp32 and lets 0 / 0 through.
#if AL_PRECISION_FP64
const real AL_TINY = AL_R(2.2250738585072014e-308);
#else
const real AL_TINY = AL_R(1.17549435e-38);
#endif

// One shading problem as the methods see it, built from the renderer's values by
// the light's library entry (library_<light>.glsl) in the working precision: p moved
// to the origin, lengths divided by the light's distance, and the frame rotated so
// that the light's centre lies on +z. Near the light, directions then differ from
// the pole in small components that hold their relative precision. n, v unit; r =
// 2 (n.v) n - v. verts = polygon vertices relative to the centre (AL_MAX_VERTS
// used). params =
// (exponent or alpha, two_sided, vertex count, Schlick f0: 1 gives F = 1).
// verts holds a polygon light's vertices (at most 8, CONTRACT.md 1) or a curved
// light's proxy polygon (light/spin_polygon.glsl), which may have more.
#if defined(AL_MAX_VERTS) && AL_MAX_VERTS > 8
#define AL_CASE_VERTS AL_MAX_VERTS
#else
#define AL_CASE_VERTS 8
#endif
struct AlCase {
    rvec4 n;
    rvec4 v;
    rvec4 r;
    rvec4 params;
    rvec4 center;
    rvec4 verts[AL_CASE_VERTS];
};

// Odd series 2 w (1 + w^2/3 + w^4/5 + ...) = log((1 + w) / (1 - w)) for |w| <= 0.172.
// Truncation: fp64 to w^21 (< 1e-18 relative), fp32 to w^11 (< 4e-10).
real al_log_ratio_series(real w) {
    real w2 = w * w;
#if AL_PRECISION_FP64
    real s = AL_R(1.0) / AL_R(21.0);
    s = s * w2 + AL_R(1.0) / AL_R(19.0);
    s = s * w2 + AL_R(1.0) / AL_R(17.0);
    s = s * w2 + AL_R(1.0) / AL_R(15.0);
    s = s * w2 + AL_R(1.0) / AL_R(13.0);
#else
    real s = AL_R(1.0) / AL_R(13.0);
#endif
    s = s * w2 + AL_R(1.0) / AL_R(11.0);
    s = s * w2 + AL_R(1.0) / AL_R(9.0);
    s = s * w2 + AL_R(1.0) / AL_R(7.0);
    s = s * w2 + AL_R(1.0) / AL_R(5.0);
    s = s * w2 + AL_R(1.0) / AL_R(3.0);
    s = s * w2 + real(1);
    return AL_R(2.0) * w * s;
}

// atan(t) for |t| <= 1: argument reduction by pi/6 to |t| <= tan(pi/12), then the
// odd Taylor series (truncation: fp64 to t^27, < 1e-18; fp32 to t^13, < 2e-10).
// Relative error a few ulp, also for tiny t. Drivers' fp32 atan (lavapipe: 2e-5
// relative) is not accurate enough, and GLSL has no fp64 atan.
real al_atan_unit(real t) {
    real a = abs(t), base = AL_R(0.0);
    const real sqrt3 = AL_R(1.73205080756887729353);
    if (a > AL_R(0.26794919243112270647)) {
        a = (a * sqrt3 - AL_R(1.0)) / (a + sqrt3);
        base = AL_R(0.52359877559829887308);
    }
    real z = -a * a;
#if AL_PRECISION_FP64
    real p = AL_R(1.0) / AL_R(27.0);
    p = p * z + AL_R(1.0) / AL_R(25.0);
    p = p * z + AL_R(1.0) / AL_R(23.0);
    p = p * z + AL_R(1.0) / AL_R(21.0);
    p = p * z + AL_R(1.0) / AL_R(19.0);
    p = p * z + AL_R(1.0) / AL_R(17.0);
    p = p * z + AL_R(1.0) / AL_R(15.0);
#else
    real p = AL_R(1.0) / AL_R(15.0);
#endif
    p = p * z + AL_R(1.0) / AL_R(13.0);
    p = p * z + AL_R(1.0) / AL_R(11.0);
    p = p * z + AL_R(1.0) / AL_R(9.0);
    p = p * z + AL_R(1.0) / AL_R(7.0);
    p = p * z + AL_R(1.0) / AL_R(5.0);
    p = p * z + AL_R(1.0) / AL_R(3.0);
    p = p * z + real(1);
    p *= a;
    return t < AL_R(0.0) ? -(base + p) : base + p;
}

// atan2(y, x) in (-pi, pi], 0 for (0, 0). Error a few ulp (al_atan_unit). One
// quotient and one series: SIMD drivers (lavapipe) would run both arms of a
// conditional call.
real al_atan2(real y, real x) {
    real ax = abs(x), ay = abs(y);
    if (ax == AL_R(0.0) && ay == AL_R(0.0)) return AL_R(0.0);
#ifdef AL_FAST_ARC
    // AL_FAST_ARC: atan on [0, 1] by one odd polynomial of degree 11 (no reduction),
    // |error| < 1.7e-6 rad (2.3e-5 relative near 0), checked in double on 2e5 points.
    real t = min(ax, ay) / max(ax, ay), z = t * t;
    real p = AL_R(-0.01172120);
    p = p * z + AL_R(0.05265332);
    p = p * z - AL_R(0.11643287);
    p = p * z + AL_R(0.19354346);
    p = p * z - AL_R(0.33262347);
    p = p * z + AL_R(0.99997726);
    real a = t * p;
#else
    real a = al_atan_unit(min(ax, ay) / max(ax, ay));
#endif
    real r = ay <= ax ? a : AL_HALF_PI - a;
    if (x < AL_R(0.0)) r = AL_PI - r;
    return y < AL_R(0.0) ? -r : r;
}

// Natural log for x > 0: frexp reduction to m in [sqrt(1/2), sqrt(2)), then
// log m = al_log_ratio_series((m - 1) / (m + 1)). Error a few ulp (lavapipe's fp32
// log: 7e-6 relative; GLSL has no fp64 log).
real al_log(real x) {
#ifdef AL_FAST_ARC
    // AL_FAST_ARC: the driver's log (lavapipe: 7e-6 relative).
    return log(x);
#endif
    AL_FREXP_EXPONENT e;  // frexp's exponent: int in GLSL and C++, float in HLSL
    real m = frexp(x, e);
    if (m < AL_R(0.70710678118654752440)) {
        m *= AL_R(2.0);
        e -= 1;
    }
    return real(e) * AL_R(0.69314718055994530942) +
           al_log_ratio_series((m - AL_R(1.0)) / (m + AL_R(1.0)));
}

// log(1 + z) for z in (-1, inf). Relative error ~1 ulp: for |z| < 1/4 the series in
// z / (2 + z) (|w| <= 1/7) avoids the cancellation of log(1 + z).
real al_log1p(real z) {
    if (abs(z) < AL_R(0.25)) return al_log_ratio_series(z / (AL_R(2.0) + z));
    return al_log(AL_R(1.0) + z);
}

// exp(x), 0 below -745. fp32: the driver's (measured adequate). fp64 (GLSL has
// none): x = k ln 2 + t, |t| <= ln2 / 2 with ln 2 split in two so t is exact to
// rounding, Taylor to t^13 (truncation < 4e-18 relative), then ldexp.
real al_exp(real x) {
#if AL_PRECISION_FP64
    if (x < AL_R(-745.0)) return AL_R(0.0);
    x = min(x, AL_R(709.0));
    real k = floor(x * AL_R(1.44269504088896340736) + AL_R(0.5));
    real t = (x - k * AL_R(0.693145751953125)) - k * AL_R(1.42860682030941723212e-6);
    real p = AL_R(1.0) / AL_R(6227020800.0);
    p = p * t + AL_R(1.0) / AL_R(479001600.0);
    p = p * t + AL_R(1.0) / AL_R(39916800.0);
    p = p * t + AL_R(1.0) / AL_R(3628800.0);
    p = p * t + AL_R(1.0) / AL_R(362880.0);
    p = p * t + AL_R(1.0) / AL_R(40320.0);
    p = p * t + AL_R(1.0) / AL_R(5040.0);
    p = p * t + AL_R(1.0) / AL_R(720.0);
    p = p * t + AL_R(1.0) / AL_R(120.0);
    p = p * t + AL_R(1.0) / AL_R(24.0);
    p = p * t + AL_R(1.0) / AL_R(6.0);
    p = p * t + AL_R(0.5);
    p = p * t + AL_R(1.0);
    p = p * t + AL_R(1.0);
    return ldexp(p, int(k));
#else
    return exp(x);
#endif
}

// Below |z| = AL_EXPM1_SERIES_BELOW, exp(z) - 1 is its Taylor series (al_expm1_of);
// beyond, exp(z) - 1 itself, which cannot cancel there. One threshold for both functions,
// so that al_expm1 takes its exp exactly where al_expm1_of would use it.
#ifdef AL_FAST_ARC
#define AL_EXPM1_SERIES_BELOW AL_R(0.1)
#else
#define AL_EXPM1_SERIES_BELOW AL_R(0.5)
#endif

// exp(z) - 1 for z <= 0 (used for 1 - x^k), given ez = exp(z) where a caller has it.
// Relative error a few ulp: Taylor for |z| < 1/2 (fp64 to z^16, < 1e-18; fp32 to z^8,
// < 1e-9), ez - 1 beyond, where it cannot cancel.
real al_expm1_of(real z, real ez) {
#ifdef AL_FAST_ARC
    // AL_FAST_ARC: Taylor to z^5 below |z| = 0.1 (truncation < 1.4e-8 relative), exp(z) - 1
    // beyond (rounding < 6.3e-7 relative): four FMAs fewer on each of a peak fit's paths.
    if (abs(z) < AL_EXPM1_SERIES_BELOW)
        return z * (AL_R(1.0) + z * (AL_R(0.5) + z * (AL_R(1.0) / AL_R(6.0) +
                    z * (AL_R(1.0) / AL_R(24.0) + z * (AL_R(1.0) / AL_R(120.0))))));
    return ez - AL_R(1.0);
#endif
    if (abs(z) < AL_EXPM1_SERIES_BELOW) {
#if AL_PRECISION_FP64
        real p = AL_R(1.0) / AL_R(20922789888000.0);
        p = p * z + AL_R(1.0) / AL_R(1307674368000.0);
        p = p * z + AL_R(1.0) / AL_R(87178291200.0);
        p = p * z + AL_R(1.0) / AL_R(6227020800.0);
        p = p * z + AL_R(1.0) / AL_R(479001600.0);
        p = p * z + AL_R(1.0) / AL_R(39916800.0);
        p = p * z + AL_R(1.0) / AL_R(3628800.0);
        p = p * z + AL_R(1.0) / AL_R(362880.0);
#else
        real p = AL_R(1.0) / AL_R(362880.0);
#endif
        p = p * z + AL_R(1.0) / AL_R(40320.0);
        p = p * z + AL_R(1.0) / AL_R(5040.0);
        p = p * z + AL_R(1.0) / AL_R(720.0);
        p = p * z + AL_R(1.0) / AL_R(120.0);
        p = p * z + AL_R(1.0) / AL_R(24.0);
        p = p * z + AL_R(1.0) / AL_R(6.0);
        p = p * z + AL_R(0.5);
        p = p * z + AL_R(1.0);
        return p * z;
    }
    return ez - AL_R(1.0);
}

// exp(z) - 1 for z <= 0 (al_expm1_of), the exp only where the series does not serve.
real al_expm1(real z) {
    if (abs(z) < AL_EXPM1_SERIES_BELOW) return al_expm1_of(z, AL_R(1.0));
    return al_exp(z) - AL_R(1.0);
}

// (sin x, cos x) for |x| <= pi. fp32: the driver's. fp64 (GLSL has none): x = q pi/2
// + t with |t| <= pi/4 (pi/2 split in two), Taylor to t^17 / t^18 (truncation
// < 1e-19), quadrant by q.
rvec2 al_sincos(real x) {
#if AL_PRECISION_FP64
    real q = floor(x * AL_R(0.63661977236758134308) + AL_R(0.5));
    real t = (x - q * AL_R(1.57079632673412561417)) - q * AL_R(6.07710050650619224932e-11);
    real z = t * t;
    real s = -AL_R(1.0) / AL_R(355687428096000.0);
    s = s * z + AL_R(1.0) / AL_R(1307674368000.0);
    s = s * z - AL_R(1.0) / AL_R(6227020800.0);
    s = s * z + AL_R(1.0) / AL_R(39916800.0);
    s = s * z - AL_R(1.0) / AL_R(362880.0);
    s = s * z + AL_R(1.0) / AL_R(5040.0);
    s = s * z - AL_R(1.0) / AL_R(120.0);
    s = s * z + AL_R(1.0) / AL_R(6.0);
    s = t - t * z * s;
    real c = AL_R(1.0) / AL_R(6402373705728000.0);
    c = c * z - AL_R(1.0) / AL_R(20922789888000.0);
    c = c * z + AL_R(1.0) / AL_R(87178291200.0);
    c = c * z - AL_R(1.0) / AL_R(479001600.0);
    c = c * z + AL_R(1.0) / AL_R(3628800.0);
    c = c * z - AL_R(1.0) / AL_R(40320.0);
    c = c * z + AL_R(1.0) / AL_R(720.0);
    c = c * z - AL_R(1.0) / AL_R(24.0);
    c = c * z + AL_R(0.5);
    c = AL_R(1.0) - z * c;
    int quadrant = int(q) & 3;
    if (quadrant == 0) return rvec2(s, c);
    if (quadrant == 1) return rvec2(c, -s);
    if (quadrant == 2) return rvec2(-s, -c);
    return rvec2(-c, s);
#else
    return rvec2(sin(x), cos(x));
#endif
}

// Orthonormal e1, e2 with (e1, e2, z) right-handed, for unit z (Duff et al. 2017,
// "Building an orthonormal basis, revisited": branch-free, exact to rounding).
void al_tangent_frame(rvec3 z, AL_INOUT(rvec3) e1, AL_INOUT(rvec3) e2) {
    real sgn = z.z >= AL_R(0.0) ? AL_R(1.0) : AL_R(-1.0);
    real a = AL_R(-1.0) / (sgn + z.z);
    real b = z.x * z.y * a;
    e1 = rvec3(AL_R(1.0) + sgn * z.x * z.x * a, sgn * b, -sgn * z.x);
    e2 = rvec3(b, sgn + z.y * z.y * a, -z.y);
}

// Replaces NaN, infinities and negatives by 0: no bad value leaves a shader
// (CONTRACT.md 2 asks for finite values >= 0 everywhere). Results are fp32 at any
// precision: a value beyond the fp32 range is thus caught here too.
float al_clean(float x) { return (x >= 0.0f && x <= 3.0e38f) ? x : 0.0f; }
vec4 al_clean(vec4 x) { return vec4(al_clean(x.x), al_clean(x.y), al_clean(x.z), al_clean(x.w)); }
