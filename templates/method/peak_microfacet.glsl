// Lecocq et al. 2016 section 8 on polygon lights for the microfacet distributions (blinn,
// beckmann, ggx) with every peak function (lorentz, pearson, ellipsoid): the NDF
// integral of CONTRACT.md 2 by axial moments about n of the lit region's half-vector
// image, and specular from it at O(1). Output as the exact family's: (diffuse,
// specular, ndf), diffuse exact (light/polygon.glsl).
//
// Construction. light/polygon.glsl streams the arcs of the lit region R = light ∩ {n.w >= 0}
// (no lobe clip: clip_axis = false) into al_moments_arc. Each arc's ends and split
// points (key split) are mapped to h = normalize(w + v), and consecutive ones are
// joined by great-circle chords: the h-polygon. Its moment about n,
// mu_N = (N+1)/(2 pi) int (n.h)^N dh, is method/phong_boundary.glsl's boundary form with
// r := n, each chord's edge integral (only the T_(N+1) term of the moment) by
// method/peak_phong.glsl's al_peak_edge_term: the same peak functions, fits, near/far
// forms and tail bounds as Phong's, and its winding and near/far sweep bookkeeping.
// The NDF is modelled as a mixture D ~ c0/pi + sum_j w_j (N_j+2)/(2 pi) (n.h)^N_j with
// sum_j w_j + c0 = 1, so int D dh ~ c0 Omega_h/pi + sum_j w_j (N_j+2)/(N_j+1) mu_j
// (Omega_h the h-polygon's solid angle, a Van Oosterom-Strackee fan from n), and
// every model is normalized: int D (n.h) dh = 1 over the hemisphere for any weights
// (tests/test_peak_microfacet.cpp checks it by quadrature of al_mix_ndf).
//
// GPU cost (navi21, `arealight gpu-cost`, the validation kernel, polygon, against the
// point light's 498-573; with AL_FAST_ARC, common/common.glsl, the one-lobe loop unrolled,
// each arc's shared terms once, GGX's spread factor and the fits' one fixed-point step, and
// each chord's sweep from its own frame, 2026-12-07): lorentz 15 062 / 15 055 / 19 965
// (blinn / beckmann / ggx; 26-40x), pearson 17 020 / 17 013 / 23 881 (29.7-48.0x),
// ellipsoid 17 035 / 17 028 / 23 911 (29.7-48.0x).
//
// The paper's formulas, checked numerically (the copy we read garbles some):
// - eq. 23: int D_Blinn dh = (N+2)/(2 pi) int (n.h)^N dh = (N+2)/(N+1) mu_N. As printed.
// - eq. 25: (1/(pi m^2)) int (n.h)^n dh with n = 2/m^2 - 2 (printed "m ~ 2/m^2 - 2"):
//   1/(pi m^2) = (n+2)/(2 pi), so eq. 25 is exactly Blinn at N = 2/alpha^2 - 2.
// - eq. 26: (1/pi)(c0 Omega + c1 (n1+2)/2 M^n1 + c2 (n2+2)/2 M^n2), M unnormalized,
//   n1 = 2/alpha^2 - 2, n2 = n1/10, c1 = 0.7 (1 - alpha^2), c2 = 0.3 (1 - alpha^2).
//   Normalization needs c0 + c1 + c2 = 1 (printed "c1 + c2 + c3 = 1" and "c0 = c^2 c0"),
//   so c0 = alpha^2. It is GGX's own constant: with b = 1 - alpha^2,
//   D_GGX = (alpha^2/pi) / (1 - b c^2)^2 = sum_k alpha^2 b^k L_2k exactly (L_N the
//   normalized Blinn lobe (N+2)/(2 pi) c^N, L_0 = 1/pi): weight alpha^2 on k = 0 and an
//   exponential spread of exponents of mean ~2/alpha^2 that eq. 26 samples at n1, n1/10.
// fit=paper (not enumerated; measured below) keeps eq. 23, 25, 26, Algorithm 1 and the
// Phong peak fits' printed recipe.
//
// Departures (fit=tuned), each measured with the ellipsoid at split=halved,
// factor=blend on the public sets (score --floor 1e-2, relL2, typical / horizon /
// glossy / stress, CPU mirror; lavapipe agrees to the digits shown):
// - GGX: three lobes and the constant, fitted per alpha, instead of eq. 26's two.
//   N_j = rho_j (2/alpha^2 - 2) (at least 1) and w_j come from tables at 20 alphas in
//   [0.001, 1] (linear in log alpha; c0 = 1 - sum w_j, 1 at alpha = 1 where D is
//   uniform), fitted by scripts/fit_peak_mixture.py (which prints these tables) to the
//   cumulative int_cap D dh about n and to D on patches of 0.003-0.3 sr, against the
//   score's floor. ndf: eq. 26 7.6e-2 / 2.5e-2 / 1.5e-2 / 8.7e-3 (p95 0.28 on typical),
//   two fitted lobes 2.5e-2 / 9.2e-3 / 3.0e-2 / 8.0e-3, three 5.8e-3 / 1.5e-3 /
//   6.4e-3 / 1.2e-3. The third lobe costs one more peak integral per chord.
// - Beckmann keeps eq. 25: a single lobe with N(alpha) fitted the same way made
//   typical ndf worse (7.1e-3 -> 2.1e-2); no positive mixture of cosine powers has
//   Beckmann's light tail. eq. 25's error grows with alpha (ndf 0.11, specular 0.056
//   on 150 random polygons at alpha in [0.8, 1]).
// - Exponents below 1 (eq. 25 above alpha = 0.816, eq. 26's n2 above 0.41, fit=paper):
//   the peak integrals start at N = 1, so such a lobe becomes the N = 1 lobe with
//   weight N plus the constant with weight 1 - N (both normalized; exact at the peak
//   and at N = 0, 1). Against clamping N to 1, beckmann at alpha in [0.8, 1]
//   (fit=paper): specular relL2 0.060 against 0.158, ndf 0.142 against 0.111, ndf p95
//   0.22 against 0.33.
// - Slivers: a chord misses the sliver between it and the true (curved) h-image of its
//   piece. Its offset is taken as a parabola through the image of the piece's
//   midpoint, d(t) = 4 d_mid (t - ta)(tb - t)/L^2, and its share of each lobe,
//   -int x^N d(t) dt, from the Gaussian form of x^N along the chord (al_pmf_sliver);
//   the constant's share is -2/3 d_mid L. One more half vector and a few exp/erfc per
//   chord and lobe, no peak fit. Blinn ndf without / with: 5.3e-3 / 4.6e-3, 0.116 /
//   1.6e-2, 6.2e-3 / 4.0e-3, 1.1e-4 / 2.8e-4 (the horizon set's lobes sit at clipped
//   edges, where the chords bend most). For scale, 32 chords per edge without it:
//   4.6e-3 / 6.1e-3 / 6.7e-4 (the rest is the peak fits').
// - split=halved: Algorithm 1's point p (the foot of r, the preimage of n, on the
//   edge's great circle, where it lies inside the edge), then each piece halved at its
//   midpoint in w (normalize(a + p)); an edge without p is halved once. At most 3
//   splits. Algorithm 2 (balanced) is not built: the issue measured halving 2-3x
//   better. Blinn ndf, split=none / single / halved (with slivers): 5.1e-3 / 4.5e-3 /
//   4.6e-3, 3.1e-2 / 3.0e-2 / 1.6e-2, 8.9e-2 / 6.0e-3 / 4.0e-3, 1.0 / 7.8e-2 / 2.8e-4.
// - factor: specular = int D G2 (h.v)/(n.v) F dh ~ ndf W(h*), W = G2(w*, v)
//   (h*.v)/(n.v) F(h*.v), w* = 2 (h*.v) h* - v. closest: h* = n if the h-polygon holds
//   n, else its boundary point closest to n. blend: h* = normalize(beta h_c +
//   (1 - beta) h_F), h_c that point, h_F = normalize(f + v) for the direction f of the
//   lit region's vector irradiance (sum of arc m / 2), beta = Omega / (Omega + 4 pi m^2),
//   Omega the lit region's solid angle and m the lobe's width (alpha; Blinn
//   sqrt(2/(N+2))): a small light is represented by its centre, a large one by the
//   lobe's peak. The issue's words leave which end beta weights open; the other
//   reading (beta on h_F) measured far worse: GGX specular 3.9e-2 / 0.15 / 0.11 / 0.92
//   against 2.2e-2 / 2.7e-2 / 7.0e-3 / 2.8e-2 (a light filling the hemisphere took
//   h* = normalize(n + v)). The D-weighted mean half vector of lobe 0 (its first
//   moment by Arvo's two-axis relation, two more peak integrals per chord) was no
//   better (Blinn specular 5.6e-3 / 4.6e-2 with horizon p95 0.76) and was dropped.
// - factor=blend, GGX: W is concave, so W at one point overestimates its D-weighted mean
//   (Jensen), most where GGX's long tail spreads D over a large light. W is averaged over
//   four points about h* (al_mf_end): specular relL2 typical / horizon / glossy / stress
//   pearson 2.2e-2 / 2.7e-2 / 7.0e-3 / 2.8e-2 -> 1.3e-2 / 1.6e-2 / 7.0e-3 / 2.8e-2, lorentz
//   2.3e-2 / 3.3e-2 -> 1.3e-2 / 2.5e-2; spinning polygon on spheres 7.8e-2 / 0.14 -> 1.5e-2 /
//   2.8e-2. The same average made Blinn's and Beckmann's horizon sets worse (blinn pearson
//   3.8e-2 -> 6.2e-2; their Gaussian tails keep D within the spread), as did moving points
//   whose w falls below the horizon back above it, for GGX (typical 2.2e-2 -> 3.2e-2). The
//   unshrunk spread at grazing views took GGX's stress sets from 2.9e-3 to 5.0e-2 (ellipsoid
//   lights). And at grazing views, with the lobe's peak lit, h* moves from n to the mean of
//   the lobe's half that the horizon leaves (al_mf_end; for Blinn and Beckmann too, whose
//   measurements are there): on 300 seeded GGX cases of
//   `scripts/gen_microfacet_cases.py 900 11 X --kind hard` pearson specular relL2 0.14 -> 6.3e-2
//   (its 50 grazing ones 0.38 -> 0.16); public sets within 2% but the stress disk (one case at
//   n.v = 4e-3, 8.3e-2 -> 0.10) and lorentz on the glossy ellipsoids (3.6e-3 -> 1.1e-2: its
//   ndf is 2% high on one case, which W 3% low had cancelled). Cost +120 cycles a wave in all
//   (ggx ellipsoid 24 876 -> 24 994, 50.2x its point light).
//   Per component (2026-12-07): the mixture's wide lobes and constant are GGX's tail, spread
//   over the whole light, so each of the four components takes its own blend weight beta_j
//   (its own width m_j) and its own spread; one point and one spread for the mixture held
//   the tail's W at the lobe's. Pearson specular relL2 typical / horizon / glossy / stress
//   1.32e-2 / 1.60e-2 / 7.07e-3 / 2.78e-2 -> 7.9e-3 / 5.9e-3 / 7.0e-3 / 2.4e-2 (lorentz
//   1.25e-2 / 2.48e-2 -> 8.5e-3 / 1.6e-2), disk horizon 6.4e-2 -> 3.3e-2; the GGX third of
//   `scripts/gen_microfacet_cases.py 3000 12 X --kind typical` 2.92e-2 -> 2.51e-2, of
//   `--kind near-horizon` (1800 21) 3.00e-2 -> 3.29e-2 (one case, -4.6% -> -5.1%). Taken
//   alone, the per-component spread (one h* for all) gave horizon 1.37e-2 and the
//   per-component h* (one spread) typical 1.22e-2; the pull of beta_j back to the
//   mixture's beta at low n.v (AL_PMF_VIEW2) keeps grazing views as they were (own hard set
//   0.138 without it, 9.9e-2 with, as before). Cost +1.7% (pearson 23 881 -> 24 283 cycles
//   a wave, 48.8x its point light; 16 evaluations of G2 instead of 4, outside the edge loop).
// - n.v <= 0 (specular 0, outside the method's range): half vectors below n's horizon
//   are projected onto it, so the chords follow the horizon there.
// - A chord shorter than 1e-7 rad adds nothing but its sweep to the total: its edge
//   integral and sliver vanish with its length, its normal would be rounding noise, and it
//   counts as a near arc, whose sweep the winding does not take (counted as a far one, as
//   it was, a chord at h = n, where r passes exactly through a vertex of the light or
//   Algorithm 1 splits at the vertex itself, gave the winding an O(1) sweep; al_pmf_h_arc).
//
// Measured (lavapipe; the CPU mirror agrees), default keys, specular relL2 typical /
// horizon / glossy: blinn ellipsoid 6.5e-3 / 3.8e-2 / 2.9e-3, beckmann 9.6e-3 / 1.7e-2
// / 6.8e-3, ggx 8.1e-3 / 5.9e-3 / 7.1e-3; no missing or bad value on any set. The
// paper's recipe (fit=paper, Algorithm 1, closest): 3.4e-2 / 0.34 / 2.1e-2, 6.4e-2 /
// 9.8e-2 / 5.1e-2, 7.0e-2 / 8.8e-2 / 2.6e-2. What is left: the specular factor (W at
// one point; grazing views, e.g. beckmann at n.v = 1e-3: -11%), Beckmann's model at
// large alpha, and GGX's small-alpha tail (ndf p95 0.15 on glossy).

