// Peak-function edge integrals for Phong (Lecocq et al. 2016 sections 5-6): every edge
// integral of the boundary form (method/exact_phong.glsl) is an integral over an
// arc [tau_a, tau_b] of an even function g(tau), unimodal on [-pi/2, pi/2], with
// g(0) = g_max and g(pi/2) = g_min in closed form. It is replaced by a peak
// function P fitted through those two values and one more exact sample g(tau_w)
// (Lecocq et al. 2016 eq. 8-9): g ~ g_min + (g_max - g_min) Q, Q = (P - P(pi/2)) / (1 - P(pi/2)).
// O(1) per edge whatever N is.
//
// Departures from the paper, and why:
// - Real N without parity. Lecocq et al. 2016 eq. 2-5 pick f = 1 or x by the parity of n and
//   add z_n Omega; here f = 1 always and the driver adds the azimuth swept about r,
//   whose signed total is exactly 2 pi [r in D] for any real N (the near form
//   below). So eq. 6 reads I = (1 - x^(N+1)) / (1 - x^2), I_min = 1 and
//   I_max = (1 - c^(N+1)) / s^2, formed as -expm1((N+1) log c) / s^2 (no 0/0 as c -> 1).
// - Far edges (method/phong_edge.glsl) fit x^(N+1) / (1 - x^2) instead (min 0, max c^k/s^2):
//   there the near form's result is a small difference of O(1) terms, and a fit
//   error of 1e-3 in I became an error of order 1 in the moment. An edge counts as
//   near only where x^(N+1) reaches 0.1 on it (AL_PEAK_LOG_FAR; the exact method
//   uses 1e-3): measured on the public typical set, moment p95 9.6e-2 at 1e-3,
//   4.3e-2 at 1e-2, 2.2e-2 at 0.1, 1.0e-1 at 0.5.
// - An arc beside the foot lies in g's tail, where a fitted peak decays like a power
//   of tau but x^k like a Gaussian (a far fit was 1e20 times too large there): such
//   arcs take the smaller of the fit and an exponential tail bound (al_tail_bound).
// - The fit point is not the paper's empirical half width (eq. 7) but an estimate
//   of the half-maximum point from the two widths that shape g, the azimuth core s
//   and the lobe ~ (2 / k)^(1/2): tan^2 tau_w = s^2 + 2/k (near form),
//   2 ln2 / (k + 2 / s^2) (far form), and for x^N the exact half width
//   cos^2 tau_w = 2^(-2/N). g(tau_w) itself is exact, so the fit always passes
//   through it (as the paper's does).
// - The ellipse's parameter (eq. 18) is solved in closed form from that sample:
//   a = y (1 - C) / (C (1 - y)), C = cos^2 tau_w, y the sample's relative height.
//
// Peak functions (Q normalized to 1 at the peak and 0 at tau = pi/2):
// - lorentz: P = 1 / (1 + a tau^2) (eq. 11), integral in the single-atan form of
//   eq. 12, written as atan2 so the mod pi is exact.
// - pearson: a blend alpha Q_L + (1 - alpha) Q_P of that Lorentzian and the Pearson
//   VII P = 1 / (1 + b tau^2)^2 (eq. 13), integral tau / (2 (1 + b tau^2)) +
//   atan(sqrt(b) tau) / (2 sqrt(b)), alpha from one more exact sample in the tail
//   and clamped to [0, 1] (as printed it is unbounded: it reached -496).
// - ellipsoid: P = a / (1 + (a - 1) cos^2 tau) (eq. 15), integral
//   sqrt(a) atan(tan(tau) / sqrt(a)) (eq. 16); it contains the azimuth core
//   1 / (1 - x^2) exactly (a = s^2). fit=paper blends it with the squared ellipse,
//   whose integral is (sqrt(b) (b+1) / 2) atan(tan(tau) / sqrt(b))
//   - (b (b-1) / 4) sin(2 tau) / (sin^2 tau + b cos^2 tau) (eq. 17 prints that
//   denominator as "2c"; differentiating checks it).
// fit=tuned (default): the fit points above; pearson solves b through the fit
// point by one fixed-point step of P_P(tau_w) = P_min(b) + y (1 - P_min(b)) from
// b = (y^(-1/2) - 1) / tau_w^2 (b = a/2 as printed missed the sample), tail sample
// at tan(tau_t) = 2 tan(tau_w); the ellipsoid blends the ellipse with the squared
// ellipse through the fit point (P_E(tau_w) = p gives b = p t / (1 + t - p),
// t = tan^2 tau_w; one fixed-point step for P_E^2 = b^2 + y (1 - b^2)) at the same
// tail point. Measured on the public typical set, moment relL2 (floor 1e-2): single
// ellipse 5.7e-3, blend 3.0e-3.
// fit=paper: Lecocq et al. 2016 as printed but for its errors: near form on every edge, no
// tail bound, half width from eq. 7 with the parity labels swapped (our f = 1
// integrand (1 - x^k) / (1 - x^2) is the printed "even" case with n = k - 2, which
// matches the true half width to ~0.01 rad), b = a/2 (pearson),
// b = a (2.1 + 1.28 x_w / x_w(0)) (ellipsoid), tail point eq. 14, alpha clamped.
// Measured error: see docs/methods.md (arealight report). GPU cost (navi21, `arealight
// gpu-cost`, the validation kernel, polygon, against the point light's 457; with
// AL_FAST_ARC, common/common.glsl; 2026-12-06, with method/peak_lobe_edge.glsl's closed-form z
// and 6-node low-N rule, and one fit for both exponents, al_peak_edge_terms): lorentz 6 295
// (13.8x), fit=paper 5 089 (11.1x); pearson 6 785 (14.8x), fit=paper 6 937 (15.2x); ellipsoid
// 6 800 (14.9x), fit=paper 7 236 (15.8x): one edge loop, counted by ACO as 8 iterations of
// ~800 cycles. 2026-12-08, with the rule on the edges between the lobe's core and its tail
// (method/peak_lobe_edge.glsl): lorentz 6 380 (14.0x), pearson 6 869 (15.0x), ellipsoid
// 6 884 (15.1x).

