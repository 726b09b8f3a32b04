// Polygon lights (CONTRACT.md 1) as spherical polygons: orientation, sidedness,
// exact clipping to the hemispheres of n and of the lobe axis, and the exact diffuse
// (Lambert) integral. The clipped polygons are never stored: their arcs are
// streamed one by one into the method's accumulator (al_moments_*), so the shader
// holds no per-vertex arrays (on lavapipe the arrays of a stored clip were 2/3 of
// the machine code and of the JIT time).

// Curved lights (light/spin_polygon.glsl) have no sided key: their two_sided is the
// function's argument, as AL_SIDED 0 says (GLSL ES refuses an undefined macro in #if).
#ifndef AL_SIDED
#define AL_SIDED 0
#endif

// Which side of the light p (the origin) sees: +1 front, -1 back, 0 on its plane
// or not emitting towards p (one-sided back face).
real al_polygon_side(AlCase c) {
    rvec3 d0 = rvec3(c.verts[0]), d1 = rvec3(c.verts[1]), d2 = rvec3(c.verts[2]);
    real side = -dot(cross(d1 - d0, d2 - d0), rvec3(c.center) + d0);
    if (side == AL_R(0.0)) return AL_R(0.0);
#if AL_SIDED == 1
    return side > AL_R(0.0) ? AL_R(1.0) : AL_R(0.0);
#elif AL_SIDED == 2
    return side > AL_R(0.0) ? AL_R(1.0) : -AL_R(1.0);
#else
    if (side > AL_R(0.0)) return AL_R(1.0);
    return c.params.y != 0.0f ? -AL_R(1.0) : AL_R(0.0);
#endif
}

// Length of the arc a -> b with unit normal m, in [0, pi): atan2 of the sine along
// the arc's own normal.
real al_arc(rvec3 a, rvec3 b, rvec3 m) {
    return al_atan2(dot(b, cross(m, a)), dot(a, b));
}

// The point where the arc a -> b crosses the great circle w.d = 0, from the signed
// distances da = d.a, db = d.b of opposite signs: (da b - db a) / (da - db) lies on
// both (da - db cannot cancel). One formula for every use, so that a crossing shared
// by two arcs is the same value in both (the azimuth sweeps then telescope).
rvec3 al_crossing(rvec3 a, rvec3 b, real da, real db) {
    return normalize((da * b - db * a) / (da - db));
}

#if !defined(AL_METHOD_POINT) && !defined(AL_METHOD_LTC)
// The arc xn -> en along n's circle (xn where the boundary leaves n's hemisphere, en
// where it re-enters), clipped by the axis's hemisphere unless !clip_axis: its ends
// a, b, whether any of it is left, and where it leaves (yo) or re-enters (yi) the
// axis's hemisphere, if it does.
bool al_horizon_arc(rvec3 xn, rvec3 en, rvec3 axis, bool clip_axis, AL_INOUT(rvec3) a,
                    AL_INOUT(rvec3) b, AL_INOUT(rvec3) yo, AL_INOUT(bool) has_yo,
                    AL_INOUT(rvec3) yi, AL_INOUT(bool) has_yi) {
    real rx = dot(axis, xn), re = dot(axis, en);
    bool jx = !clip_axis || rx >= AL_R(0.0), je = !clip_axis || re >= AL_R(0.0);
    rvec3 q = jx != je ? al_crossing(xn, en, rx, re) : xn;
    if (jx && !je) {
        yo = q;
        has_yo = true;
    }
    if (!jx && je) {
        yi = q;
        has_yi = true;
    }
    a = jx ? xn : q;
    b = je ? en : q;
    return jx || je;
}

// Whether the axis's hemisphere cuts anything n's does not. Not when the axis is n to
// within 1e-6 rad (a view exactly along n makes r = n up to rounding): the two horizons are
// then one circle, and D's arc along it would be streamed twice, once as each (a disc
// crossing the horizon under v = n: Phong moment 0.046 where the oracle's is 0; rounding
// the sweeps' total to a whole turn had hidden it). The sliver between two circles that
// close holds x = axis.w < 1e-6, so x^N drops nothing there.
bool al_axis_clips(rvec3 n, rvec3 axis) {
    rvec3 t = cross(n, axis);
    return dot(t, t) > AL_R(1e-12) || dot(n, axis) < AL_R(0.0);
}

