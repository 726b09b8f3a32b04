// Exact microfacet shading over a spherical polygon: `ndf` and `specular`
// (CONTRACT.md 2) as boundary integrals in half-vector space, evaluated by
// peak-aware Gauss-Legendre rules of fixed size. Domain: every distribution's
// parameter range, any convex polygon clipped to the horizon of n, n.v > 0
// (specular is 0 otherwise; ndf is computed for n.v <= 0 too). Cost: AL_NODES
// nodes per arc for ndf, times AL_RADIAL radial nodes for specular, whatever
// alpha or N.
//
// Derivation (ROADMAP.md identity, checked against the oracle): the lit region
// R = light ∩ {n.w > 0} maps to the half-vector region R_h = {normalize(w + v)}.
// In polar coordinates (theta, phi) about n, any integrand f(theta, phi) has the
// potential G_f(theta, phi) = int_0^theta f(t, phi) sin t dt with d(G_f dphi) =
// f dA, so int_R_h f dA = sum over R_h's boundary arcs of int G_f dphi ("direct
// form", valid when -n is not in R_h). With the tail T_f = G_f(theta_hz(phi)) -
// G_f(theta) (theta_hz where the lobe meets the horizon of w, below),
// int_R_h f dA = [n in R_h] Full - sum int T_f dphi ("tail form", valid when
// -n may be in R_h). ndf takes f = D, with closed-form potentials (the
// distribution's al_ndf_cumulative and al_ndf_tail) and Full = 2 pi gmax;
// specular takes f = D W, W = G2(w, v) (h.v) / (n.v) F(h.v) (the Jacobian
// dw = 4 (h.v) dh of CONTRACT.md 2's specular), with the potentials by a
// radial rule. n is in R_h exactly when the mirror direction r is in R.
//
// Which form: the direct form is used when r lies in R or within 1e-5 of it
// (then the result is of the lobe's size and nothing cancels); otherwise the
// tail form, whose integrand is small everywhere except on arcs that pass
// close to n ("near" arcs: closer than twice the lobe width). There int T dphi
// = int Full(phi) dphi - int G dphi: for ndf Full is constant (gmax times the
// arc's azimuth sweep, from two atan2), for specular a smooth function of phi
// integrated by a Gauss rule in phi.
//
// Nodes along an arc: the arc's parameter tau is substituted by tan(tau - tau*) =
// sigma tan(xi), which places half the nodes within sigma of tau*, tau* the foot
// of r on the arc's great circle (where h comes closest to n) and sigma the
// lobe's width plus the distance of closest approach, divided by |dh/dtau| there
// (so the squeeze of the lobe at grazing views and the fold of the half-vector
// map near w = -v set the spacing); in the reference rule (fp64, 16 nodes), Newton steps
// move tau* to where h truly comes closest (al_moments_arc). Radial nodes: the substitution y = 2 pi
// int_theta^pi/2 D cos sin (al_ndf_y, the cosine-weighted tail) makes D sin dtheta
// = dy / (2 pi cos theta), so the radial integrand W / cos theta is smooth on the
// lobe's own scale (GGX: nodes spread in log(1 + z / AL_RADIAL_CORE), al_mf_mean_weight).
// Grazing views, n.v = 1e-3, 1e-4 and 1e-7, alpha 0.1 to 1 (tests/test_microfacet_shading.cpp):
// specular within 6.4e-6 (ggx), 4.4e-6 (beckmann), 1.3e-7 (blinn) of the oracle; before
// those two steps 1.6e-4 (ggx) and 1.8e-4 (beckmann, alpha 0.1), both at n.v = 1e-7.
//
// Error: see docs/microfacet.md's table (arealight eval + shared/tools/score).
// GPU cost (navi21, `arealight gpu-cost`, the validation kernel, GGX polygon, 2026-12-06):
// fp64 default 2 343 030 (4 700x the point light's 498; 256 VGPRs, 282 spilled; 2 019 845
// before the centre's Newton steps and GGX's radial spread); precision=fp32 70 660 (142x;
// was 65 165); nodes=2 radial=2 fp32 20 937 (42.0x, 152 VGPRs; 23 687 before it took
// AL_FAST_ARC, common/common.glsl, on 2026-12-07; 22 149 before the radial spread).
//
// Curved lights (disk, sphere, ellipsoid): the same pieces along their curved
// boundary (al_mf_piece with conic true; al_moments_conic, light/ellipse_clip.glsl), w and
// w' at each node from the ellipse's parametrisation instead of the arc's.