#define AL_PEAK_LOG_FAR AL_R(-2.3)
// Integral over the arc of the ellipse's Q = a cos^2 / (sin^2 + a cos^2) =
// (P_E - a) / (1 - a): (sqrt(a) Psi - a dtau) / (1 - a), Psi = atan(tan(tau)/sqrt(a))
// across the arc; or (squared) of the squared ellipse's Q = (P_E^2 - a^2) / (1 - a^2)
// (fit=paper ellipsoid and the tuned blend). Both cancel as a -> 1 and both tend to
// cos^2 there: within 0.05 of 1, interpolate linearly between the exact a = 1 value
// dtau/2 + (sin 2tau_b - sin 2tau_a)/4 and a = 1 -+ 0.05 (interpolation error ~1e-4
// of the integral, rounding amplified at most 20x).
// Psi is one atan2 of the ends' cross and dot products in the (sqrt(a) f, g) plane (both
// ends lie within pi/2 of the foot, f >= 0, so the difference is in (-pi, pi)), and the
// squared ellipse's two quotients share one denominator, whose numerator factors as
// (ag bf - af bg)(ag bg - a af bf): one quotient and one atan2 fewer than the textbook form
// (ggx ellipsoid 26 869 -> 26 049 cycles a wave, navi21). Computing the ends' products once
// per arc instead (they do not depend on a, and GGX fits in a loop over three lobes) took
// ggx ellipsoid to 24 825 but blinn's curved ellipsoids from 168 to 176 VGPRs, 3 to 2 waves
// in ACO's model (disk 22 029 -> 28 569 cycles a wave): written as here, each call forms
// them afresh and none lives across the fit.
real al_ellipse_q_at(real ag, real af, real bg, real bf, real dtau, real a, bool squared) {
    real sa = sqrt(a);
    real cross = bg * af - ag * bf;
    real psi = al_atan2(sa * cross, a * af * bf + ag * bg);
    if (!squared) return (sa * psi - a * dtau) / (AL_R(1.0) - a);
    real da = ag * ag + a * af * af, db = bg * bg + a * bf * bf;
    real rat = -AL_R(2.0) * cross * (ag * bg - a * af * bf) / (da * db);
    real integral_p = AL_R(0.5) * sa * (a + AL_R(1.0)) * psi - AL_R(0.25) * a * (a - AL_R(1.0)) * rat;
    return (integral_p - a * a * dtau) / (AL_R(1.0) - a * a);
}
// One call of al_ellipse_q_at, at a or at the interpolation's far end: with a call in each
// branch, each inlined copy of it held its own registers (ggx ellipsoid 184 VGPRs, 2 waves
// on navi21 and latency-bound; one copy: 168, 3 waves, 45 855 -> 30 888 cycles a wave).
real al_ellipse_q_integral(real ag, real af, real bg, real bf, real dtau, real a, bool squared) {
    bool near_one = abs(AL_R(1.0) - a) < AL_R(0.05);
    real a0 = !near_one ? a : (a < AL_R(1.0) ? AL_R(0.95) : AL_R(1.05));
    real q0 = al_ellipse_q_at(ag, af, bg, bf, dtau, a0, squared);
    if (!near_one) return q0;
    real q1 = AL_R(0.5) * (dtau + bg * bf - ag * af);  // (g, f) of unit ends: sin 2tau = 2 g f
    return q1 + (a - AL_R(1.0)) / (a0 - AL_R(1.0)) * (q0 - q1);
}