// (Curved lights shaded along their true boundary have no polygon: AL_MAX_VERTS
// undefined, and light/ellipse_clip.glsl streams instead.)
#ifdef AL_MAX_VERTS
// Streams the arcs of D = light ∩ {n.w >= 0} ∩ {axis.w >= 0} into the method's
// accumulator M (al_moments_arc) and returns the irradiance / pi of light ∩ {n.w >= 0}
// (Lambert: sum arc_i (n.m_i) / (2 pi), exact). Without clip_axis, D = light ∩
// {n.w >= 0} (microfacet lobes live in half-vector space: no second clip).
// The light is convex and lies in an open hemisphere, so each clip circle meets
// the clipped boundary in at most one arc, shorter than pi. Iterations 0..count-1
// take the light's edges, clipped to both hemispheres; iteration count the arc
// along n's circle from where the boundary leaves n's hemisphere to where it
// re-enters (clipped by the axis); iteration count+1 the arc along the axis's
// circle between D's exit and entry points. All in one rolled loop, so the
// method's per-arc code appears once.
real al_polygon_stream(AlCase c, real side, rvec3 n, rvec3 axis, bool clip_axis, real N,
                       AL_INOUT(AlMoments) M) {
    int count = int(c.params.z);
    rvec3 center = rvec3(c.center);
    clip_axis = clip_axis && al_axis_clips(n, axis);
    real lit_sum = AL_R(0.0);
    rvec3 xn = rvec3(AL_R(0.0)), en = rvec3(AL_R(0.0));  // leaves / re-enters n's hemisphere
    rvec3 yo = rvec3(AL_R(0.0)), yi = rvec3(AL_R(0.0));  // leaves / re-enters the axis's, on D
    bool has_xn = false, has_en = false, has_yo = false, has_yi = false;
    for (int i = 0; i < AL_MAX_VERTS + 2; ++i) {
        if (i >= count + 2) break;
        rvec3 a, b, m;
        bool d_arc = false;
        if (i < count) {
            // Seen from the front the contract's counter-clockwise order is clockwise
            // from outside the sphere: walk each edge backwards. The normal comes from
            // x_p x (x_q - x_p), the edge vector taken from the offsets.
            int j = i + 1 < count ? i + 1 : 0;
            int p = side > AL_R(0.0) ? j : i, q = side > AL_R(0.0) ? i : j;
            rvec3 dp = rvec3(c.verts[p]), dq = rvec3(c.verts[q]);
            a = normalize(center + dp);
            b = normalize(center + dq);
            m = normalize(cross(center + dp, dq - dp));
            real na = dot(n, a), nb = dot(n, b), ra = dot(axis, a), rb = dot(axis, b);
            bool ia = na >= AL_R(0.0), ib = nb >= AL_R(0.0);
            bool ja = !clip_axis || ra >= AL_R(0.0), jb = !clip_axis || rb >= AL_R(0.0);
            rvec3 pn = ia != ib ? al_crossing(a, b, na, nb) : a;
            rvec3 pr = ja != jb ? al_crossing(a, b, ra, rb) : a;
            // Lit part (diffuse): the edge clipped to n's hemisphere.
            if (ia || ib) lit_sum += al_arc(ia ? a : pn, ib ? b : pn, m) * dot(n, m);
            if (ia && !ib) {
                xn = pn;
                has_xn = true;
            }
            if (!ia && ib) {
                en = pn;
                has_en = true;
            }
            // The axis's circle crosses D's boundary here only inside n's hemisphere.
            bool pr_lit = dot(n, pr) >= AL_R(0.0);
            if (ja && !jb && pr_lit) {
                yo = pr;
                has_yo = true;
            }
            if (!ja && jb && pr_lit) {
                yi = pr;
                has_yi = true;
            }
            // D's part: the parameter interval of (1-t) a + t b inside both.
            real tn = ia != ib ? na / (na - nb) : AL_R(0.0);
            real tr = ja != jb ? ra / (ra - rb) : AL_R(0.0);
            real t0 = max(ia ? AL_R(0.0) : tn, ja ? AL_R(0.0) : tr);
            real t1 = min(ib ? AL_R(1.0) : tn, jb ? AL_R(1.0) : tr);
            d_arc = (ia || ib) && (ja || jb) && t0 < t1;
            rvec3 a0 = ia && ja ? a : (!ja && (ia || tr >= tn) ? pr : pn);
            rvec3 b0 = ib && jb ? b : (!jb && (ib || tr <= tn) ? pr : pn);
            a = a0;
            b = b0;
        } else if (i == count) {
            // Along n's circle (normal n), clipped by the axis.
            m = n;
            if (has_xn && has_en) {
                lit_sum += al_arc(xn, en, n);
                d_arc = al_horizon_arc(xn, en, axis, clip_axis, a, b, yo, has_yo, yi, has_yi);
            }
        } else {
            // Along the axis's circle (normal axis), from D's exit to its entry.
            m = axis;
            d_arc = has_yo && has_yi;
            a = yo;
            b = yi;
        }
        if (d_arc) al_moments_arc(M, a, b, m, axis, n, N);
    }
    return lit_sum / AL_TWO_PI;
}

#if defined(AL_DIST_PHONG) && !defined(AL_METHOD_MRP)
// The Phong moments about `axis` over D (al_moments_end), and D's diffuse (every Phong
// accumulator but mrp's vector form factor, which has no lobe).
rvec2 al_polygon_moments(AlCase c, real side, rvec3 n, rvec3 axis, real N,
                         AL_INOUT(real) diffuse) {
    AlMoments M = al_moments_begin(axis);
    diffuse = al_polygon_stream(c, side, n, axis, true, N, M);
    return al_moments_end(M, axis, n, N);
}
#endif
#endif
#endif