// ---- The moment model of D ----------------------------------------------------------

// Smallest exponent a lobe is evaluated at: the peak edge integrals' domain starts at
// N = 1.
#define AL_PMF_N_MIN AL_R(1.0)
#if defined(AL_DIST_GGX) && !defined(AL_FIT_PAPER)
#define AL_PMF_LOBES 3
#elif defined(AL_DIST_GGX)
#define AL_PMF_LOBES 2
#else
#define AL_PMF_LOBES 1
#endif
// The lobe loop of the edge accumulator: unrolled for one lobe (Blinn, Beckmann), where it
// costs no instruction, since ACO's cost model charges a loop nested in the edge loop 4 x 8
// trips whatever its count (beckmann pearson 29 346 -> 19 820 cycles a wave, 2 576 -> 2 560
// instructions); GGX's three lobes stay a loop, whose unrolled form the model charges more
// (pearson 30 325 -> 38 391).
// (n.v)^2 at which the grazing-view terms of al_mf_end change over: GGX's spread is halved
// and h*'s shift towards the lobe's lit half is half on at n.v = 0.05 (about 3 degrees from
// grazing).
#define AL_PMF_GRAZING2 AL_R(0.0025)
// (n.v)^2 at which GGX's per-component blend weights are halfway back to the distribution's
// (al_mf_end): about 18 degrees from grazing.
#define AL_PMF_VIEW2 AL_R(0.1)
// GGX's specular factor (factor=blend) averages W over the spread of each mixture
// component's D-weighted h-region (al_mf_end); the Gaussian-tailed lobes and
// factor=closest keep W at one point.
#if defined(AL_DIST_GGX) && !defined(AL_FIT_PAPER) && defined(AL_FACTOR_BLEND)
#define AL_PMF_SPREAD
#endif
#if AL_PMF_LOBES == 1
#define AL_PMF_LOBE_LOOP AL_UNROLL
#else
#define AL_PMF_LOBE_LOOP
#endif

