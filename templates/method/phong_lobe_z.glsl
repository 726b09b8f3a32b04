// The z integral of one Phong arc in closed form, for the peak methods at N >= 32
// (method/peak_lobe_edge.glsl): int x^N dtau over the arc of E, x = c cos(tau).
// With t = tan(tau) it is c^N int (1 + t^2)^(-m) dt, m = (N + 2) / 2; w = sqrt(2 m
// log(1 + t^2)) makes the integrand exp(-w^2 / 2) exactly, and dt/dw = (2m)^(-1/2) (1 + 3
// w^2 / (8 m) + 25 w^4 / (384 m^2) + O(w^6 / m^3)) (from t = sqrt(exp(w^2 / (2 m)) - 1)).
// The Gaussian's moments integrate that in closed form: each end contributes its tail
// beyond |w|, q(w) = exp(-w^2 / 2) ((1 + A + 3 B) sqrt(pi / 2) erfcx(|w| / sqrt 2) + |w| (A
// + B (w^2 + 3))), A = 3 / (8 m), B = 25 / (384 m^2). Ends on one side of the foot take the
// difference of their tails (no cancellation of two values near the total).
// Domain: real N >= 32, any arc (t = +-inf at x = 0 included). Error, against Simpson's
// rule at 4 000 nodes on arcs across and beside the foot, N in [32, 1e5]: <= 2.1e-5 of
// the whole lobe's integral (at N = 32; less above), where the 8-node rule of
// method/phong_edge_rule.glsl it replaces reached ~1e-3 at grazing views (the public stress
// set's N = 2 551 pentagon). Cost: two log1p, two exp, two erfcx an arc, no loop.
real al_lobe_z_tail(real t2, real m2, real a, real b, real c0) {
    real w2 = m2 * al_log1p(t2);
    real w = sqrt(w2);
    return al_exp(AL_R(-0.5) * w2) *
           (c0 * al_erfcx_fast(AL_R(0.70710678118654752440) * w) + w * (a + b * (w2 + AL_R(3.0))));
}

// lc = log c (AlArcShared.lc).
real al_lobe_z(AlEdgeFrame E, real lc, real N) {
    real m2 = N + AL_R(2.0);  // 2 m
    real a = AL_R(0.75) / m2;
    real b = AL_R(0.26041666666666666667) / (m2 * m2);
    real c0 = (AL_R(1.0) + a + AL_R(3.0) * b) * AL_R(1.25331413731550025121);  // sqrt(pi / 2)
    // f >= 0 at both ends (al_edge_frame); t^2 capped where x = 0 (f = 0): q = 0 there.
    real qa = al_lobe_z_tail(min(E.ag * E.ag / (E.af * E.af), AL_R(1e30)), m2, a, b, c0);
    real qb = al_lobe_z_tail(min(E.bg * E.bg / (E.bf * E.bf), AL_R(1e30)), m2, a, b, c0);
    bool a_pos = E.ag >= AL_R(0.0), b_pos = E.bg >= AL_R(0.0);
    // The arc runs from a to b in increasing tau: a beyond the foot with b before it is empty.
    real v = a_pos == b_pos ? (b_pos ? qa - qb : qb - qa)
                            : (b_pos ? AL_R(2.0) * c0 - qa - qb : AL_R(0.0));
    // c^N of a NaN log c (an arc whose pole is r, to rounding) counts as 0, as the fits' flat
    // test takes it.
    real cn = al_exp(N * lc);
    return cn > AL_R(0.0) ? cn * max(v, AL_R(0.0)) * inversesqrt(m2) : AL_R(0.0);
}