struct AlMoments {
    rvec3 n, v, r;
    rvec3 e1, e2;      // tangent frame of n: azimuth phi = atan2(h.e2, h.e1)
    rvec3 u1, u2;      // the plane of incidence's tangent at r, and its normal
    real nv, lv, f0;   // n.v, Smith Lambda(v), Schlick f0 (1: F = 1)
    AlDist d;
    bool direct;       // direct form (r in R, or within 1e-5); else tail form
    bool specular_on;  // n.v > 0
    real ndf, specular;
};

AlMoments al_mf_begin(rvec3 n, rvec3 v, rvec3 r, real param, real f0, bool direct) {
    AlMoments M;
    M.n = n;
    M.v = v;
    M.r = r;
    M.nv = dot(n, v);
    al_tangent_frame(n, M.e1, M.e2);
    rvec3 nxv = cross(n, v);
    real nxv_len = length(nxv);
    M.u2 = nxv_len > AL_R(0.0) ? nxv / nxv_len : M.e2;
    M.u1 = cross(M.u2, r);
    M.d = al_dist_make(param);
    M.specular_on = M.nv > AL_R(0.0);
    M.lv = M.specular_on ? al_smith_lambda(M.d, M.nv, nxv_len * nxv_len) : AL_R(0.0);
    M.f0 = f0;
    M.direct = direct && M.specular_on;
    M.ndf = AL_R(0.0);
    M.specular = AL_R(0.0);
    return M;
}

// W = G2(w, v) (h.v) / (n.v) F(h.v) at the half vector h = cos(theta) n +
// sin(theta) e (unit e tangent to n), w = 2 (h.v) h - v: the factor of D in the
// specular potentials; 0 where w is below the horizon.
real al_mf_weight(AlMoments M, rvec2 cs, rvec3 e) {
    rvec3 h = cs.x * M.n + cs.y * e;
    real hv = dot(h, M.v);
    rvec3 w = AL_R(2.0) * hv * h - M.v;
    real nw = dot(M.n, w);
    if (!(nw > AL_R(0.0)) || !(hv > AL_R(0.0))) return AL_R(0.0);
    rvec3 nxw = cross(M.n, w);
    real g2 = al_smith_g2(al_smith_lambda(M.d, nw, dot(nxw, nxw)), M.lv);
    return g2 * hv / M.nv * al_schlick(M.f0, hv);
}

// The lobe's reach along the meridian of unit tangent e: theta_hz where
// w = 2 (h.v) h - v meets the horizon of n, tan(2 theta_hz) = -(n.v) / (e.v)
// (from 2 (h.v)(n.h) = n.v), as (cos, sin); h.v > 0 on [0, theta_hz].
rvec2 al_mf_horizon(AlMoments M, rvec3 e) {
    rvec2 cs2 = rvec2(-dot(e, M.v), M.nv);  // (cos 2t, sin 2t) up to scale
    real len = length(cs2);
    real c2 = cs2.x / len;
    // Half angles without cancellation: from 1 + cos 2t or 1 - cos 2t, whichever is larger.
    real ct = sqrt(max(AL_R(0.5) * (AL_R(1.0) + c2), AL_R(0.0)));
    real st = c2 >= AL_R(0.0) ? (cs2.y / len) / (AL_R(2.0) * ct)
                              : sqrt(max(AL_R(0.5) * (AL_R(1.0) - c2), AL_R(0.0)));
    if (c2 < AL_R(0.0)) ct = (cs2.y / len) / (AL_R(2.0) * st);
    return rvec2(ct, st);
}

