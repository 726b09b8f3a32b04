// Linearly transformed cosines (Heitz, Dupuy, Hill, Neubelt 2016, "Real-time
// polygonal-light shading with linearly transformed cosines") for polygon lights,
// with arealight's own fitted tables (data/ltc/, `arealight fit-ltc`, conventions
// in include/arealight/ltc_table.hpp). The BRDF lobe f (n.w) of a view
// and roughness is approximated by a clamped cosine seen through a 3x3 matrix M:
// its integral over the light is the cosine's over Minv applied to the light, a
// polygon again, integrated by the edge formula (Lambert's), times
// the lobe's magnitude. Domain: every case of CONTRACT.md 2 (n.v <= 0 gives
// specular 0). Error: the fit's (docs/ltc.md, `arealight report`); diffuse is the exact
// Lambert term (fp32 rounding only).
//
// Curved lights (disk, sphere, ellipsoid) take the same lookup, proxy horizon and
// magnitude (al_ltc_lookup, al_ltc_proxy_form, al_ltc_magnitude) with the ellipse's
// own form factor instead of the edge sum (method/ltc_ellipse.glsl); the polygon's parts
// below are compiled for polygons only.
//
// Keys: horizon=clip clips the transformed polygon to z >= 0 exactly; horizon=proxy
// (Hill 2016, "Real-Time Area Lighting: a Journey from Research to Production")
// integrates it unclipped and replaces the clipped form factor by that of a sphere
// with the same vector form factor (a table: the amplitude texture's w).
// edge=acos takes theta / sin(theta) exactly; edge=poly by a quadratic in cos(theta)
// (scripts/fit_edge_poly.py). precision=fp16 computes the edge integrals, the
// clipping and the proxy in half precision (hreal), after the transform in fp32.
// table=fit (GGX) evaluates the coefficients in closed form (templates/method/ltc_ggx_fit.glsl,
// al_ltc_fit_lookup) and the proxy by Snyder's formula: no texture, no sampler.
// GPU cost (navi21, `arealight gpu-cost`, the validation kernel; with the flat horizon's
// crossing, al_ltc_horizon_arc, 2026-12-07): GGX polygon default 1 078 (2.16x its point
// light's 498; 3 024 instructions, 96 VGPRs); table=fit 2 005 (4.03x; 3 898 instructions).
// The two-lobe tables' second edge sum: blinn / beckmann / phong polygon 1 203 / 1 200 /
// 1 201 (2.10x / 2.17x / 2.63x; one lobe, before the albedo
// ceiling and the clip to n's horizon, 949 / 945 / 947); their disk, sphere and ellipsoid
// +29-31% with horizon=clip, +19-21% with proxy (before the clip to n's horizon).

// Two lobes (include/arealight/ltc_table.hpp, fit/ltc_fit.cpp): a transformed clamped
// cosine has a power-law tail, as GGX's lobe has, while the Phong, Blinn and Beckmann
// lobes' tails are Gaussian; one LTC cannot fit their core and tail together (the fit's
// error 0.03-0.05 against GGX's 0.005). Their tables hold the LTC of the kernel
// D_o + K D_s, D_s the clamped cosine s = 1.2 times wider (K ~ -0.75: a sharpened
// cosine): its integral over a region is the LTC's plus K times that of the region under
// diag(1 / s, 1 / s, 1) Minv, the same transformed vertices with x and y over s; the
// clipping to z >= 0 is the same. K is the amplitude texture's z.
#ifndef AL_DIST_GGX
#define AL_LTC_TWO_LOBES
// The map diag(1 / s, 1 / s, 1), s = kLtcSecondLobeWidth.
const rvec3 AL_LTC_SECOND = rvec3(AL_R(0.83333333333333333), AL_R(0.83333333333333333), AL_R(1.0));
#endif

// Grid of the tables (include/arealight/ltc_table.hpp, ltc_rho_range in
// fit/ltc_table.cpp): 64 x 64 cells; rho = sqrt(alpha) (beckmann: alpha^(1/3)) spans the
// contract's parameter range (alpha in [0.001, 1]; phong and blinn through
// alpha = sqrt(2 / (N + 2)) for N in [1, 1e5]).
const real AL_LTC_SIZE = AL_R(64.0);
#if defined(AL_DIST_PHONG) || defined(AL_DIST_BLINN)
const real AL_LTC_RHO_MIN = AL_R(0.0668736961);  // (2 / 100002)^(1/4)
const real AL_LTC_RHO_MAX = AL_R(0.9036020036);  // (2 / 3)^(1/4)
#elif defined(AL_DIST_BECKMANN)
const real AL_LTC_RHO_MIN = AL_R(0.1);  // 0.001^(1/3)
const real AL_LTC_RHO_MAX = AL_R(1.0);
#else
const real AL_LTC_RHO_MIN = AL_R(0.0316227766);  // sqrt(0.001)
const real AL_LTC_RHO_MAX = AL_R(1.0);
#endif

#ifdef AL_LANG_CPP
// Compute shaders have no derivatives: GLSL samples with an explicit LOD; the
// mirror's sampler has one level.
vec4 textureLod(const AlSampler2D& s, vec2 uv, float) { return texture(s, uv); }
#endif