// A fit of g over an arc: its closed-form max and min, and exact samples at the
// fit point tau_w and (blends only) the tail point tau_t, as tan^2 and value.
struct AlPeakFit {
    real gmax, gmin;
    real tw2, gw;
    real tt2, gt;
};

// Half width at half maximum from Lecocq et al. 2016 eq. 7, "even" branch (see the header),
// for the near-form exponent k; x_w(0) = pi/4.
real al_paper_half_width(real c, real k) {
    real base = max(c - c / max(k - AL_R(3.0), AL_R(1.0)), AL_R(0.0));
    return AL_R(0.78539816339744830962) *
           al_exp(AL_R(0.45) * al_log1p(-al_exp(AL_R(2.5) * al_log(max(base, AL_R(1e-30))))));
}
// Lecocq et al. 2016 eq. 14: the tail point from the half width, below pi/2.
real al_paper_tail(real xw) {
    const real xw0 = AL_R(0.78539816339744830962);
    real u = AL_R(1.0) - xw / xw0;
    real u2 = u * u, u4 = u2 * u2;
    real xt = xw + AL_R(0.3946) * xw0 * (AL_R(1.0) - u4 * u4 * u4);
    return min(xt, AL_R(1.5607963267948966));
}

// Lorentzian and Pearson VII, Q at angle t and the arc integral of Q (ta to
// ta + dtau), for shape a (Lorentz, power 1) or b (Pearson, power 2).
real al_lorentz_q(real a, real t) {
    const real quarter_pi2 = AL_R(2.46740110027233965471);  // (pi/2)^2
    real p_min = AL_R(1.0) / (AL_R(1.0) + a * quarter_pi2);
    return (AL_R(1.0) / (AL_R(1.0) + a * t * t) - p_min) / (AL_R(1.0) - p_min);
}
real al_lorentz_q_integral(real a, real ta, real dtau) {
    const real quarter_pi2 = AL_R(2.46740110027233965471);
    real sa = sqrt(a), tb = ta + dtau;
    real integral_p = al_atan2(sa * dtau, AL_R(1.0) + a * ta * tb) / sa;
    real p_min = AL_R(1.0) / (AL_R(1.0) + a * quarter_pi2);
    return (integral_p - p_min * dtau) / (AL_R(1.0) - p_min);
}
real al_pearson_q(real b, real t) {
    const real quarter_pi2 = AL_R(2.46740110027233965471);
    real m = AL_R(1.0) / (AL_R(1.0) + b * quarter_pi2);
    real p = AL_R(1.0) / (AL_R(1.0) + b * t * t);
    return (p * p - m * m) / (AL_R(1.0) - m * m);
}
real al_pearson_q_integral(real b, real ta, real dtau) {
    const real quarter_pi2 = AL_R(2.46740110027233965471);
    real sb = sqrt(b), tb = ta + dtau;
    real integral_p = AL_R(0.5) * (tb / (AL_R(1.0) + b * tb * tb) - ta / (AL_R(1.0) + b * ta * ta)) +
                      AL_R(0.5) * al_atan2(sb * dtau, AL_R(1.0) + b * ta * tb) / sb;
    real m = AL_R(1.0) / (AL_R(1.0) + b * quarter_pi2);
    return (integral_p - m * m * dtau) / (AL_R(1.0) - m * m);
}