// The mean of W / cos(theta) along the meridian e between the radial variables
// z_lo and z_hi (al_radial_z of the distribution), weighted by D sin(theta)
// dtheta = |dy/dz| dz / (2 pi cos theta): the ratio of two AL_RADIAL-node
// Gauss-Legendre sums over the same nodes, so that the rule is exact for constant
// W and the lobe's mass comes from the closed-form potentials.
//
// With AL_RADIAL_CORE (dist/ggx_radial.glsl) the nodes are spread in s = log(1 + (z - z_lo) /
// AL_RADIAL_CORE) rather than in z: GGX's range in z grows as log(1 / (n.v)) at grazing
// views while its mass stays within a few AL_RADIAL_CORE of z_lo, and 16 nodes spread
// evenly over z in [0, 18] (n.v = 1e-7) left the lobe's core to four of them (specular
// 9.5e-4 off at alpha 0.5).
real al_mf_mean_weight(AlMoments M, rvec3 e, real z_lo, real z_hi) {
#ifdef AL_RADIAL_CORE
    real half_len = AL_R(0.5) * al_log1p((z_hi - z_lo) / AL_RADIAL_CORE), mid = half_len;
#else
    real half_len = AL_R(0.5) * (z_hi - z_lo), mid = AL_R(0.5) * (z_hi + z_lo);
#endif
    real num = AL_R(0.0), den = AL_R(0.0);
    for (int k = 0; k < AL_RADIAL; ++k) {
#ifdef AL_RADIAL_CORE
        real g = al_exp(mid + half_len * AL_GR_X[k]);  // dz/ds / AL_RADIAL_CORE
        real z = z_lo + AL_RADIAL_CORE * (g - AL_R(1.0));
#else
        real g = AL_R(1.0), z = mid + half_len * AL_GR_X[k];
#endif
        rvec3 node = al_radial_node(M.d, z);
        if (!(node.x > AL_R(0.0))) continue;  // theta = pi/2: no mass in fp (z rounded to its end)
        real mass = AL_GR_W[k] * g * node.z / node.x;
        num += mass * al_mf_weight(M, rvec2(node.x, node.y), e);
        den += mass;
    }
    return den > AL_R(0.0) ? num / den : AL_R(0.0);
}

// The specular potential at a boundary point at polar angle theta_b (cos c_b,
// sin^2 s2_b): int D W sin dtheta from n (use_g) or to the lobe's horizon
// theta_hz (else), along the meridian e: the ndf potential over the same range
// (closed form) times the mean of W there.
real al_mf_potential(AlMoments M, rvec3 e, real c_b, real s2_b, bool use_g) {
    rvec2 hz = al_mf_horizon(M, e);
    real s2_hz = hz.y * hz.y;
    real z_hz = al_radial_z(M.d, hz.x, s2_hz);
    real z_b = al_radial_z(M.d, c_b, s2_b);
    if (z_b >= z_hz) {
        // The boundary lies on (or, by rounding, past) the lobe's horizon.
        z_b = z_hz;
        c_b = hz.x;
        s2_b = s2_hz;
    }
    if (use_g) return al_ndf_cumulative(M.d, c_b, s2_b) * al_mf_mean_weight(M, e, AL_R(0.0), z_b);
    real mass = al_ndf_tail(M.d, c_b, s2_b) - al_ndf_tail(M.d, hz.x, s2_hz);
    return mass * al_mf_mean_weight(M, e, z_b, z_hz);
}

// Azimuth about n of a direction.
real al_mf_azimuth(AlMoments M, rvec3 h) {
    return al_atan2(dot(h, M.e2), dot(h, M.e1));
}

// Wraps an azimuth difference into (-pi, pi].
real al_mf_wrap(real d) {
    if (d > AL_PI) return d - AL_TWO_PI;
    if (d <= -AL_PI) return d + AL_TWO_PI;
    return d;
}