// The table's roughness axis alpha of a case's parameter (phong and blinn: the lobe width
// sqrt(2 / (N + 2)) that stands for alpha; include/arealight/ltc_table.hpp). Exact.
real al_ltc_alpha(real param) {
#if defined(AL_DIST_PHONG) || defined(AL_DIST_BLINN)
    return sqrt(AL_R(2.0) / (param + AL_R(2.0)));
#else
    return param;
#endif
}

// The table's axis rho of alpha (ltc_axis_power in include/arealight/ltc_table.hpp). Domain
// alpha >= 0; fp32 pow's error (a few ulp) is far below a column's width.
real al_ltc_rho(real alpha) {
#ifdef AL_DIST_BECKMANN
    // Cube root: Beckmann's alphas reach 0.001, where sqrt's columns step 2.2x in alpha and
    // bilinear filtering between them loses the lobe's width (fit/ltc_fit.cpp).
    return pow(max(alpha, AL_R(1e-9)), AL_R(0.33333333333333333));
#else
    return sqrt(alpha);
#endif
}

// Its inverse, alpha of rho (ltc_alpha_of_rho in include/arealight/ltc_table.hpp), a macro so
// that the axis's constant bounds fold: the GGX-only paths (table=fit's coordinate, the
// alpha-scaled divisor) use both.
#ifdef AL_DIST_BECKMANN
#define AL_LTC_ALPHA_OF_RHO(rho) ((rho) * (rho) * (rho))
#else
#define AL_LTC_ALPHA_OF_RHO(rho) ((rho) * (rho))
#endif

// Texture coordinates of (rho, cos theta_v): texel centres are the fitted cells.
vec2 al_ltc_uv(real param, real nv, real sin_v) {
    real rho = al_ltc_rho(al_ltc_alpha(param));
    real u = clamp((rho - AL_LTC_RHO_MIN) / (AL_LTC_RHO_MAX - AL_LTC_RHO_MIN), AL_R(0.0),
                   AL_R(1.0));
    // sqrt(1 - cos) from the sine where the view is within 90 degrees of n: near n,
    // 1 - n.v keeps only fp32's rounding of n.v (a view 3.4e-4 rad off n per ulp), the
    // sine keeps its own digits.
    real w = nv > AL_R(0.0) ? min(sin_v * inversesqrt(AL_R(1.0) + nv), AL_R(1.0))
                            : sqrt(clamp(AL_R(1.0) - nv, AL_R(0.0), AL_R(1.0)));
    return vec2((rvec2(u, w) * (AL_LTC_SIZE - AL_R(1.0)) + AL_R(0.5)) / AL_LTC_SIZE);
}

// The angle atan2(s, x) in [0, pi] for s >= 0, by one quotient t = min / max in
// [0, 1] and Abramowitz & Stegun 4.4.49's odd polynomial for atan t (|error| <= 2e-8,
// below fp32's half ulp of the result; relative 1.8e-8, also for small t). Cheaper than
// common/common.glsl's al_atan2 (no reduction quotient), which the LTC's edges (9 per
// polygon, twice) would spend most of their time in.
real al_ltc_angle(real s, real x) {
    real ax = abs(x);
    real t = min(s, ax) / max(max(s, ax), AL_R(1e-30));
    real z = t * t;
    real p = AL_R(0.0028662257);
    p = p * z - AL_R(0.0161657367);
    p = p * z + AL_R(0.0429096138);
    p = p * z - AL_R(0.0752896400);
    p = p * z + AL_R(0.1065626393);
    p = p * z - AL_R(0.1420889944);
    p = p * z + AL_R(0.1999355085);
    p = p * z - AL_R(0.3333314528);
    p = (p * z + AL_R(1.0)) * t;
    real r = s <= ax ? p : AL_HALF_PI - p;
    return x < AL_R(0.0) ? AL_PI - r : r;
}

// theta / sin(theta) of the arc between a and b, from x = a.b and m = a x b, in
// the LTC's arithmetic (hreal) and by the edge key; a and b unit for poly (x is the
// cosine), any lengths for acos (theta / |m| then absorbs them). poly: the quadratic p(x) =
// c2 x^2 + c1 x + c0 with p(1) = 1, largest relative error 5.2e-3 on [0, 1] (the mobile LTC article
// prints 0.33735186 x^2 - 0.89665001 x + pi/2: 1.15e-2, and 1.15% too large on every
// small edge); for x < 0, theta / sin = pi / sin - p(|x|) with sin = |m| (the article forms
// sqrt(1 - x^2), which cancels in fp16 as the edge nears a half circle), floored at
// fp16's smallest normal.
hreal al_edge_factor(hreal x, hvec3 m) {
#ifdef AL_EDGE_POLY
    hreal y = abs(x);
    hreal p = (hreal(0.28515792) * y + hreal(-0.84773167)) * y + hreal(1.56257375);
    return x >= hreal(0.0) ? p : hreal(3.14159265) / max(length(m), hreal(6.2e-5)) - p;
#else
    hreal s = length(m);
    return s > hreal(0.0) ? hreal(al_ltc_angle(float(s), float(x))) / s : hreal(1.0);
#endif
}

// Unit vectors where the LTC's edge integral needs them: poly (x = cos theta) and
// fp16 (its range); the exact acos form is scale-free.
#if defined(AL_EDGE_POLY) || defined(AL_PRECISION_FP16)
#define AL_LTC_UNIT(x) normalize(x)
#else
#define AL_LTC_UNIT(x) (x)
#endif