// The blend weight of eq. 13 from the tail sample: Q_mix(tau_t) = y_t, clamped.
real al_blend_alpha(real q_wide, real q_narrow, real yt) {
    real den = q_narrow - q_wide;
    if (!(abs(den) > AL_R(1e-12))) return AL_R(1.0);
    return clamp((q_narrow - yt) / den, AL_R(0.0), AL_R(1.0));
}

// Integral over the arc of the fit's shape Q alone, in [0, dtau] (F not flat: al_peak_flat).
real al_peak_q_integral(real ag, real af, real bg, real bf, real ta, real dtau, AlPeakFit F) {
    real span = F.gmax - F.gmin;
    real y = clamp((F.gw - F.gmin) / span, AL_R(1e-6), AL_R(0.999999));
#if defined(AL_METHOD_LORENTZ) || defined(AL_METHOD_PEARSON)
    // Q_L(tau_w) = y solved for a (Lecocq et al. 2016, after eq. 11), tau_w the angle. A g
    // flatter than the Lorentzian family allows gives a <= 0; the floor bounds the
    // cancellation in (integral P - P_min dtau) / (1 - P_min) to a factor ~8.
    real tw = al_atan2(sqrt(F.tw2), AL_R(1.0));
    const real quarter_pi2 = AL_R(2.46740110027233965471);  // (pi/2)^2
    real a = max((AL_R(1.0) - tw * tw / quarter_pi2 - y) / (y * tw * tw), AL_R(0.05));
    real integral_q = al_lorentz_q_integral(a, ta, dtau);
#ifdef AL_METHOD_PEARSON
#ifdef AL_FIT_PAPER
    real b = AL_R(0.5) * a;
#else
    // P_P(tau_w) = P_min(b) + y (1 - P_min(b)) by one fixed-point step from P_min = 0 (a
    // second moved the public sets' relL2 by <= 1.5%, and cost ggx pearson 1%, navi21).
    real b = max((AL_R(1.0) / sqrt(y) - AL_R(1.0)) / (tw * tw), AL_R(0.05));
    real m = AL_R(1.0) / (AL_R(1.0) + b * quarter_pi2);
    real target = m * m + y * (AL_R(1.0) - m * m);
    b = max((AL_R(1.0) / sqrt(target) - AL_R(1.0)) / (tw * tw), AL_R(0.05));
#endif
    real tt = al_atan2(sqrt(F.tt2), AL_R(1.0));
    real yt = (F.gt - F.gmin) / span;
    real alpha = al_blend_alpha(al_lorentz_q(a, tt), al_pearson_q(b, tt), yt);
    integral_q = alpha * integral_q + (AL_R(1.0) - alpha) * al_pearson_q_integral(b, ta, dtau);
#endif
#else
    // Q = a cos^2 / (sin^2 + a cos^2) for any a > 0 (a > 1: g rises away from 0);
    // Q(tau_w) = y gives a in closed form (eq. 18).
    real a = clamp(y * F.tw2 / (AL_R(1.0) - y), AL_R(1e-12), AL_R(1e6));
    real integral_q = al_ellipse_q_integral(ag, af, bg, bf, dtau, a, false);
#ifdef AL_FIT_PAPER
    // Squared ellipse with b = a (2.1 + 1.28 x_w / x_w(0)), blended at the tail point.
    real xw = al_atan2(sqrt(F.tw2), AL_R(1.0));
    real b = clamp(a * (AL_R(2.1) + AL_R(1.62974661726101) * xw), AL_R(1e-12), AL_R(1e6));
#else
    // Squared ellipse through the fit point: P_E(tau_w) = p solves
    // b = p t / (1 + t - p), t = tan^2 tau_w, and P_E^2 = b^2 + y (1 - b^2) fixes p;
    // one fixed-point step from b^2 = 0 (as pearson's). y <= 1 - 1e-6 keeps p <= 1 - 5e-7 and
    // so b < 1 and 1 + t - p > 0: no guard on the quotient, and only b's floor (t = 0 gives
    // b = 0).
    real p = sqrt(y);
    real b = max(p * F.tw2 / (AL_R(1.0) + F.tw2 - p), AL_R(1e-12));
    p = sqrt(y + (AL_R(1.0) - y) * b * b);
    b = max(p * F.tw2 / (AL_R(1.0) + F.tw2 - p), AL_R(1e-12));
#endif
    real yt = (F.gt - F.gmin) / span;
    real qe = a / (F.tt2 + a);
    // (pe2^2 - b^2) / (1 - b^2) with the factor 1 - b cancelled: no 0/0 at b = 1.
    real qe2 = b * b * (AL_R(1.0) + AL_R(2.0) * F.tt2 + b) /
               ((F.tt2 + b) * (F.tt2 + b) * (AL_R(1.0) + b));
    real alpha = al_blend_alpha(qe, qe2, yt);
    integral_q = alpha * integral_q +
                 (AL_R(1.0) - alpha) * al_ellipse_q_integral(ag, af, bg, bf, dtau, b, true);
#endif
    // Q lies in [0, 1], so its integral in [0, dtau]: rounding of the closed forms
    // on short arcs must not push the fit below g_min or above g_max.
    return clamp(integral_q, AL_R(0.0), dtau);
}

