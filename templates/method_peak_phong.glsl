// Peak-function edge integrals for Phong (seed 000 sections 5-6): every edge
// integral of the boundary form (method_exact_phong.glsl) is an integral over an
// arc [tau_a, tau_b] of an even function g(tau), unimodal on [-pi/2, pi/2], with
// g(0) = g_max and g(pi/2) = g_min in closed form. It is replaced by a peak
// function P fitted through those two values and one more exact sample g(tau_w)
// (seed 000 eq. 8-9): g ~ g_min + (g_max - g_min) Q, Q = (P - P(pi/2)) / (1 - P(pi/2)).
// O(1) per edge whatever N is.
//
// Departures from the paper, and why:
// - Real N without parity. Seed 000 eq. 2-5 pick f = 1 or x by the parity of n and
//   add z_n Omega; here f = 1 always and the driver adds the azimuth swept about r,
//   whose signed total is exactly 2 pi [r in D] for any real N (the near form
//   below). So eq. 6 reads I = (1 - x^(N+1)) / (1 - x^2), I_min = 1 and
//   I_max = (1 - c^(N+1)) / s^2, formed as -expm1((N+1) log c) / s^2 (no 0/0 as c -> 1).
// - Far edges (phong_edge.glsl) fit x^(N+1) / (1 - x^2) instead (min 0, max c^k/s^2):
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
// Peak functions: AL_METHOD_LORENTZ: P = 1 / (1 + a tau^2) (eq. 11), its integral
// in the single-atan form of eq. 12, written as atan2 so the mod pi is exact.
// AL_METHOD_ELLIPSOID: P = a / (1 + (a - 1) cos^2 tau) (eq. 15), integral
// sqrt(a) atan(tan(tau) / sqrt(a)) (eq. 16); it contains the azimuth core
// 1 / (1 - x^2) exactly (a = s^2).
// Measured error: see README (arealight eval + shared/tools/score).

#define AL_PEAK_LOG_FAR AL_R(-2.3)
// Integral over the arc of Q = a cos^2 / (sin^2 + a cos^2) = (P_E - a) / (1 - a):
// (sqrt(a) Psi - a dtau) / (1 - a), Psi = atan(tan(tau)/sqrt(a)) across the arc. That
// cancels as a -> 1 (Q -> cos^2): within 0.05 of 1, interpolate linearly between
// the exact a = 1 value dtau/2 + (sin 2tau_b - sin 2tau_a)/4 and a = 1 -+ 0.05
// (interpolation error ~1e-4 of the integral, rounding amplified at most 20x).
real al_ellipse_q_at(real ag, real af, real bg, real bf, real dtau, real a) {
    real sa = sqrt(a);
    real psi = al_atan2(bg, sa * bf) - al_atan2(ag, sa * af);
    return (sa * psi - a * dtau) / (AL_R(1.0) - a);
}
real al_ellipse_q_integral(real ag, real af, real bg, real bf, real dtau, real a) {
    if (abs(AL_R(1.0) - a) >= AL_R(0.05)) return al_ellipse_q_at(ag, af, bg, bf, dtau, a);
    real q1 = AL_R(0.5) * dtau +
              AL_R(0.5) * (bg * bf / (bg * bg + bf * bf) - ag * af / (ag * ag + af * af));
    real a0 = a < AL_R(1.0) ? AL_R(0.95) : AL_R(1.05);
    real q0 = al_ellipse_q_at(ag, af, bg, bf, dtau, a0);
    return q1 + (a - AL_R(1.0)) / (a0 - AL_R(1.0)) * (q0 - q1);
}