// The edge's share of the vector form factor times 2 pi (its z is the form factor's).
hvec3 al_edge_ltc(hvec3 a, hvec3 b) {
    hvec3 m = cross(a, b);
    return m * al_edge_factor(dot(a, b), m);
}

#ifdef AL_DIST_GGX
// Schlick's (1 - h.v)^5 for the direction w (any length, in the local frame) and the
// view (sv, 0, nv): h.v = sqrt((1 + w.v / |w|) / 2). -1 when w is 0 (no direction).
real al_ltc_schlick_weight(rvec3 w, real sv, real nv) {
    real len = length(w);
    if (!(len > AL_R(0.0))) return -AL_R(1.0);
    real hv = sqrt(max(AL_R(0.5) + AL_R(0.5) * (w.x * sv + w.z * nv) / len, AL_R(0.0)));
    real t = AL_R(1.0) - hv, t2 = t * t;
    return t2 * t2 * t;
}
#endif

// One edge a -> b of a polygon clipped to z >= 0, streamed (the clipped polygon is
// never stored; light/polygon.glsl does the same for the exact methods): adds the edge's
// clipped part to `sum` and records where the boundary leaves (exit) and re-enters
// (entry) the upper half space; the closing arc exit -> entry along the horizon is
// added after the loop. The crossing is taken on the chord (planes through the
// origin keep their sides under projection); it is made unit only where the edge
// integral needs unit vectors (al_edge_factor), as a and b then are.
void al_ltc_clip_edge(hvec3 a, hvec3 b, AL_INOUT(hvec3) sum, AL_INOUT(hvec3) exit_pt,
                      AL_INOUT(hvec3) entry_pt, AL_INOUT(bool) has_exit) {
    bool ia = a.z >= hreal(0.0), ib = b.z >= hreal(0.0);
    if (!ia && !ib) return;
    hvec3 q = a;
    if (ia != ib) q = AL_LTC_UNIT((a.z * b - b.z * a) / (a.z - b.z));
    sum += al_edge_ltc(ia ? a : q, ib ? b : q);
    if (ia && !ib) {
        exit_pt = q;
        has_exit = true;
    }
    if (!ia && ib) entry_pt = q;
}

#ifndef AL_LIGHT_CURVED
// One lobe's sums over a polygon, edge by edge (al_shade): its vector form factor times
// 2 pi and, with horizon=clip, where the boundary leaves and re-enters z >= 0.
struct AlLtcSum {
    hvec3 ff;
    hvec3 exit_pt;
    hvec3 entry_pt;
    bool has_exit;
};

AlLtcSum al_ltc_sum_init() {
    AlLtcSum s;
    s.ff = hvec3(0.0);
    s.exit_pt = hvec3(0.0);
    s.entry_pt = hvec3(0.0);
    s.has_exit = false;
    return s;
}

// The edge a -> b (transformed vertices): unclipped (proxy) or clipped.
void al_ltc_sum_edge(hvec3 a, hvec3 b, AL_INOUT(AlLtcSum) s) {
#ifdef AL_HORIZON_PROXY
    s.ff += al_edge_ltc(a, b);
#else
    al_ltc_clip_edge(a, b, s.ff, s.exit_pt, s.entry_pt, s.has_exit);
#endif
}
#endif

#ifndef AL_LIGHT_CURVED
// The same for the Lambert term in the working precision, exact, about n in the
// case's frame (za = n.a, zb = n.b; q the edge's crossing of n's horizon where they
// differ in sign, al_crossing).
// The edge's unit normal m comes from the vertex offsets (light/polygon.glsl's rule: a x (b - a)
// with b - a formed from the offsets, which the sums a, b would round away when p is
// near the light's plane); the clipped arc keeps it.
void al_lambert_clip_edge(rvec3 a, rvec3 b, real za, real zb, rvec3 q, rvec3 m, rvec3 n,
                          AL_INOUT(real) sum, AL_INOUT(rvec3) exit_pt, AL_INOUT(rvec3) entry_pt,
                          AL_INOUT(bool) has_exit) {
    bool ia = za >= AL_R(0.0), ib = zb >= AL_R(0.0);
    if (!ia && !ib) return;
    rvec3 a0 = ia ? a : q, b0 = ib ? b : q;
    // The arc's sine along m (light/polygon.glsl's al_arc), not |a0 x b0|: m carries the
    // offsets' precision.
    real sn = dot(b0, cross(m, a0));
    real arc = al_ltc_angle(abs(sn), dot(a0, b0));
    sum += (sn < AL_R(0.0) ? -arc : arc) * dot(m, n);
    if (ia && !ib) {
        exit_pt = q;
        has_exit = true;
    }
    if (!ia && ib) entry_pt = q;
}
#endif