// Whether g is flat on the arc to working precision (its max and min within 1e-7).
bool al_peak_flat(real gmax, real gmin) {
    return !(abs(gmax - gmin) > AL_R(1e-7) * max(abs(gmax), abs(gmin)));
}

// Integral over [tau_a, tau_b] (tau = atan(g, f) of each end, ta = tau_a, dtau = tau_b -
// tau_a >= 0) of the fit of g through F. Finite for any input; a flat g integrates as
// g_min dtau.
real al_peak_integral(real ag, real af, real bg, real bf, real ta, real dtau, AlPeakFit F) {
    if (al_peak_flat(F.gmax, F.gmin)) return F.gmin * dtau;
    return F.gmin * dtau + (F.gmax - F.gmin) * al_peak_q_integral(ag, af, bg, bf, ta, dtau, F);
}

// Upper bound of the integral over an arc that lies on one side of the foot, for a g
// with log-concave decay away from it: g(tau_1) (1 - exp(-lambda dtau)) / lambda,
// tau_1 the end nearer the foot and lambda = -d log g / dtau there (the tangent of
// log g lies above it). x^k is log-concave; the 1 / (1 - x^2) factor of the far form
// is not beyond |tau| ~ s, so there the bound is an estimate. A single fit's tail decays like a power of tau while x^k
// decays like a Gaussian: far out in the tail the fit was 1e20 times too large.
real al_tail_bound(real g1, real lambda, real dtau) {
    if (!(lambda * dtau > AL_R(1e-6))) return g1 * dtau;
    return g1 * -al_expm1(-lambda * dtau) / lambda;
}