// One boundary piece of the lit region about its centre psi = 0 (where h comes
// closest to n), psi in [psi_a, psi_b] given by the ends' (sin, cos) up to a
// positive factor: a great arc w = cos(psi) ws + sin(psi) ts (conic false; inward
// unit normal m = ws x ts, psi the arc length), or a part of a curved light's
// boundary w = normalize(C + ws cos psi + ts sin psi) (conic true; light/ellipse_clip.glsl,
// m unused). hs: the half vector at the centre; sigma: the core's width in psi.
// Pieces 0-2 of al_peak_rule, and piece 3, for a near piece in the tail form
// only, Full(phi) by a Gauss rule over the core's azimuth sweep. One loop over the
// pieces, so that the node code appears once (on lavapipe each inlined copy of
// the radial rule costs seconds of JIT time).
void al_mf_piece(AL_INOUT(AlMoments) M, bool conic, rvec3 C, rvec3 ws, rvec3 ts, rvec3 m,
                 rvec4 ends, rvec3 hs, real sigma) {
    real s_h = length(cross(M.n, hs));
    bool near_arc = s_h < AL_R(2.0) * M.d.width;
    AlPeakRule rule = al_peak_rule(sigma, ends.x, ends.y, ends.z, ends.w);
    bool tail_near = !M.direct && near_arc;
    // The core's azimuth sweep about n in two halves through hs (each less than
    // pi, however close the piece passes to n): the tail form of a near piece needs it.
    rvec2 sc0 = al_sincos(rule.c0), sc1 = al_sincos(rule.c1);
    rvec3 w0, w1;
    if (conic) {
        rvec2 e0 = normalize(rvec2(sc0.y, sigma * sc0.x)), e1 = normalize(rvec2(sc1.y, sigma * sc1.x));
        w0 = normalize(C + e0.x * ws + e0.y * ts);
        w1 = normalize(C + e1.x * ws + e1.y * ts);
    } else {
        w0 = normalize(sc0.y * ws + sigma * sc0.x * ts);
        w1 = normalize(sc1.y * ws + sigma * sc1.x * ts);
    }
    real phi0 = al_mf_azimuth(M, normalize(w0 + M.v));
    real phi1 = al_mf_azimuth(M, normalize(w1 + M.v));
    real phi_s = al_mf_azimuth(M, hs);
    real sweep = al_mf_wrap(phi_s - phi0) + al_mf_wrap(phi1 - phi_s);
    rvec2 acc[4];
    for (int piece = 0; piece < 4; ++piece) {
        acc[piece] = rvec2(AL_R(0.0));
        bool use_g = M.direct || (piece == 0 && near_arc);
        rvec2 range = al_peak_range(rule, piece);
        if (piece == 3) {
            if (!tail_near || !M.specular_on) continue;
            range = rvec2(phi0, phi0 + sweep);
            use_g = false;
        }
        real x0 = range.x, x1 = range.y;
        real half_width = AL_R(0.5) * (x1 - x0), mid = AL_R(0.5) * (x0 + x1);
        if (!(abs(half_width) > AL_R(0.0))) continue;
        rvec2 sum = rvec2(AL_R(0.0));
        for (int j = 0; j < AL_NODES; ++j) {
            real x = mid + half_width * AL_GL_X[j];
            rvec3 e;       // unit tangent at n towards the boundary point
            real c_h = AL_R(1.0), sin2_h = AL_R(0.0), dphi;
            if (piece == 3) {
                rvec2 sc = al_sincos(x);
                e = sc.y * M.e1 + sc.x * M.e2;
                dphi = AL_GL_W[j];
            } else {
                // (cos, sin) of psi up to a positive factor, and dpsi/dx.
                rvec3 node = al_peak_node(rule, piece, x);
                real wc = node.x, wsn = node.y;
                rvec3 wj, dw;  // w and dw/dpsi
                if (conic) {
                    real l = inversesqrt(wc * wc + wsn * wsn);
                    rvec3 P = C + (wc * l) * ws + (wsn * l) * ts;
                    rvec3 dP = (wc * l) * ts - (wsn * l) * ws;
                    real il = inversesqrt(dot(P, P));
                    wj = P * il;
                    dw = (dP - wj * dot(wj, dP)) * il;
                } else {
                    wj = (wc * ws + wsn * ts) * inversesqrt(wc * wc + wsn * wsn);
                    dw = cross(m, wj);
                }
                rvec3 s = wj + M.v;
                rvec3 ns = cross(M.n, s);
                real ns2 = dot(ns, ns);
                if (!(ns2 > AL_R(0.0))) continue;
                real s2 = dot(s, s);
                c_h = dot(M.n, s) * inversesqrt(s2);
                sin2_h = ns2 / s2;
                // dphi/dpsi = n.(s x w') / |n x s|^2.
                dphi = AL_GL_W[j] * node.z * dot(ns, dw) / ns2;
                e = cross(ns * inversesqrt(ns2), M.n);
                real pot = use_g ? al_ndf_cumulative(M.d, c_h, sin2_h)
                                 : al_ndf_tail(M.d, c_h, sin2_h);
                sum.x += pot * dphi;
            }
            if (M.specular_on) sum.y += al_mf_potential(M, e, c_h, sin2_h, use_g) * dphi;
        }
        acc[piece] = sum * half_width;
    }
    rvec2 outer = acc[1] + acc[2];
    if (!tail_near) {
        // Direct form: every piece integrated G. Tail form, far piece: every piece T.
        real sgn = M.direct ? AL_R(1.0) : AL_R(-1.0);
        M.ndf += sgn * (acc[0].x + outer.x);
        M.specular += sgn * (acc[0].y + outer.y);
        return;
    }
    // Tail form, near piece: the core integrated G, so -int T dphi = int G dphi -
    // int Full(phi) dphi over the core (Full = gmax for ndf), and the outer pieces T.
    M.ndf += acc[0].x - M.d.gmax * sweep - outer.x;
    M.specular += acc[0].y - acc[3].y - outer.y;
}