#ifdef AL_TABLE_FIT
// table=fit (GGX): the two textures' (a, b, c, d) and (A, B) in closed form, from the
// lobe quantities of templates/method/ltc_ggx_fit.glsl (scripts/fit_ltc_ggx_closed.py: why
// these, not the coefficients): axis angle phi = theta_v + alpha q, inverse widths
// sx = e^lsx / alpha, sy = e^lsy / (alpha cos theta_v), then a = N cos phi,
// b = N sin phi, c = sy k, N = sx k with k = cos phi - d sin phi. Domain: alpha in
// [0.001, 1], any view (w is clamped to the fitted rows, cos theta_v >= 0.0315; a
// view below the horizon gets finite values, its specular is 0). Error: the fit's
// (that file's header) in place of bilinear filtering's.
void al_ltc_fit_lookup(real param, real nv, real sin_v, AL_INOUT(rvec4) m,
                       AL_INOUT(rvec4) amp) {
    // sqrt(alpha): al_ltc_rho for GGX, whose path this is, written out: through the call
    // glslang emitted a different module, whose cost the reports do not carry.
    real u = clamp((sqrt(param) - AL_LTC_RHO_MIN) / (AL_LTC_RHO_MAX - AL_LTC_RHO_MIN),
                   AL_R(0.0), AL_R(1.0));
    real rho = AL_LTC_RHO_MIN + u * (AL_LTC_RHO_MAX - AL_LTC_RHO_MIN);
    real alpha = AL_LTC_ALPHA_OF_RHO(rho);
    // w from the sine, as al_ltc_uv takes it; clamped to the last fitted row, 62/63.
    real w = nv > AL_R(0.0) ? sin_v * inversesqrt(AL_R(1.0) + nv)
                            : sqrt(clamp(AL_R(1.0) - nv, AL_R(0.0), AL_R(1.0)));
    w = min(w, AL_R(0.98412698412698413));
    real x = AL_R(2.0) * u - AL_R(1.0);
    real y = w * AL_R(2.0317460317460317) - AL_R(1.0);  // 2 w / (62 / 63) - 1
    real w2 = w * w, w4 = w2 * w2;
    real cos_v = AL_R(1.0) - w2;
    // Polygons (clipped to n's hemisphere, al_ltc_horizon_arc): the clamped row's view
    // angle, as for every other coefficient, so past 62/63 the lobe stays the row's; a lobe
    // turned onto the horizon lost half its mass to that clip (own hard GGX set, views at
    // n.v ~ 1.5e-3: 0.6 against 0.9). Curved lights, whose LTC counts its mass below n's
    // horizon: the view's own angle, the lobe following the view (ellipsoid stress 0.009,
    // with the row's 0.028).
#ifdef AL_LIGHT_CURVED
    real view_angle = al_ltc_angle(sin_v, nv);
#else
    real view_angle = al_ltc_angle(w * sqrt(AL_R(2.0) - w2), cos_v);  // sin = w sqrt(2 - w^2)
#endif
    real phi = clamp(view_angle + alpha * al_ltc_fit_q(x, y), AL_R(0.0), AL_HALF_PI);
    real cp = cos(phi), sp = sin(phi);
    real d = al_ltc_fit_d(x, y);
    // k = (a - b d) / N > 0 in every cell; the floor only keeps a fit's excursion finite.
    real k = max(cp - d * sp, AL_R(1e-3));
    real n = exp(al_ltc_fit_lsx(x, y)) / alpha * k;
    real cc = exp(al_ltc_fit_lsy(x, y)) / (alpha * cos_v) * k;
    m = rvec4(n * cp, n * sp, cc, d);
    real b = al_ltc_fit_b(x, y) + w4 * w4 * w2;  // + Schlick's weight at the mirror, w^10
    amp = rvec4(al_ltc_fit_t(x, y) - b, b, AL_R(0.0), AL_R(0.0));
}

// Snyder's closed form of Hill 2016's horizon proxy (fit/ltc_sphere.cpp, whose values
// the amplitude texture's w holds divided by sin^2 sigma): the horizon-clipped form
// factor of a sphere of angular radius sigma at angle omega from n. Domain: co =
// cos omega in [-1, 1], ss2 = sin^2 sigma in [0, 1]. Error: fp32 rounding (exact form).
real al_ltc_sphere_clipped(real co, real ss2) {
    if (!(ss2 > AL_R(0.0))) return AL_R(0.0);
    real ss = sqrt(ss2);
    if (co >= ss) return co * ss2;    // entirely above the horizon
    if (co <= -ss) return AL_R(0.0);  // entirely below
    real so = sqrt(max((AL_R(1.0) - co) * (AL_R(1.0) + co), AL_R(0.0)));
    real cs = sqrt(max(AL_R(1.0) - ss2, AL_R(0.0)));
    // sin gamma = cs / so, cos gamma = sqrt(sin^2 sigma - cos^2 omega) / so: the
    // difference as a product, and the angles by atan2 (al_ltc_angle), because asin and
    // 1 - sg^2 lose fp32's digits as gamma nears pi / 2 (a sphere barely straddling).
    real cg_so = sqrt(max((ss - co) * (ss + co), AL_R(0.0)));
    real inv_so = so > AL_R(0.0) ? AL_R(1.0) / so : AL_R(0.0);
    real sg = so > AL_R(0.0) ? min(cs * inv_so, AL_R(1.0)) : AL_R(1.0);
    real cg = cg_so * inv_so;
    real gamma = al_ltc_angle(cs, cg_so);
    real g = -AL_R(2.0) * so * cs * cg + AL_HALF_PI - gamma + sg * cg;
    real sr = sqrt(max(ss2 - cg * cg, AL_R(0.0)));  // sqrt(sin^2 sigma - cos^2 gamma)
    real h = co * (cg * sr + ss2 * al_ltc_angle(cg, sr));
    real i = co > AL_R(0.0) ? (AL_PI * co * ss2 + g - h) / AL_PI : (g + h) / AL_PI;
    return clamp(i, AL_R(0.0), AL_R(1.0));
}
#endif