// The end of the arc nearer the foot, when the foot lies outside the arc: tan(tau_1)
// (from the ends' components; af, bf > 0) and x there. Returns false when the arc
// holds the foot.
bool al_arc_near_end(AlEdgeFrame E, AL_INOUT(real) tan1, AL_INOUT(real) x1) {
    if (E.ag <= AL_R(0.0) && E.bg >= AL_R(0.0)) return false;
    bool a_nearer = E.ag > AL_R(0.0);
    tan1 = abs(a_nearer ? E.ag / E.af : E.bg / E.bf);
    x1 = a_nearer ? E.xa : E.xb;
    return true;
}

// What the fits of one arc share whatever their exponent k, computed once per arc: the
// microfacet methods fit each lobe's exponent in a loop nested in the polygon's edge loop
// (method/peak_microfacet.glsl), out of which the GPU compilers do not hoist it, and
// which ACO's cost model counts 64 times per trip of the edge loop (ggx pearson 30 325 ->
// 28 986 cycles a wave, navi21; Phong's two exponents, lorentz 8 374 -> 8 014).
struct AlArcShared {
    real s2, lc;   // s^2 and log c
    real ta, dtau; // tau_a and tau_b - tau_a >= 0
    bool beside;   // the foot lies outside the arc (al_arc_near_end); then, at the nearer end:
    real tan1;     // tan(tau_1)
    real x1, lx1;  // x and log x
    real inv_omx2; // 1 / (1 - x^2), 1 - x^2 = s^2 + c^2 sin^2(tau_1)
    real lambda0;  // 2 x^2 tan(tau_1) / (1 - x^2) (al_peak_edge_term's tail)
};
AlArcShared al_arc_shared(AlEdgeFrame E) {
    AlArcShared S;
    S.s2 = min(E.s * E.s, AL_R(1.0));
    S.lc = al_arc_log_c(E);
    S.ta = al_atan2(E.ag, E.af);
    S.dtau = max(al_atan2(E.bg, E.bf) - S.ta, AL_R(0.0));
    S.tan1 = AL_R(0.0);
    S.x1 = AL_R(0.0);
    S.beside = al_arc_near_end(E, S.tan1, S.x1);
    real sin2 = S.tan1 * S.tan1 / (AL_R(1.0) + S.tan1 * S.tan1);
    S.inv_omx2 = AL_R(1.0) / (S.s2 + (AL_R(1.0) - S.s2) * sin2);
    S.lambda0 = AL_R(2.0) * S.x1 * S.x1 * S.tan1 * S.inv_omx2;
    // Beside the foot the nearer end holds x's maximum on the arc: log x1 is the far test's
    // al_arc_log_x_max, which the compiler then forms once for both.
    S.lx1 = al_arc_log_x_max(E);
    return S;
}

// The integrand at tan^2(tau) = t2 for exponent k: the near form (1 - x^k) / (1 - x^2), or
// the far form x^k / (1 - x^2), with log x = log c - log1p(t2) / 2 and 1 / (1 - x^2) =
// (1 + t2) / (s^2 + t2) (no cancellation).
real al_peak_sample(AlArcShared S, real k, real t2, bool far_edge) {
    real lx = S.lc - AL_R(0.5) * al_log1p(t2);
    return (far_edge ? al_exp(k * lx) : -al_expm1(k * lx)) * ((AL_R(1.0) + t2) / (S.s2 + t2));
}

// The integrand's maximum and minimum on its great circle for exponent k: (c^k / s^2, 0) far,
// ((1 - c^k) / s^2, 1) near (-> k / 2 as s -> 0).
rvec2 al_peak_extremes(AlArcShared S, real k, bool far_edge) {
    real ck = al_exp(k * S.lc);
    rvec2 e;
    if (far_edge) {
        e.x = S.s2 > AL_R(0.0) ? ck / S.s2 : AL_R(0.0);
        e.y = AL_R(0.0);
    } else {
        e.x = S.s2 > AL_R(1e-30) ? -al_expm1_of(k * S.lc, ck) / S.s2 : AL_R(0.5) * k;
        e.y = AL_R(1.0);
    }
    return e;
}