// Newton steps that refine an arc's centre (al_moments_arc): for the in-shader reference
// only (fp64, 16 nodes an arc piece). At fp32 they changed no public set's relL2 by more
// than rounding and cost 8-15% (navi21; ggx nodes=2 radial=2 22 149 -> 25 584 cycles a
// wave), and fp32 cannot resolve the grazing views they are for; with 2 or 3 nodes an arc
// piece (fp64) they cost 16-19% for relL2 changes of -2% to +4% (ggx nodes=3: specular
// 2.47e-3 -> 2.58e-3).
#if AL_PRECISION_FP64 && AL_NODES >= 8
#define AL_CENTRE_STEPS 4
#else
#define AL_CENTRE_STEPS 0
#endif

// One arc a -> b of the lit region with inward unit normal m (light/polygon.glsl),
// integrated about its centre w* (al_mf_piece).
void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 axis, rvec3 n,
                    real N) {
    // Centre: where h comes closest to n. Near r the half-vector distance is
    // anisotropic, |dh|^2 ~ (dw.u1)^2 / 4 + (dw.u2)^2 / (4 (n.v)^2): its minimum
    // along the arc's tangent line through the foot of r.
    // A foot within 1e-4 of 0 (r within that of the arc's pole: the horizon's arc under a
    // view exactly along n, where h keeps one distance from n along the whole arc) is
    // rounding's direction, off the arc's plane, and the tangent from it not a unit vector:
    // a light across the horizon under v = n came out 0 on lavapipe (blinn and beckmann
    // precision=fp32). There the arc's start serves.
    rvec3 foot = M.r - dot(M.r, m) * m;
    real foot_len = length(foot);
    rvec3 ws = foot_len > AL_R(1e-4) ? foot / foot_len : a;
    rvec3 ts = cross(m, ws);
    real l2 = AL_R(1.0) / max(M.nv * M.nv, AL_R(1e-12));
    rvec3 dd = ws - M.r;
    real p1 = dot(ts, M.u1), p2 = dot(ts, M.u2);
    real shift = -(dot(dd, M.u1) * p1 + l2 * dot(dd, M.u2) * p2) / (p1 * p1 + l2 * p2 * p2);
    ws = normalize(ws + clamp(shift, AL_R(-1e6), AL_R(1e6)) * ts);  // along the gnomonic line
    ts = cross(m, ws);
    // That metric holds near r only. At grazing views the lobe's preimage is a wedge in
    // the plane of incidence that widens with the elevation, and an arc crossing it well
    // above r came closest to n far from that estimate (n.v = 1e-7, beckmann alpha 0.1:
    // theta_h 0.29 there against 0.20 at the true closest point; specular 1.8e-4 and ndf
    // 1.6e-4 off). Newton steps on d(n.h)/dtau = 0 from it, each kept only if n.h grows.
#if AL_CENTRE_STEPS > 0
    real nh_best = dot(M.n, normalize(ws + M.v));
    for (int it = 0; it < AL_CENTRE_STEPS; ++it) {
        rvec3 P = ws + M.v;
        real nw1 = dot(M.n, ts), vw1 = dot(M.v, ts), nP = dot(M.n, P), PP = dot(P, P);
        real g = nw1 * PP - nP * vw1;  // |P|^3 d(n.h)/dtau
        real g1 = -dot(M.n, ws) * PP + nw1 * vw1 + nP * dot(M.v, ws);
        if (!(g1 < AL_R(0.0))) break;  // not towards a maximum
        real step = clamp(-g / g1, AL_R(-0.5), AL_R(0.5));
        rvec2 sc = al_sincos(step);
        rvec3 ws_new = sc.y * ws + sc.x * ts;
        real nh = dot(M.n, normalize(ws_new + M.v));
        if (!(nh > nh_best)) break;
        nh_best = nh;
        ws = normalize(ws_new);
        ts = cross(m, ws);
    }
#endif
    real ta_s = dot(a, ts), ta_c = dot(a, ws), tb_s = dot(b, ts), tb_c = dot(b, ws);
    if (al_atan2(ta_s, ta_c) > AL_R(0.0) || al_atan2(tb_s, tb_c) < AL_R(0.0)) {
        // Off the arc: centre on the end nearer to it.
        ws = dot(ws, a) >= dot(ws, b) ? a : b;
        ts = cross(m, ws);
        ta_s = dot(a, ts);
        ta_c = dot(a, ws);
        tb_s = dot(b, ts);
        tb_c = dot(b, ws);
    }
    // The half vector there, its distance from n and its speed |dh/dtau|.
    rvec3 sv = ws + M.v;
    real sl = length(sv);
    rvec3 hs = sv / sl;
    real s_h = length(cross(M.n, hs));
    real speed = length(ts - dot(hs, ts) * hs) / sl;
    real w = M.d.width;
    real sigma = clamp(sqrt(s_h * s_h + w * w) / max(speed, AL_R(1e-30)), AL_R(1e-12),
                       AL_R(1e6));
    al_mf_piece(M, false, rvec3(AL_R(0.0)), ws, ts, m, rvec4(ta_s, ta_c, tb_s, tb_c), hs, sigma);
}