// The albedo ceiling's reach (al_ltc_specular): the table's albedo (f0 A + B) I_H holds the
// true one to AL_LTC_ALBEDO_TOL from n.v = AL_LTC_ALBEDO_VIEWS up (a light filling the
// hemisphere, tests/test_ltc_shading.cpp: worst 0.9%); at grazing views it is not a bound
// (n.v 1e-3, beyond the last fitted row: 0.61 against 0.91). AL_LTC_ALBEDO_MAX bounds every
// view: 1 for Phong and for Beckmann and GGX with their own Smith G2 (F <= 1, single
// scattering); blinn's D with Beckmann's Lambda (CONTRACT.md 2) is not so bounded (1.044 at
// n.v = 0.08, N = 6), so it has none.
const real AL_LTC_ALBEDO_VIEWS = AL_R(0.08);
const real AL_LTC_ALBEDO_TOL = AL_R(0.01);
#ifdef AL_DIST_BLINN
const real AL_LTC_ALBEDO_MAX = AL_R(1e30);
#else
const real AL_LTC_ALBEDO_MAX = AL_R(1.0);
#endif

// The case's LTC: n, its frame (z = n, x toward v; ltc_table.hpp), the texels of its
// roughness and view, and Minv times the frame as rows: t = Minv (d.tx, d.ty, d.n).
struct AlLtc {
    rvec3 n;
    real nv;
    rvec4 m;
    rvec4 amp;
    rvec3 row0;
    rvec3 row1;
    rvec3 row2;
    real albedo;  // the ceiling on specular (al_ltc_specular)
};

// The LTC's integral over n's hemisphere, I_H, from the table's (a, d) and K (ltc_table.hpp:
// the magnitudes A and B are the hemisphere's parts divided by it). The hemisphere's image
// is the lune z > 0, (-d, 0, a).w > 0 in the LTC's space (the GGX Fresnel term's reading,
// al_ltc_magnitude), whose cosine form factor is (1 + cos beta) / 2, beta the lune planes'
// angle (Lambert's formula on its two half circles); the second lobe's map diag(1/s, 1/s, 1)
// takes the plane's normal to (-d s, 0, a). Taken at the lookup, so that one value, not the
// matrix, stays live through the edge loop (blinn's and beckmann's polygons kept 96 VGPRs).
real al_ltc_upper_integral(rvec4 m, rvec4 amp) {
    real a = m.x, d = m.w;
    real i_h = AL_R(0.5) + AL_R(0.5) * a * inversesqrt(a * a + d * d);
#ifdef AL_LTC_TWO_LOBES
    real ds = d / AL_LTC_SECOND.x;  // d s
    i_h += amp.z * (AL_R(0.5) + AL_R(0.5) * a * inversesqrt(a * a + ds * ds));
#endif
    return i_h;
}

AlLtc al_ltc_lookup(AlCase c) {
    AlLtc L;
    L.n = normalize(rvec3(c.n));
    rvec3 v = normalize(rvec3(c.v));
    L.nv = dot(L.n, v);
    // The azimuth from n x v, whose rounding is absolute (~1 ulp) at every angle, and
    // x = y x n, orthogonal to n to rounding even where v is n to the last bit:
    // v - n (n.v) there is rounding along n, and a frame built from it had x = +-n.
    // Below sin(theta_v) = 1e-4 the fitted lobe is isotropic to that order, so any
    // azimuth serves; above it the azimuth's error is at most ulp / 1e-4 rad.
    rvec3 ty = cross(L.n, v);
    real ty_len = length(ty);
    rvec3 tx;
    if (ty_len > AL_R(1e-4)) {
        ty /= ty_len;
        tx = cross(ty, L.n);
    } else {
        al_tangent_frame(L.n, tx, ty);
    }
#ifdef AL_TABLE_FIT
    al_ltc_fit_lookup(real(c.params.x), L.nv, ty_len, L.m, L.amp);
#else
    vec2 uv = al_ltc_uv(real(c.params.x), L.nv, ty_len);
    L.m = rvec4(textureLod(al_ltc_matrix, uv, 0.0f));
#ifdef AL_DIST_GGX
    {
        // GGX's matrix texture holds (a, b, c) times the cell's alpha (ltc_table.hpp): they
        // grow as 1 / alpha, which bilinear filtering of the bare entries follows badly where
        // neighbouring cells' alphas differ by up to 2.2x (a lobe 12% too narrow halfway
        // between the two smallest); scaled, a lobe that keeps its shape as it narrows is
        // interpolated exactly (specular relL2 at alpha = 0.002 9.7e-3 -> 2e-4, typical
        // set; the two-lobe tables' cells are not one shape: fit/ltc_fit.cpp). The alpha is
        // clamped as the coordinate u is.
        real alpha = clamp(al_ltc_alpha(real(c.params.x)), AL_LTC_ALPHA_OF_RHO(AL_LTC_RHO_MIN),
                           AL_LTC_ALPHA_OF_RHO(AL_LTC_RHO_MAX));
        real inv = AL_R(1.0) / alpha;
        L.m.x *= inv;
        L.m.y *= inv;
        L.m.z *= inv;
    }
#endif
    L.amp = rvec4(textureLod(al_ltc_amplitude, uv, 0.0f));
#endif
    L.row0 = L.m.x * tx + L.m.y * L.n;
    L.row1 = L.m.z * ty;
    L.row2 = L.m.w * tx + L.n;
#ifdef AL_DIST_PHONG
    real albedo = L.amp.x * al_ltc_upper_integral(L.m, L.amp);
#else
    real albedo = (real(c.params.w) * L.amp.x + L.amp.y) * al_ltc_upper_integral(L.m, L.amp);
#endif
    L.albedo = L.nv >= AL_LTC_ALBEDO_VIEWS
                   ? min(albedo * (AL_R(1.0) + AL_LTC_ALBEDO_TOL), AL_LTC_ALBEDO_MAX)
                   : AL_LTC_ALBEDO_MAX;
    return L;
}