// A far arc beside the foot: the smaller of the fit and al_tail_bound.
real al_peak_tail_min(real fit, AlArcShared S, real k, bool far_edge) {
    if (!far_edge || !S.beside) return fit;
    // g = x^k / (1 - x^2); -d log g = k tan + 2 x^2 tan / (1 - x^2).
    real g1 = al_exp(k * S.lx1) * S.inv_omx2;
    real lambda = k * S.tan1 + S.lambda0;
    return min(fit, al_tail_bound(g1, max(lambda, AL_R(0.0)), S.dtau));
}

// The fit of exponent k: its samples at the fit point tau_w and the tail point tau_t
// (fit=tuned: the estimate of the half-maximum point in the header and twice its tangent;
// fit=paper: eq. 7 and eq. 14) and the integrand's extremes.
AlPeakFit al_peak_fit(AlEdgeFrame E, AlArcShared S, real k, bool far_edge) {
    AlPeakFit F;
#ifdef AL_FIT_PAPER
    real xw = al_paper_half_width(E.c, k);
    real txw = tan(xw), txt = tan(al_paper_tail(xw));
    F.tw2 = txw * txw;
    F.tt2 = txt * txt;
#else
    F.tw2 = far_edge ? AL_R(1.38629436111989061883) * S.s2 / (k * S.s2 + AL_R(2.0))
                     : S.s2 + AL_R(2.0) / k;
    F.tt2 = AL_R(4.0) * F.tw2;
#endif
    F.gw = al_peak_sample(S, k, F.tw2, far_edge);
    F.gt = al_peak_sample(S, k, F.tt2, far_edge);
    rvec2 ext = al_peak_extremes(S, k, far_edge);
    F.gmax = ext.x;
    F.gmin = ext.y;
    return F;
}

// Fitted integral of the near-form integrand (1 - x^k) / (1 - x^2) (far = false)
// or of x^k / (1 - x^2) (far = true) over the arc of E (S: al_arc_shared of it). One call of
// the fit for both forms (a call in each branch was two inlined copies of it, with their own
// registers).
real al_peak_edge_term(AlEdgeFrame E, AlArcShared S, real k, bool far_edge) {
    AlPeakFit F = al_peak_fit(E, S, k, far_edge);
    real fit = al_peak_integral(E.ag, E.af, E.bg, E.bf, S.ta, S.dtau, F);
    return al_peak_tail_min(fit, S, k, far_edge);
}

// Phong's two terms (exponents N + 1 and N) from one fit, N's: the shape Q fitted to
// exponent N, between each exponent's own maximum and minimum (their shapes' widths differ by
// ~1 / (2N) relative). x = t_(N+1), y = t_N. Against a fit per exponent (public sets, CPU
// mirror): specular unchanged to 3 digits (t_N is N's own fit), moment relL2 typical 2.56e-3
// -> 2.49e-3, horizon 4.96e-4 -> 5.32e-4, degenerate 3.82e-3 -> 3.41e-3 (pearson); lorentz
// horizon 1.04e-3 -> 1.14e-3. The shape at N + 1/2 for both moved specular by +7% (typical).
// GPU cost: pearson 7 440 -> 6 785 cycles a wave (navi21).
rvec2 al_peak_edge_terms(AlEdgeFrame E, AlArcShared S, real N, bool far_edge) {
    AlPeakFit F = al_peak_fit(E, S, N, far_edge);
    real q = al_peak_flat(F.gmax, F.gmin)
                 ? AL_R(0.0)
                 : al_peak_q_integral(E.ag, E.af, E.bg, E.bf, S.ta, S.dtau, F);
    real k1 = N + AL_R(1.0);
    rvec2 e1 = al_peak_extremes(S, k1, far_edge);
    real fit1 = e1.y * S.dtau + (al_peak_flat(e1.x, e1.y) ? AL_R(0.0) : (e1.x - e1.y) * q);
    real fit0 =
        F.gmin * S.dtau + (al_peak_flat(F.gmax, F.gmin) ? AL_R(0.0) : (F.gmax - F.gmin) * q);
    return rvec2(al_peak_tail_min(fit1, S, k1, far_edge), al_peak_tail_min(fit0, S, N, far_edge));
}