#ifdef AL_LIGHT_CURVED
// One part [psi0, psi1] (at most pi/2) of a curved light's boundary (light/ellipse_clip.glsl;
// a and b, its ends, only matter to Phong's accumulator), in the sub-parts of
// al_conic_plan: about where h comes closest to n (lobe width: the distribution's),
// about the fold near w = -v where the view grazes (h turns fast there: |dh| =
// |dw_perp| / |w + v|), and about p's nearest point on the light's rim.
void al_moments_conic(AL_INOUT(AlMoments) M, rvec3 C, rvec3 U, rvec3 V, real psi0, real psi1,
                      rvec3 a, rvec3 b, rvec3 axis, rvec3 n, real N) {
    AlConicPlan plan = al_conic_plan(C, U, V, psi0, psi1, M.n, M.v, M.d.width, true);
    for (int k = 0; k < 4; ++k) {
        if (k >= plan.count) break;
        AlConicFrame f = al_conic_frame(U, V, plan.sub[k]);
        al_mf_piece(M, true, C, f.Us, f.Vs, rvec3(AL_R(0.0)), f.ends,
                    normalize(normalize(C + f.Us) + M.v), plan.sub[k].w);
    }
}
#endif

// (specular, ndf) of the streamed region. In the tail form n is not in R_h
// (r is outside R), so Full never enters.
rvec2 al_mf_end(AlMoments M) {
    return rvec2(M.specular_on ? M.specular : AL_R(0.0), M.ndf);
}