// Hill 2016's horizon: the clipped form factor of a sphere with the light's vector form
// factor F (vector_ff = 2 pi F, any light): sin^2(sigma) = |F|, cos(omega) = F.z / |F|;
// |F| S(cos omega, |F|) with S from the table (S = 1 where the sphere is above the
// horizon). Error: the proxy's (exact for a sphere; docs/ltc.md), plus bilinear filtering.
real al_ltc_proxy_form(hvec3 vector_ff) {
    real len = real(length(vector_ff)) / AL_TWO_PI;
    real form = AL_R(0.0);
    if (len > AL_R(0.0)) {
        real cz = clamp(real(vector_ff.z) / (len * AL_TWO_PI), AL_R(-1.0), AL_R(1.0));
#ifdef AL_TABLE_FIT
        // table=fit: the closed form the table holds, |F| S = I (sin^2 sigma = |F|).
        form = al_ltc_sphere_clipped(cz, min(len, AL_R(1.0)));
#else
        rvec2 suv = (rvec2(cz * AL_R(0.5) + AL_R(0.5), min(len, AL_R(1.0))) *
                         (AL_LTC_SIZE - AL_R(1.0)) + AL_R(0.5)) / AL_LTC_SIZE;
        form = len * real(textureLod(al_ltc_amplitude, vec2(suv), 0.0f).w);
#endif
    }
    return form;
}

#ifndef AL_LIGHT_CURVED
// A lobe's form factor of the polygon from its sums: the proxy's, or the clipped
// polygon's after the closing arc exit -> entry on the horizon z = 0 (along +z, its sine
// floored at 0, as for the Lambert term).
// With horizon=clip the closing arc is added to s.ff, whose direction the GGX Fresnel
// term reads (al_ltc_magnitude).
real al_ltc_sum_form(AL_INOUT(AlLtcSum) s) {
#ifdef AL_HORIZON_PROXY
    return al_ltc_proxy_form(s.ff);
#else
    if (s.has_exit) {
        hreal sz = max(cross(s.exit_pt, s.entry_pt).z, hreal(0.0));
        s.ff.z += sz * al_edge_factor(dot(s.exit_pt, s.entry_pt), hvec3(hreal(0.0), hreal(0.0), sz));
    }
    return real(s.ff.z) / AL_TWO_PI;
#endif
}
#endif

// The lobe's magnitude for a light whose LTC-space vector form factor is vector_ff (any
// scale; only its direction enters, GGX only), Schlick f0 (1: F = 1).
real al_ltc_magnitude(AlLtc L, hvec3 vector_ff, real f0) {
#ifdef AL_DIST_PHONG
    return L.amp.x;
#else
    // Fresnel (the mobile LTC article, last section): the table's split f0 A + B is the lobe's
    // whole-hemisphere average of F. A light holding part of the lobe sees F near
    // its own part's half vectors, so the (1 - h.v)^5 weight moves by its value at
    // the light's direction in the lobe (the LTC's vector form factor taken back
    // through M) less its value for a light filling the hemisphere, so that such a
    // light stays exact. M = Minv^-1 up to scale: xz block
    // [[1, -b], [-d, a]], y (a - b d) / c.
    // Measured on seeded random sets (tests/test_ltc_shading.cpp): the correction
    // helps GGX (relL2 with random f0 1.81x -> 0.97x that of a perfect Fresnel
    // channel on the same fit) and hurts the Gaussian-tailed lobes, whose LTC
    // direction is a poorer guide (beckmann 1.05x -> 1.52x, blinn 1.24x -> 1.52x):
    // GGX only.
    rvec4 amp = L.amp;
    real magnitude = f0 * amp.x + amp.y;
#ifdef AL_DIST_GGX
    if (f0 < AL_R(1.0)) {
        rvec4 m = L.m;
        real nv = L.nv;
        rvec3 g = rvec3(vector_ff);
        rvec3 w = rvec3(g.x - m.y * g.z, g.y * (m.x - m.y * m.w) / m.z, m.x * g.z - m.w * g.x);
        // The hemisphere's image in the LTC's space is the lune z > 0, (-d, 0, a).w > 0
        // (M's third row): its vector form factor lies along the sum of the two unit
        // normals, taken back through M the same way.
        rvec3 h = rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0)) +
                  normalize(rvec3(-m.w, AL_R(0.0), m.x));
        rvec3 wh = rvec3(h.x - m.y * h.z, AL_R(0.0), m.x * h.z - m.w * h.x);
        real sv = sqrt(max(AL_R(1.0) - nv * nv, AL_R(0.0)));
        real x_light = al_ltc_schlick_weight(w, sv, nv);
        real x_lobe = al_ltc_schlick_weight(wh, sv, nv);
        if (x_light >= AL_R(0.0) && x_lobe >= AL_R(0.0))
            magnitude += (AL_R(1.0) - f0) * (amp.x + amp.y) * (x_light - x_lobe);
    }