// Integral over [tau_a, tau_b] (tau = atan(g, f) of each end, dtau = tau_b - tau_a
// >= 0) of the fit of g through g_max, g_min and g(tau_w) = gw, with
// tw2 = tan^2 tau_w. Finite for any input; a flat g integrates as g_min dtau.
real al_peak_integral(real ag, real af, real bg, real bf, real dtau, real gmax, real gmin,
                      real tw2, real gw) {
    real span = gmax - gmin;
    if (!(abs(span) > AL_R(1e-7) * max(abs(gmax), abs(gmin)))) return gmin * dtau;
    real y = clamp((gw - gmin) / span, AL_R(1e-6), AL_R(0.999999));
#ifdef AL_METHOD_LORENTZ
    // Q(tau_w) = y solved for a (seed 000, after eq. 11), with tau_w the angle. A g
    // flatter than the Lorentzian family allows gives a <= 0; the floor bounds the
    // cancellation in (integral P - P_min dtau) / (1 - P_min) to a factor ~8.
    real tw = al_atan2(sqrt(tw2), AL_R(1.0));
    const real quarter_pi2 = AL_R(2.46740110027233965471);  // (pi/2)^2
    real a = max((AL_R(1.0) - tw * tw / quarter_pi2 - y) / (y * tw * tw), AL_R(0.05));
    real ta = al_atan2(ag, af), tb = ta + dtau;
    real sa = sqrt(a);
    real integral_p = al_atan2(sa * dtau, AL_R(1.0) + a * ta * tb) / sa;
    real p_min = AL_R(1.0) / (AL_R(1.0) + a * quarter_pi2);
    real integral_q = (integral_p - p_min * dtau) / (AL_R(1.0) - p_min);
#else
    // Q = a cos^2 / (sin^2 + a cos^2) for any a > 0 (a > 1: g rises away from 0);
    // Q(tau_w) = y gives a in closed form.
    real a = clamp(y * tw2 / (AL_R(1.0) - y), AL_R(1e-12), AL_R(1e6));
    real integral_q = al_ellipse_q_integral(ag, af, bg, bf, dtau, a);
#endif
    return gmin * dtau + span * integral_q;
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

// Fitted integral of the near-form integrand (1 - x^k) / (1 - x^2) (far = false)
// or of x^k / (1 - x^2) (far = true) over the arc of E.
real al_peak_edge_term(AlEdgeFrame E, real dtau, real k, bool far_edge) {
    real s2 = E.s * E.s;
    real lc = AL_R(0.5) * al_log1p(-s2);  // log c
    real tw2 = far_edge ? AL_R(1.38629436111989061883) / (k + AL_R(2.0) / max(s2, AL_R(1e-30)))
                        : s2 + AL_R(2.0) / k;
    // At tau_w: 1 - x^2 = (s^2 + tan^2) / (1 + tan^2) without cancellation, log x.
    real one_minus_xw2 = (s2 + tw2) / (AL_R(1.0) + tw2);
    real lxw = lc - AL_R(0.5) * al_log1p(tw2);
    if (far_edge) {
        real gmax = s2 > AL_R(0.0) ? al_exp(k * lc) / s2 : AL_R(0.0);
        real fit = al_peak_integral(E.ag, E.af, E.bg, E.bf, dtau, gmax, AL_R(0.0), tw2,
                                    al_exp(k * lxw) / one_minus_xw2);
        real tan1, x1;
        if (!al_arc_near_end(E, tan1, x1)) return fit;
        // g = x^k / (1 - x^2), 1 - x^2 = s^2 + c^2 sin^2; -d log g = k tan + 2 x^2 tan / (1 - x^2).
        real sin2 = tan1 * tan1 / (AL_R(1.0) + tan1 * tan1);
        real omx2 = s2 + (AL_R(1.0) - s2) * sin2;
        real g1 = al_exp(k * al_log(max(x1, AL_R(1e-30)))) / omx2;
        real lambda = k * tan1 + AL_R(2.0) * x1 * x1 * tan1 / omx2;
        return min(fit, al_tail_bound(g1, max(lambda, AL_R(0.0)), dtau));
    }
    real gmax = s2 > AL_R(1e-30) ? -al_expm1(k * lc) / s2 : AL_R(0.5) * k;
    return al_peak_integral(E.ag, E.af, E.bg, E.bf, dtau, gmax, AL_R(1.0), tw2,
                            -al_expm1(k * lxw) / one_minus_xw2);
}

// Per-arc sums for the arc a -> b with inward unit normal m (phong_edge.glsl), the
// same quantities as the exact method's.
AlPhongEdge al_phong_edge(rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n, real N) {
    AlEdgeFrame E = al_edge_frame(a, b, m, r, N, AL_PEAK_LOG_FAR);
    real dtau = max(al_atan2(E.bg, E.bf) - al_atan2(E.ag, E.af), AL_R(0.0));
    bool far_edge = E.far_edge;
    real t1 = al_peak_edge_term(E, dtau, N + AL_R(1.0), far_edge);
    real t0 = al_peak_edge_term(E, dtau, N, far_edge);
    // x^N: max c^N, min 0, exact half width cos^2 tau_w = 2^(-2/N), where g = c^N / 2.
    real cw2 = al_exp(AL_R(-1.38629436111989061883) / N);
    real cn = al_exp(N * AL_R(0.5) * al_log1p(-E.s * E.s));
    real tz = al_peak_integral(E.ag, E.af, E.bg, E.bf, dtau, cn, AL_R(0.0),
                               (AL_R(1.0) - cw2) / cw2, AL_R(0.5) * cn);
    real tan1, x1;
    if (al_arc_near_end(E, tan1, x1)) {
        tz = min(tz, al_tail_bound(al_exp(N * al_log(max(x1, AL_R(1e-30)))), N * tan1, dtau));
    }
    AlPhongEdge e;
    e.near_edge = !far_edge;
    real sgn = far_edge ? AL_R(1.0) : AL_R(-1.0);
    e.sums = rvec3(sgn * E.rm * t1, sgn * E.rm * t0, dot(n, m) * tz);
    return e;
}