// D ~ sum_j w_j (N_j + 2)/(2 pi) (n.h)^N_j + c0 / pi, so that
// int D dh ~ sum_j w_j (N_j + 2)/(N_j + 1) mu_j + c0 Omega_h / pi, mu_j the normalized
// moment (N_j + 1)/(2 pi) int (n.h)^N_j dh of the h-polygon and Omega_h its solid
// angle. sum_j w_j + c0 = 1 makes every model normalized: int D (n.h) dh = 1 over the
// hemisphere.
struct AlMix {
    rvec3 N;  // lobe exponents (>= AL_PMF_N_MIN)
    rvec3 w;  // lobe weights
    real c0;  // weight of the constant 1/pi
};

#if !defined(AL_FIT_PAPER) && defined(AL_DIST_GGX)
#define AL_PMF_TAB 20
const real AL_PMF_T_LOGA[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(-6.90776), AL_R(-6.21461), AL_R(-5.52146), AL_R(-4.82831), AL_R(-4.13517),
    AL_R(-3.50656), AL_R(-2.99573), AL_R(-2.59027), AL_R(-2.30259), AL_R(-1.96611),
    AL_R(-1.60944), AL_R(-1.30933), AL_R(-1.04982), AL_R(-0.798508), AL_R(-0.597837),
    AL_R(-0.430783), AL_R(-0.287682), AL_R(-0.162519), AL_R(-0.0512933), AL_R(0.0) AL_ARRAY_END;
const real AL_PMF_T_LRHO0[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(0.119051), AL_R(0.119051), AL_R(0.131223), AL_R(0.141252), AL_R(0.137394),
    AL_R(0.187874), AL_R(0.269466), AL_R(0.372719), AL_R(0.461601), AL_R(0.556101),
    AL_R(0.680489), AL_R(0.823941), AL_R(0.988231), AL_R(1.2016), AL_R(1.41976),
    AL_R(1.66422), AL_R(1.97531), AL_R(2.06515), AL_R(3.06473), AL_R(3.06473) AL_ARRAY_END;
const real AL_PMF_T_W0[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(0.671573), AL_R(0.671573), AL_R(0.665277), AL_R(0.658996), AL_R(0.65723),
    AL_R(0.631668), AL_R(0.593291), AL_R(0.54032), AL_R(0.493948), AL_R(0.444552),
    AL_R(0.377421), AL_R(0.302859), AL_R(0.226618), AL_R(0.148135), AL_R(0.0923036),
    AL_R(0.0528959), AL_R(0.02535), AL_R(0.0425545), AL_R(0.00719891), AL_R(5.992e-18) AL_ARRAY_END;
const real AL_PMF_T_LRHO1[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(-1.67953), AL_R(-1.67953), AL_R(-1.65662), AL_R(-1.63358), AL_R(-1.63161),
    AL_R(-1.54604), AL_R(-1.42358), AL_R(-1.24487), AL_R(-1.09074), AL_R(-0.936407),
    AL_R(-0.734441), AL_R(-0.498379), AL_R(-0.231692), AL_R(0.0969459), AL_R(0.413191),
    AL_R(0.751091), AL_R(1.16265), AL_R(1.06413), AL_R(2.24055), AL_R(2.24055) AL_ARRAY_END;
const real AL_PMF_T_W1[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(0.263778), AL_R(0.263778), AL_R(0.26754), AL_R(0.270103), AL_R(0.271648),
    AL_R(0.290921), AL_R(0.31833), AL_R(0.350597), AL_R(0.375262), AL_R(0.399276),
    AL_R(0.423098), AL_R(0.434031), AL_R(0.423806), AL_R(0.38043), AL_R(0.313714),
    AL_R(0.232944), AL_R(0.145889), AL_R(0.22399), AL_R(0.0896557), AL_R(1.63567e-17) AL_ARRAY_END;
const real AL_PMF_T_LRHO2[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(-3.4485), AL_R(-3.4485), AL_R(-3.42171), AL_R(-3.40486), AL_R(-3.41756),
    AL_R(-3.35456), AL_R(-3.22417), AL_R(-3.00463), AL_R(-2.80907), AL_R(-2.63047),
    AL_R(-2.36834), AL_R(-2.02637), AL_R(-1.63487), AL_R(-1.1617), AL_R(-0.71462),
    AL_R(-0.252562), AL_R(0.275119), AL_R(0.263749), AL_R(1.53217), AL_R(1.53217) AL_ARRAY_END;
const real AL_PMF_T_W2[20] = AL_ARRAY_BEGIN(real, 20)
    AL_R(0.0612715), AL_R(0.0612715), AL_R(0.0629058), AL_R(0.0647461), AL_R(0.0638327),
    AL_R(0.0696675), AL_R(0.0782986), AL_R(0.0938816), AL_R(0.110763), AL_R(0.129794),
    AL_R(0.155657), AL_R(0.187496), AL_R(0.225361), AL_R(0.267699), AL_R(0.29079),
    AL_R(0.291393), AL_R(0.266186), AL_R(0.011236), AL_R(0.00065986), AL_R(2.89768e-17) AL_ARRAY_END;
#endif

#ifdef AL_PMF_TAB
// The fitted mixture at alpha: exponents N_j = rho_j (2/alpha^2 - 2) (>= 1) and
// weights w_j, interpolated linearly in log alpha (log rho_j, w_j) between the
// table's nodes, clamped at its ends; c0 = 1 - sum w_j.
AlMix al_mix_fitted(real alpha) {
    real t = al_log(alpha);
    int i = 0;
    for (int k = 1; k < AL_PMF_TAB - 1; ++k) {
        if (t >= AL_PMF_T_LOGA[k]) i = k;
    }
    real f = clamp((t - AL_PMF_T_LOGA[i]) / (AL_PMF_T_LOGA[i + 1] - AL_PMF_T_LOGA[i]),
                   AL_R(0.0), AL_R(1.0));
    real nb = AL_R(2.0) / (alpha * alpha) - AL_R(2.0);
    AlMix x;
    rvec3 lr = mix(rvec3(AL_PMF_T_LRHO0[i], AL_PMF_T_LRHO1[i], AL_PMF_T_LRHO2[i]),
                   rvec3(AL_PMF_T_LRHO0[i + 1], AL_PMF_T_LRHO1[i + 1], AL_PMF_T_LRHO2[i + 1]), f);
    x.N = nb * rvec3(al_exp(lr.x), al_exp(lr.y), al_exp(lr.z));
    x.w = mix(rvec3(AL_PMF_T_W0[i], AL_PMF_T_W1[i], AL_PMF_T_W2[i]),
              rvec3(AL_PMF_T_W0[i + 1], AL_PMF_T_W1[i + 1], AL_PMF_T_W2[i + 1]), f);
    x.N = max(x.N, rvec3(AL_PMF_N_MIN));
    x.c0 = AL_R(1.0) - x.w.x - x.w.y - x.w.z;
    return x;
}
#endif

AlMix al_mix_make(AlDist d) {
#ifdef AL_PMF_TAB
    return al_mix_fitted(d.param);
#else
    AlMix x;
    x.c0 = AL_R(0.0);
    x.N = rvec3(AL_R(1.0));
    x.w = rvec3(AL_R(0.0));
#if defined(AL_DIST_BLINN)
    x.N.x = d.param;  // eq. 23
    x.w.x = AL_R(1.0);
#elif defined(AL_DIST_BECKMANN)
    x.N.x = AL_R(2.0) / d.alpha2 - AL_R(2.0);  // eq. 25
    x.w.x = AL_R(1.0);
#else
    // eq. 26: n1 = 2/alpha^2 - 2, n2 = n1/10, c1 = 0.7 (1 - alpha^2), c2 = 0.3 (1 - alpha^2),
    // c0 = alpha^2.
    x.N.x = AL_R(2.0) / d.alpha2 - AL_R(2.0);
    x.N.y = AL_R(0.1) * x.N.x;
    x.w.x = AL_R(0.7) * (AL_R(1.0) - d.alpha2);
    x.w.y = AL_R(0.3) * (AL_R(1.0) - d.alpha2);
    x.c0 = d.alpha2;
#endif
    // A lobe of exponent N < 1 is replaced by the lobe of exponent 1 with weight N plus
    // the constant 1/pi with weight 1 - N: both normalized, and equal to
    // (N+2)/(2 pi) c^N at the peak and at N = 0 and 1.
    for (int j = 0; j < AL_PMF_LOBES; ++j) {
        if (x.N[j] < AL_PMF_N_MIN) {
            real f = max(x.N[j], AL_R(0.0)) / AL_PMF_N_MIN;
            x.c0 += x.w[j] * (AL_R(1.0) - f);
            x.w[j] *= f;
            x.N[j] = AL_PMF_N_MIN;
        }
    }
    return x;
#endif
}

// The model's D at n.h = c (for the normalization test; the shader integrates it
// through the moments).
real al_mix_ndf(AlMix x, real c) {
    real D = x.c0 / AL_PI;
    for (int j = 0; j < AL_PMF_LOBES; ++j)
        D += x.w[j] * (x.N[j] + AL_R(2.0)) / AL_TWO_PI *
             al_exp(x.N[j] * al_log(max(c, AL_R(1e-30))));
    return D;
}

// ---- The accumulator ----------------------------------------------------------------

struct AlMoments {
    rvec3 n, v, r;
    rvec3 e1, e2;  // a tangent frame of n
    real nv, lv, f0;
    AlDist d;
    AlMix mix;
    bool specular_on;
    // Per lobe, the h-polygon's moment about n by method/phong_boundary.glsl's boundary sums
    // (r := n), and the slivers' share (fit=tuned).
    rvec3 sums;
    // The azimuth about n each lobe's far-form arcs sweep (and its absolute total), and
    // every arc's (the near-form arcs' sweeps are the difference).
    rvec3 sweep_far, size_far;
    real sweep_all, size_all;
    rvec3 sliver;
    real omega_h;  // solid angle of the h-polygon (and its slivers)
    // The h-polygon's boundary point closest to n (max n.h).
    rvec3 h_close;
    real c_close;
    // The lit region's solid angle and vector irradiance (factor=blend).
    real omega;
    rvec3 irr;
};

AlMoments al_mf_begin(rvec3 n, rvec3 v, rvec3 r, real param, real f0, bool direct) {
    AlMoments M;
    M.n = n;
    M.v = v;
    M.r = r;
    M.nv = dot(n, v);
    al_tangent_frame(n, M.e1, M.e2);
    M.d = al_dist_make(param);
    M.mix = al_mix_make(M.d);
    M.specular_on = M.nv > AL_R(0.0);
    rvec3 nxv = cross(n, v);
    M.lv = M.specular_on ? al_smith_lambda(M.d, M.nv, dot(nxv, nxv)) : AL_R(0.0);
    M.f0 = f0;
    M.sums = rvec3(AL_R(0.0));
    M.sweep_far = rvec3(AL_R(0.0));
    M.size_far = rvec3(AL_R(0.0));
    M.sweep_all = AL_R(0.0);
    M.size_all = AL_R(0.0);
    M.sliver = rvec3(AL_R(0.0));
    M.omega_h = AL_R(0.0);
    M.h_close = n;
    M.c_close = -AL_R(1.0);
    M.omega = AL_R(0.0);
    M.irr = rvec3(AL_R(0.0));
    return M;
}

// Signed solid angle of the spherical triangle (n, p, q) (Van Oosterom and Strackee),
// given pxq = p x q: summed over a closed boundary it is the enclosed solid angle.
real al_fan_angle(rvec3 n, rvec3 p, rvec3 q, rvec3 pxq) {
    return AL_R(2.0) * al_atan2(dot(n, pxq), AL_R(1.0) + dot(n, p) + dot(n, q) + dot(p, q));
}

// The half vector of a lit direction. n.h > 0 whenever n.v > 0; for n.v <= 0
// (specular 0, ndf outside the method's range) h is projected onto n's horizon.
rvec3 al_pmf_half(AlMoments M, rvec3 w) {
    rvec3 h = normalize(w + M.v);
    real nh = dot(M.n, h);
    if (nh < AL_R(0.0)) {
        rvec3 t = h - nh * M.n;
        real len = length(t);
        h = len > AL_R(1e-12) ? t / len : M.e1;
    }
    return h;
}

// The far/near choice of al_edge_frame for exponent N (log_x_max: al_arc_log_x_max, once
// per arc, not per lobe).
bool al_pmf_far(AlEdgeFrame E, real log_x_max, real N) {
#ifdef AL_FIT_PAPER
    return false;  // the paper fits the near form everywhere
#else
    return al_arc_far(E, log_x_max, N, AL_PEAK_LOG_FAR);
#endif
}

#ifndef AL_FIT_PAPER
// erfc(|x|).
real al_pmf_erfc_abs(real x) {
    return al_erfcx_fast(abs(x)) * al_exp(-x * x);
}

// The sliver between a chord [ta, tb] (arc angle from the foot of n, c = n.foot) and
// the true h-image, whose offset from the chord's circle is taken as the parabola
// 4 d_mid (t - ta)(tb - t) / (tb - ta)^2 through the image of the piece's midpoint:
// P = int x^N (t - ta)(tb - t) dt with x^N = (c cos t)^N ~ c^N exp(-t^2 / (2 sigma^2)),
// sigma^2 = 1 / (N + 1/4) (cos^N's half width to ~1% for every N >= 1). Chords longer
// than 2 sigma: the truncated Gaussian's moments I0, I1, I2 in closed form (erfc);
// shorter ones, where those cancel, a 2-point Gauss rule of (1 - u^2) x^N over the
// chord (exact for x^N linear on it). lc = log c.
real al_pmf_sliver(real lc, real N, real ta, real tb) {
    real sigma2 = AL_R(1.0) / (N + AL_R(0.25));
    real k2 = AL_R(0.5) / sigma2;  // 1 / (2 sigma^2)
    real half_len = AL_R(0.5) * (tb - ta), mid = AL_R(0.5) * (ta + tb);
    if (half_len * half_len < sigma2) {
        real d = half_len * AL_R(0.57735026918962576451);
        real g = al_exp(N * lc - k2 * (mid - d) * (mid - d)) +
                 al_exp(N * lc - k2 * (mid + d) * (mid + d));
        return half_len * half_len * half_len * g * AL_R(0.66666666666666666667);
    }
    real k = sqrt(k2);  // 1 / (sigma sqrt 2)
    real ua = ta * k, ub = tb * k;
    real cn = al_exp(N * lc);
    real ea = al_pmf_erfc_abs(ua), eb = al_pmf_erfc_abs(ub);
    real erf_ab = ua >= AL_R(0.0) ? ea - eb : (ub <= AL_R(0.0) ? eb - ea : AL_R(2.0) - ea - eb);
    real i0 = cn * AL_R(1.25331413731550025121) * sqrt(sigma2) * erf_ab;  // sqrt(pi/2) sigma
    real ga = cn * al_exp(-ua * ua), gb = cn * al_exp(-ub * ub);
    real i1 = sigma2 * (ga - gb);
    real i2 = sigma2 * (i0 + ta * ga - tb * gb);
    return max(-i2 + (ta + tb) * i1 - ta * tb * i0, AL_R(0.0));
}
#endif

// One great-circle arc p -> q of the h-polygon (n.p, n.q >= 0), with the true image h_mid
// of its piece's midpoint: the azimuth it sweeps about n, each lobe's boundary terms
// (method/phong_boundary.glsl's al_moments_arc with r := n and the lobe's exponent; only
// the moment's T_(N+1) term), the slivers, the solid-angle fan and the closest approach
// to n.
void al_pmf_h_arc(AL_INOUT(AlMoments) M, rvec3 p, rvec3 q, rvec3 h_mid) {
    // p x q as p x (q - p): q - p is exact for ends this close (Sterbenz), so a short chord's
    // normal keeps its digits (from p x q it lost ~ulp / |p x q| of them: 3e-5 relative on the
    // 2e-3 rad chords of a small sphere's h-image, 6e-4 rad in their sweeps about n).
    rvec3 pxq = cross(p, q - p);
    real len = length(pxq);
    M.omega_h += al_fan_angle(M.n, p, q, pxq);
    bool degenerate = !(len > AL_R(1e-7));
    rvec3 m = degenerate ? M.n : pxq / len;
    AlEdgeFrame E = al_edge_frame(p, q, m, M.n, M.mix.N.x, AL_PEAK_LOG_FAR);
    // Closest approach: the foot of n on the arc's circle if the arc holds it.
    bool holds = !degenerate && E.ag <= AL_R(0.0) && E.bg >= AL_R(0.0);
    rvec3 close = holds ? normalize(M.n - E.rm * m) : (dot(M.n, p) >= dot(M.n, q) ? p : q);
    real cc = dot(M.n, close);
    if (cc > M.c_close) {
        M.c_close = cc;
        M.h_close = close;
    }
    AlArcShared S = al_arc_shared(E);
    real log_x_max = al_arc_log_x_max(E);
    // The sweep about n, int (n.m) dtau / (1 - x^2) over the arc, from the frame its edge
    // integrals use: atan(tan tau / (n.m)) between the ends, as one atan2 (af, bf >= 0: the
    // arc lies in n's hemisphere). Differences of the ends' azimuths about n telescoped
    // exactly, but at h = n (r exactly through a vertex of the light) an end's azimuth is
    // rounding noise, and a chord with both ends there, whose normal is noise too, could
    // count as a far arc with an O(1) sweep: ndf 0 to 4x the oracle's on such cases. Formed
    // from the arc's own n.m, its sweep is the one its edge terms cancel, whatever rounding
    // makes of the chord, and a far arc's sweep less its far-form term is the near form's
    // term. al_mf_end finds the winding number from the total.
    real sweep = al_atan2(E.rm * (E.af * E.bg - E.ag * E.bf), E.rm * E.rm * E.af * E.bf + E.ag * E.bg);
#ifndef AL_FIT_PAPER
    real ta = S.ta, dtau = S.dtau;
    // Sliver offset d_mid / (L/2)^2 (inward positive: the true region is smaller).
    real bend = degenerate ? AL_R(0.0) : AL_R(4.0) * dot(m, h_mid) / max(dtau * dtau, AL_R(1e-30));
    real lc = S.lc;
    M.omega_h -= bend * dtau * dtau * dtau / AL_R(6.0);
#endif
    M.sweep_all += sweep;
    M.size_all += abs(sweep);
    // Each lobe's terms go to its component through a one-hot vector: a write to v[j] with j
    // the loop's counter became a select per component and per vector, which ACO's model
    // charges at the lobe loop's weight; and only the far-form sweeps are kept per lobe
    // (the near ones are the totals less them; with al_peak_sample's one quotient, ggx pearson
    // 25 601 -> 24 793). A non-finite term in one lobe was already a non-finite ndf, so the
    // zeros' products with it change nothing.
    AL_PMF_LOBE_LOOP for (int j = 0; j < AL_PMF_LOBES; ++j) {
        rvec3 one_hot = rvec3(j == 0 ? AL_R(1.0) : AL_R(0.0), j == 1 ? AL_R(1.0) : AL_R(0.0),
                              j == 2 ? AL_R(1.0) : AL_R(0.0));
        real N = M.mix.N[j];
        bool far_edge = !degenerate && al_pmf_far(E, log_x_max, N);
        real t1 = degenerate ? AL_R(0.0) : al_peak_edge_term(E, S, N + AL_R(1.0), far_edge);
        M.sums += one_hot * ((far_edge ? AL_R(1.0) : -AL_R(1.0)) * E.rm * t1);
        real sweep_far = far_edge ? sweep : AL_R(0.0);
        M.sweep_far += one_hot * sweep_far;
        M.size_far += one_hot * abs(sweep_far);
#ifndef AL_FIT_PAPER
        if (bend != AL_R(0.0)) M.sliver -= one_hot * (bend * al_pmf_sliver(lc, N, ta, ta + dtau));
#endif
    }
}

// One arc a -> b of the lit region (light/polygon.glsl; inward unit normal m). Its split
// points are mapped to half vectors, and consecutive ones joined by great-circle
// arcs of the h-polygon. Algorithm 1's point is the foot of r (the preimage of n:
// h = n exactly when w = r) on the arc's great circle, where it lies inside the arc
// (split=single); split=halved also splits each piece at its midpoint (at most 3
// splits); split=none keeps the arc whole.
void al_moments_arc(AL_INOUT(AlMoments) M, rvec3 a, rvec3 b, rvec3 m, rvec3 axis, rvec3 n,
                    real N) {
#ifdef AL_FACTOR_BLEND
    // The lit region's solid angle (fan from n) and vector irradiance (sum arc m / 2).
    rvec3 axb = cross(a, b);
    M.omega += al_fan_angle(M.n, a, b, axb);
    M.irr += AL_R(0.5) * al_atan2(dot(axb, m), dot(a, b)) * m;
#endif
    // No split point where r is within 1e-4 of the arc's pole (the horizon's arc under v = n,
    // whose image keeps one distance from n): the foot's direction is rounding's there, and
    // which pieces the arc fell into differed between the backends (a wide lobe across the
    // horizon: 0.017 on the CPU mirror, 0.020 on lavapipe, against 0.012).
    rvec3 foot = M.r - dot(M.r, m) * m;
    real foot_len = length(foot);
    rvec3 fp = foot_len > AL_R(1e-4) ? foot / foot_len : a;
    bool inside = foot_len > AL_R(1e-4) && dot(cross(a, fp), m) > AL_R(0.0) &&
                  dot(cross(fp, b), m) > AL_R(0.0);
#if defined(AL_SPLIT_HALVED)
    int pieces = inside ? 4 : 2;
#elif defined(AL_SPLIT_SINGLE)
    int pieces = inside ? 2 : 1;
#else
    int pieces = 1;
#endif
    rvec3 w_prev = a;
    rvec3 h_prev = al_pmf_half(M, a);
    for (int j = 1; j <= 4; ++j) {
        if (j > pieces) break;
        // End point of piece j.
        rvec3 w = b;
        if (j < pieces) {
#if defined(AL_SPLIT_HALVED)
            if (!inside) w = normalize(a + b);
            else if (j == 2) w = fp;
            else w = normalize(j == 1 ? a + fp : fp + b);
#else
            w = fp;
#endif
        }
        rvec3 h = al_pmf_half(M, w);
#ifdef AL_FIT_PAPER
        rvec3 h_mid = h;
#else
        rvec3 h_mid = al_pmf_half(M, normalize(w_prev + w));
#endif
        al_pmf_h_arc(M, h_prev, h, h_mid);
        w_prev = w;
        h_prev = h;
    }
}

// G2(w, v) max(h.v, 0) of a unit h, from hv = h.v and nh = n.h: w = 2 (h.v) h - v is a unit
// vector with n.w = 2 hv nh - n.v, so |n x w|^2 = (1 - n.w)(1 + n.w). The factor W of
// al_mf_end is this times F(h.v) / (n.v).
real al_pmf_g2_hv(AlMoments M, real hv, real nh) {
    real nw = AL_R(2.0) * hv * nh - M.nv;
    real lw = al_smith_lambda(M.d, max(nw, AL_R(0.0)), (AL_R(1.0) - nw) * (AL_R(1.0) + nw));
    return al_smith_g2(lw, M.lv) * max(hv, AL_R(0.0));
}

#ifdef AL_PMF_SPREAD
// W = G2 (h.v) F / (n.v) averaged over four points hs +- sqrt(2) s t1, t2 (t1 towards n)
// for one component of D of width^2 m2 (m2 < 0: unbounded, the constant): the spread
// s^2 = 1 / (4 pi / Omega_h + 2 / m2) of its D-weighted h-region (the h-polygon's size and
// the width, whichever is smaller), shrunk within ~3 degrees of grazing views, where
// W ~ 1/(n.v) is not smooth on the lobe's scale. Points whose w falls below the horizon
// count with W = 0 (G2 = 0 there). Measured and not taken: W continued as an odd function
// of n.w below the horizon (exact where W is linear across it): public horizon set
// specular p95 9.8e-2 -> 7.7e-2 (pearson) but relL2 1.6e-2 -> 1.9e-2, and disk horizon
// 6.1e-2 -> 0.19 (lobes the horizon cuts, whose D-weighted W it underestimates).
real al_pmf_w_spread(AlMoments M, rvec3 hs, real m2) {
    real nv2 = M.nv * M.nv;
    real omega = max(M.omega_h, AL_R(0.0));
    real inv_m2 = m2 > AL_R(0.0) ? AL_R(2.0) / m2 : AL_R(0.0);
    real s2 = nv2 * omega / max((nv2 + AL_PMF_GRAZING2) * (AL_R(4.0) * AL_PI + inv_m2 * omega),
                                AL_R(1e-30));
    real off2 = AL_R(2.0) * s2;
    // The points h = (h* + off t) / |h* + off t| for unit t orthogonal to h*, |h* + off t|^2 =
    // 1 + off^2: t1 = (n - (n.h*) h*) / L and t2 = (h* x n) / L, L = |h* x n|, so n.t1 = L,
    // n.t2 = 0, v.t1 = (n.v - (n.h*)(h*.v)) / L; near h* = n, t1 along v's tangent part and
    // t2 across it (v.t2 = 0).
    real k = inversesqrt(AL_R(1.0) + off2);
    real hv0 = dot(hs, M.v), nh0 = dot(hs, M.n);
    real hv = hv0 * k, nh = nh0 * k;
    k *= sqrt(off2);
    rvec3 c = cross(hs, M.n);
    real L = length(c);
    bool framed = L > AL_R(1e-6);
    real kl = k / max(L, AL_R(1e-6));
    real dn1 = framed ? k * L : AL_R(0.0);
    real dv1 = framed ? kl * (M.nv - nh0 * hv0) : k * sqrt(max((AL_R(1.0) - M.nv) * (AL_R(1.0) + M.nv), AL_R(0.0)));
    real dv2 = framed ? kl * dot(c, M.v) : AL_R(0.0);
    // F at h* alone: it varies over the spread far less than G2 (h.v) does.
    return (al_pmf_g2_hv(M, hv + dv1, nh + dn1) + al_pmf_g2_hv(M, hv - dv1, nh - dn1) +
            al_pmf_g2_hv(M, hv + dv2, nh) + al_pmf_g2_hv(M, hv - dv2, nh)) *
           al_schlick(M.f0, hv0) / (AL_R(4.0) * M.nv);
}
#endif

// (specular, ndf): the model's moments over the h-polygon, and specular as ndf times
// W = G2(w*, v) (h*.v)/(n.v) F(h*.v) at one representative half vector h* (GGX: its mean
// over four points about h*).
rvec2 al_mf_end(AlMoments M) {
    real ndf_c = M.mix.c0 * M.omega_h / AL_PI;
    real ndf = ndf_c;
    rvec3 ndf_j = rvec3(AL_R(0.0));
    for (int j = 0; j < AL_PMF_LOBES; ++j) {
        real size_near = M.size_all - M.size_far[j], sweep_near = M.sweep_all - M.sweep_far[j];
        real winding = al_winding(M.sweep_all, sweep_near, M.sweep_far[j], size_near,
                                  M.size_far[j]);  // about n (method/phong_edge.glsl)
        real N = M.mix.N[j];
        // w_j (N+2)/(2 pi) int (n.h)^N dh: (N+1)/(2 pi) int = (winding - sums) / (2 pi).
        ndf_j[j] = M.mix.w[j] * (N + AL_R(2.0)) / AL_TWO_PI *
                   ((winding - M.sums[j]) / (N + AL_R(1.0)) + M.sliver[j]);
        ndf += ndf_j[j];
    }
    ndf = max(ndf, AL_R(0.0));
    if (!M.specular_on) return rvec2(AL_R(0.0), ndf);
    // n inside the h-polygon (its sweeps total 2 pi): h* = n.
    bool n_inside = abs(M.sweep_all) > AL_PI;
    rvec3 hs = n_inside ? M.n : M.h_close;
#ifdef AL_FACTOR_BLEND
    // The blend's weight of the lobe's point against the light's (header: factor).
    real m2 = M.d.width * M.d.width;
    real beta = M.omega / max(M.omega + AL_R(4.0) * AL_PI * m2, AL_R(1e-30));
#endif
#if !defined(AL_FIT_PAPER) && defined(AL_FACTOR_BLEND)
    // Grazing views, the lobe's peak lit (n in the h-polygon): the horizon n.w = 0 cuts the
    // lobe at slope x_c = -n.v / (1 + sin theta_v) from n, away from v, within a hair of its
    // peak, and the lit half's half vectors lean towards v, where W ~ (h.v)/(n.v) is many
    // times W(n). h* moves to the lit half's mean slope: GGX's slope marginal
    // (1 + x^2/alpha^2)^(-3/2) cut to x >= x_c has mean alpha / (sqrt(1 + u0^2) - u0), u0 =
    // x_c / alpha; Beckmann's (and Blinn's, width m) Gaussian of deviation m / sqrt(2) has
    // sigma phi(z) / Q(z), z = x_c / sigma. Weighted by g = 0.05^2 / (0.05^2 + n.v^2) (1 at
    // grazing; GGX's spread below takes over as n.v grows) and by beta, the blend's weight
    // of the lobe against the light. Measured on 300 seeded hard cases each
    // (scripts/gen_microfacet_cases.py 900 11 X --kind hard), pearson specular relL2: ggx
    // 0.14 -> 6.3e-2 (with the spread), beckmann 0.15 -> 8.7e-2, blinn 0.18 -> 0.16; public
    // stress sets: blinn disk 0.31 -> 2.4e-2, sphere 0.59 -> 0.32, beckmann lorentz polygon
    // 9.9e-2 -> 0.13 (one case); the other public cells within 5%. Cost +41 cycles a wave
    // (blinn, beckmann).
    if (n_inside) {
        rvec3 tv = M.v - M.nv * M.n;
        real sv = length(tv);
#ifdef AL_DIST_GGX
        real u0 = -M.nv / ((AL_R(1.0) + sv) * M.d.width);
        real xbar = M.d.width / (sqrt(AL_R(1.0) + u0 * u0) - u0);
#else
        real sig = AL_R(0.70710678118654752) * M.d.width;
        real z = -M.nv / ((AL_R(1.0) + sv) * sig);
        // z <= 0 (n.v > 0 here): Q(z) = 1 - erfc(|z| / sqrt 2) / 2.
        real q = AL_R(1.0) - AL_R(0.5) * al_pmf_erfc_abs(z * AL_R(0.70710678118654752));
        real xbar = sig * AL_R(0.39894228040143268) * al_exp(-AL_R(0.5) * z * z) / max(q, AL_R(1e-30));
#endif
        real g = AL_PMF_GRAZING2 / (AL_PMF_GRAZING2 + M.nv * M.nv) * beta;
        if (sv > AL_R(1e-7)) hs = normalize(M.n + (g * xbar / sv) * tv);
    }
#endif
#ifdef AL_FACTOR_BLEND
    real irr_len = length(M.irr);
    bool hf_on = irr_len > AL_R(0.0);
    rvec3 hf = hf_on ? normalize(M.irr / max(irr_len, AL_R(1e-30)) + M.v) : hs;
#ifndef AL_PMF_SPREAD
    hs = normalize(beta * hs + (AL_R(1.0) - beta) * hf);
#endif
#endif
#ifdef AL_PMF_SPREAD
    // GGX: each component of the mixture, the three Blinn lobes (width^2 m_j^2 = 2 / (N_j + 2))
    // and the constant (m = infinity: beta 0, the light's point), gets its own blend weight
    // beta_j and its own spread: a wide component's D-weighted half vectors sit about the
    // light's direction and spread over the whole h-region, a narrow one's about the lobe's
    // point (header: factor=blend, GGX). A lobe's beta_j moves back to the distribution's
    // beta by AL_PMF_VIEW2 / (AL_PMF_VIEW2 + (n.v)^2) as views turn grazing, where W ~ 1/(n.v)
    // bends across a wide component's spread; the constant stays at the light's point
    // (pulled too, it measured public stress 2.4e-2 -> 2.9e-2, sphere typical 1.46e-2 ->
    // 1.61e-2).
    real pull = AL_PMF_VIEW2 / (AL_PMF_VIEW2 + M.nv * M.nv);
    real spec = ndf_c * al_pmf_w_spread(M, hf, AL_R(-1.0));
    for (int j = 0; j < AL_PMF_LOBES; ++j) {
        real mj2 = AL_R(2.0) / (M.mix.N[j] + AL_R(2.0));
        real bj = M.omega / max(M.omega + AL_R(4.0) * AL_PI * mj2, AL_R(1e-30));
        bj += (beta - bj) * pull;
        spec += ndf_j[j] * al_pmf_w_spread(M, normalize(bj * hs + (AL_R(1.0) - bj) * hf), mj2);
    }
    return rvec2(max(spec, AL_R(0.0)), ndf);
#else
    real hv = dot(hs, M.v);
    real W = al_pmf_g2_hv(M, hv, dot(hs, M.n)) * al_schlick(M.f0, hv) / M.nv;
    return rvec2(ndf * W, ndf);
#endif
}