#endif
    return magnitude;
#endif
}

// The specular of a light region from its lobe integral `form` (one or two lobes, as the
// shader sums them): the table's magnitude times form, kept within [0, L.albedo], a ceiling
// above the true value (al_ltc_lookup: the table's albedo plus its error where that is
// known, else 1), so the clamp never moves an estimate away from the truth. The LTC
// exceeds the albedo where its kernel is signed (two lobes: D_o + K D_s, K < 0, is
// negative in its far tail, so a light that holds the core but not that tail overshoots)
// and where the light reaches below n's horizon (the clip is the LTC's own z >= 0, which
// counts lobe mass beyond the true horizon, unless al_ltc_horizon_arc clips there too:
// polygons with horizon=clip). Domain: any lookup L and form; error: never
// larger than the unclamped product's (public glossy beckmann poly8 065: 1.0166 ->
// 1.0000, reference 1.0000; docs/ltc.md, "Albedo ceiling"). Cost: two inverse square
// roots a shading point, formed at the lookup (ggx polygon 986 -> 999 cycles a wave,
// beckmann 1 075 -> 1 095, VGPRs unchanged).
real al_ltc_specular(AlLtc L, real form, hvec3 vector_ff, real f0) {
    return clamp(form * al_ltc_magnitude(L, vector_ff, f0), AL_R(0.0), max(L.albedo, AL_R(0.0)));
}

// n's horizon in the LTC's space: the unit normal of its image plane, (-d, 0, a) (the
// hemisphere's lune, al_ltc_upper_integral); sx scales the image's x and y (the second
// lobe, 1 / s: (-d, 0, a / s)). Polygons and curved lights clip there (al_ltc_horizon_arc,
// method/ltc_ellipse.glsl).
rvec3 al_ltc_horizon_normal(AlLtc L, real sx) {
    return normalize(rvec3(-L.m.w, AL_R(0.0), L.m.x * sx));
}

// A vector's image t = Minv (w.tx, w.ty, w.n) in the LTC's space (not unit): a
// direction's, or a curved light's centre and semi-diameters (method/ltc_ellipse.glsl).
rvec3 al_ltc_image(AlLtc L, rvec3 w) {
    return rvec3(dot(w, L.row0), dot(w, L.row1), dot(w, L.row2));
}

#ifndef AL_LIGHT_CURVED
#ifndef AL_HORIZON_PROXY
// |nu.x| below which n's horizon and the LTC's z = 0 count as one plane (al_ltc_horizon_arc):
// above the rounding of the arc's ends' z (~1e-7 in fp32, ~1e-3 in fp16).
#ifdef AL_PRECISION_FP16
#define AL_LTC_FLAT hreal(1e-2)
#else
#define AL_LTC_FLAT hreal(1e-4)
#endif
// horizon=clip integrates the light clipped to n's hemisphere, not only to the LTC's own
// z >= 0: the lobe's true integrand (f (n.w))+ vanishes below n's horizon, and the tables
// are normalised to the LTC's mass above it (I_H, al_ltc_upper_integral), but the LTC's
// z >= 0 is the plane (-d, 0, a).w = 0 in the case's frame, so a light below n's horizon
// and above that plane was counted (public horizon blinn poly7 093: 5.4x the reference,
// 1.7x with this clip; docs/ltc.md, "True horizon"). Each edge is cut where it crosses n's
// horizon (the Lambert term's crossing, al_crossing) and the region is closed along the
// horizon from the exit lx to the entry le, an arc of at most pi counter-clockwise about n.
// Linear maps keep great circles and convexity, so the images form one convex polygon
// again, clipped to z >= 0 as before. The arc's image lies in the plane with normal
// nu = (-d, 0, a) (second lobe, x and y over s: (-d s, 0, a)), which the edge's direction
// and its crossing of z = 0 are taken from, since a x b and the segment a-b lose them as
// the arc nears pi (p near the light's plane).
void al_ltc_horizon_arc(AlLtc L, rvec3 lx, rvec3 le, AL_INOUT(AlLtcSum) s, real sx) {
    rvec3 sc = rvec3(sx, sx, AL_R(1.0));
    hvec3 a = hvec3(AL_LTC_UNIT(al_ltc_image(L, lx) * sc));
    hvec3 b = hvec3(AL_LTC_UNIT(al_ltc_image(L, le) * sc));
    hvec3 nu = hvec3(al_ltc_horizon_normal(L, sx));
    bool ia = a.z >= hreal(0.0), ib = b.z >= hreal(0.0);
    if (!ia && !ib) return;
    // Where it crosses z = 0: the planes' common line, +-y, on the arc's side (a point of
    // the segment a-b would pass by the origin as the arc nears pi).
    hvec3 y = hvec3(hreal(0.0), hreal(1.0), hreal(0.0));
    hvec3 q = dot(cross(a, y), nu) >= hreal(0.0) ? y : -y;
    // But the two planes coincide where the lobe is symmetric about n (d = 0: a view exactly
    // along n), and the arc then lies on z = 0 whole, its ends' signs rounding's: +-y, a
    // quarter turn off the arc, left the boundary open (a small light across the horizon
    // under v = n: GGX specular 0.37 where the oracle's is 1.5e-9). Within AL_LTC_FLAT of that,
    // the crossing is interpolated between the ends as al_ltc_clip_edge's (a point of the
    // arc, and the same rounding decided which side the neighbouring edges' ends are on).
    if (abs(nu.x) < AL_LTC_FLAT && ia != ib) q = AL_LTC_UNIT((a.z * b - b.z * a) / (a.z - b.z));
    hvec3 a0 = ia ? a : q, b0 = ib ? b : q;
    hvec3 m = nu * max(dot(cross(a0, b0), nu), hreal(0.0));
    s.ff += m * al_edge_factor(dot(a0, b0), m);
    if (ia && !ib) {
        s.exit_pt = q;
        s.has_exit = true;
    }
    if (!ia && ib) s.entry_pt = q;
}
#endif
#endif

