// Phong's per-arc sums on a polygon by peak functions (method/peak_phong.glsl), with
// departures where the fits fail (fit=tuned only; fit=paper fits everything):
// - N below AL_PEAK_RULE_BELOW: the whole arc by the Gauss rule of
//   method/phong_edge_rule.glsl at 6 nodes (common/gauss_legendre6.glsl). A low-N lobe is
//   wide, so lights near the horizon see a specular moment that is a small difference of
//   O(1) boundary terms (N (r.n) M_(N-1) against the z sums), and a fit's 1e-2 became an
//   error of order 1 (the public horizon sphere case at N = 2.46: specular relL2 0.5
//   through the 16-gon proxy).
// - The z integral int x^N dtau of every arc, which carries that cancellation at any N:
//   at N >= 32 in closed form (method/phong_lobe_z.glsl, error <= 2.1e-5 of the lobe's
//   integral), below it the rule's third sum.
// Measured on 1500 polygons near the horizon with r aimed at them, N in [1, 200]
// (scripts/gen_curved_cases.py 1500 5 --kind aimed), specular relL2: lorentz
// 2.4e-2 -> 8.1e-3, ellipsoid 1.4e-2 -> 2.3e-3; public horizon 3.6e-3 -> 8.0e-4
// (lorentz). What is left is the fits of the moment's t_(N+1), t_N at N >= 32.
// The rule at 8 nodes and z by its z sum at N >= 32 (before 2026-12-06) against 6 nodes
// and the closed form, specular relL2 (pearson; lorentz alike): public sets unchanged to 3
// digits but stress 2.1e-4 -> 3.8e-4 (lorentz 7.1e-4 -> 1.3e-4: a grazing N = 2 551
// pentagon, where 8 nodes left z 1e-3 off); 600 horizon-peak polygons (gen_curved_cases.py
// 600 7 --kind horizon-peak) 2.39e-3 -> 2.26e-3 (4 nodes: 2.96e-3; 5: 2.44e-3). GPU cost
// (navi21): lorentz 7 239 -> 6 721 cycles a wave, both arms of the branch counted.
// - t_(N+1) and t_N from one fit (al_peak_edge_terms, method/peak_phong.glsl; fit=tuned).
// - At N >= 32, arcs whose great circle misses the lobe's core (N s^2 > AL_PEAK_RULE_CORE:
//   s beyond a third of the lobe's width N^-1/2) but which the lobe still reaches
//   (x^(N+1) >= 1e-2 somewhere on the arc): the rule as well, with the closed-form z. On
//   such an arc g is the azimuth's Lorentzian of width s times the lobe's Gaussian of width
//   N^-1/2, a Voigt-like shape none of the three families follows, and with r outside the
//   light (a glossy lobe beside a light's edge) the result is that arc's term alone: fitted,
//   it came out +3% to +5% (pub-degenerate-grid-sphere-phong-031, N = 128, the lobe 2.2
//   widths outside the rim: +4.7%). The fits keep what they model: arcs whose circle passes
//   through the core (s -> 0: g = (1 - cos^k tau) / sin^2 tau, a peak with a Lorentzian
//   tail) and arcs in the far tail (under al_tail_bound). Specular relL2 before -> after,
//   pearson, CPU mirror, public typical / horizon / glossy / degenerate: polygon 2.5e-3 /
//   5.9e-4 / 3.2e-3 / 3.8e-3 -> 1.3e-4 / 8.5e-5 / 1.0e-4 / 2.3e-5, sphere degenerate 2.8e-2
//   -> 6.5e-4 (docs/methods.md has every method and light). Typical / degenerate with the
//   rule on near arcs only beyond N s^2 = 1: 1.3e-3 / 3.5e-3; on near and reached far arcs
//   beyond 0.25 and 0.1: 1.9e-4 / 1.0e-3 and 1.3e-4 / 2.3e-5 (lorentz degenerate 7.2e-3 and
//   3.6e-5); 0.1 taken. GPU cost (navi21): pearson 6 801 -> 6 869 cycles a wave, the rule's
//   branch already there for N < 32.
// Domain: real N >= 1, any arc.
#define AL_PEAK_RULE_BELOW AL_R(32.0)
#define AL_PEAK_RULE_CORE AL_R(0.1)
#define AL_PEAK_RULE_REACH AL_R(-4.6)  // log of x^(N+1) = 1e-2, to two digits

// Per-arc sums for the arc a -> b with inward unit normal m (method/phong_edge.glsl), the
// same quantities as the exact method's.
AlLobeEdge al_lobe_edge(rvec3 a, rvec3 b, rvec3 m, rvec3 r, rvec3 n, real N) {
#ifndef AL_FIT_PAPER
    // One frame serves both regimes (they differ only in the far test's threshold).
    bool low = N < AL_PEAK_RULE_BELOW;
    AlEdgeFrame E = al_edge_frame(a, b, m, r, N, low ? AL_R(-6.9) : AL_PEAK_LOG_FAR);
    bool rim = N * E.s * E.s > AL_PEAK_RULE_CORE &&
               (N + AL_R(1.0)) * al_arc_log_x_max(E) > AL_PEAK_RULE_REACH;
    rvec3 t;
    if (low || rim) {
        t = al_lobe_rule(E, N);  // the exact method's forms
    } else {
        t = rvec3(al_peak_edge_terms(E, al_arc_shared(E), N, E.far_edge), AL_R(0.0));
    }
    if (!low) t.z = al_lobe_z(E, al_arc_log_c(E), N);
    return al_lobe_sums(E, t, n, m);
#else
    AlEdgeFrame E = al_edge_frame(a, b, m, r, N, AL_PEAK_LOG_FAR);
    E.far_edge = false;  // the paper fits the near form everywhere
    AlArcShared S = al_arc_shared(E);
    real t1 = al_peak_edge_term(E, S, N + AL_R(1.0), false);
    real t0 = al_peak_edge_term(E, S, N, false);
    // x^N: max c^N, min 0, exact half width cos^2 tau_w = 2^(-2/N), where g = c^N / 2;
    // the tail sample at tan(tau_t) = 2 tan(tau_w).
    real lc = S.lc;
    real cw2 = al_exp(AL_R(-1.38629436111989061883) / N);
    real cn = al_exp(N * lc);
    AlPeakFit F;
    F.gmax = cn;
    F.gmin = AL_R(0.0);
    F.tw2 = (AL_R(1.0) - cw2) / cw2;
    F.gw = AL_R(0.5) * cn;
    F.tt2 = AL_R(4.0) * F.tw2;
    F.gt = al_exp(N * (lc - AL_R(0.5) * al_log1p(F.tt2)));
    real tz = al_peak_integral(E.ag, E.af, E.bg, E.bf, S.ta, S.dtau, F);
    return al_lobe_sums(E, rvec3(t1, t0, tz), n, m);
#endif
}