#ifndef AL_LIGHT_CURVED
// Diffuse and specular (CONTRACT.md 2; no ndf or moment).
vec4 al_shade(AlCase c) {
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    AlLtc L = al_ltc_lookup(c);
    rvec3 n = L.n;
    int count = int(c.params.z);
    rvec3 center = rvec3(c.center);
    real lambert = AL_R(0.0);
    rvec3 lx = rvec3(AL_R(0.0)), le = rvec3(AL_R(0.0));
    bool has_lx = false;
    AlLtcSum s1 = al_ltc_sum_init();
    rvec3 pa, pb, da, db;
    real za, zb;
    hvec3 ha, hb;
#ifdef AL_LTC_TWO_LOBES
    AlLtcSum s2 = al_ltc_sum_init();
    hvec3 ha2, hb2;
#endif
    // Vertices as given (Lambert, about n) and through Minv (LTC), walked as
    // light/polygon.glsl walks them (backwards from the front) so that both sums are >= 0;
    // the last step closes the polygon at vertex 0.
    AL_UNROLL for (int k = 0; k <= AL_MAX_VERTS; ++k) {
        if (k > count) break;
        int idx = k == 0 || k == count ? 0 : (side > AL_R(0.0) ? count - k : k);
        db = rvec3(c.verts[idx]);
        pb = normalize(center + db);
        zb = dot(pb, n);
        rvec3 tb = al_ltc_image(L, pb);
        hb = hvec3(AL_LTC_UNIT(tb));
#ifdef AL_LTC_TWO_LOBES
        hb2 = hvec3(AL_LTC_UNIT(tb * AL_LTC_SECOND));
#endif
        if (k > 0) {
            rvec3 me = normalize(cross(center + da, db - da));
            bool ia = za >= AL_R(0.0), ib = zb >= AL_R(0.0);
            rvec3 q = ia != ib ? al_crossing(pa, pb, za, zb) : pa;
            al_lambert_clip_edge(pa, pb, za, zb, q, me, n, lambert, lx, le, has_lx);
#ifdef AL_HORIZON_PROXY
            al_ltc_sum_edge(ha, hb, s1);
#ifdef AL_LTC_TWO_LOBES
            al_ltc_sum_edge(ha2, hb2, s2);
#endif
#else
            // horizon=clip: the edge's part above n's horizon, cut at q (al_ltc_horizon_arc).
            if (ia || ib) {
                rvec3 tq = al_ltc_image(L, q);
                hvec3 hq = hvec3(AL_LTC_UNIT(tq));
                al_ltc_sum_edge(ia ? ha : hq, ib ? hb : hq, s1);
#ifdef AL_LTC_TWO_LOBES
                hvec3 hq2 = hvec3(AL_LTC_UNIT(tq * AL_LTC_SECOND));
                al_ltc_sum_edge(ia ? ha2 : hq2, ib ? hb2 : hq2, s2);
#endif
            }
#endif
        }
        pa = pb;
        da = db;
        za = zb;
        ha = hb;
#ifdef AL_LTC_TWO_LOBES
        ha2 = hb2;
#endif
    }
    // The closing arc along the horizon, exit -> entry, about n: in [0, pi] (the light
    // lies in the open half space of its plane, which holds half the horizon circle).
    // Its sine is taken along n and floored at 0, so that an arc of nearly pi (p near
    // the light's plane, the foot inside) cannot flip sign through rounding.
    if (has_lx) lambert += al_ltc_angle(max(dot(le, cross(n, lx)), AL_R(0.0)), dot(lx, le));
#ifndef AL_HORIZON_PROXY
    if (has_lx && dot(le, le) > AL_R(0.0)) {
        al_ltc_horizon_arc(L, lx, le, s1, AL_R(1.0));
#ifdef AL_LTC_TWO_LOBES
        al_ltc_horizon_arc(L, lx, le, s2, AL_LTC_SECOND.x);
#endif
    }
#endif
    real diffuse = max(lambert, AL_R(0.0)) / AL_TWO_PI;

    real specular = AL_R(0.0);
    if (L.nv > AL_R(0.0)) {
        real form = al_ltc_sum_form(s1);
#ifdef AL_LTC_TWO_LOBES
        // The kernel is negative in its far tail (K < 0): a light there gets 0.
        form += L.amp.z * al_ltc_sum_form(s2);
#endif
        specular = al_ltc_specular(L, form, s1.ff, real(c.params.w));
    }
    return vec4(diffuse, specular, AL_R(0.0), AL_R(0.0));
}
#endif
