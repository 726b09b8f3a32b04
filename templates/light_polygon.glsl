// Polygon lights (CONTRACT.md 1): orientation, sidedness, exact horizon clipping
// and the shading driver of each method.

#define AL_POLY_CAP (AL_MAX_VERTS + 2)

// A convex spherical polygon of unit directions, counter-clockwise seen from
// outside the unit sphere; m[i] is the inward unit normal of the arc v[i] -> v[i+1].
// Normals are carried through clipping rather than recomputed from short arcs,
// where cross products of nearly equal fp32 directions lose their digits.
struct AlPoly {
    rvec3 v[AL_POLY_CAP];
    rvec3 m[AL_POLY_CAP];
    int count;
};

void al_poly_push(AL_INOUT(AlPoly) P, rvec3 v, rvec3 m) {
    if (P.count < AL_POLY_CAP) {
        P.v[P.count] = v;
        P.m[P.count] = m;
        P.count += 1;
    }
}

// Clips to the hemisphere c.w >= 0 (Sutherland-Hodgman on the sphere). Exact up
// to rounding: the new vertex (dp Q - dq P) / (dp - dq) lies on arc PQ and on the
// great circle c.w = 0 (dp - dq cannot cancel: opposite signs); the kept part of an
// arc keeps its normal and the new arc along the clip circle has normal c.
AlPoly al_clip(AlPoly P, rvec3 c) {
    AlPoly R;
    R.count = 0;
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= P.count) break;
        rvec3 a = P.v[i], b = P.v[i + 1 < P.count ? i + 1 : 0];
        real da = dot(c, a), db = dot(c, b);
        if (da >= AL_R(0.0)) al_poly_push(R, a, P.m[i]);
        if ((da >= AL_R(0.0)) != (db >= AL_R(0.0))) {
            rvec3 x = normalize((da * b - db * a) / (da - db));
            al_poly_push(R, x, da >= AL_R(0.0) ? c : P.m[i]);
        }
    }
    return R;
}

// Length of arc i of P, in (0, pi): atan2 of the sine along the arc's own normal.
real al_arc(AlPoly P, int i) {
    rvec3 a = P.v[i], b = P.v[i + 1 < P.count ? i + 1 : 0];
    return al_atan2(dot(b, cross(P.m[i], a)), dot(a, b));
}

// Irradiance / pi of a clipped polygon: Lambert's formula sum_i arc_i (n . m_i) / (2 pi).
// Exact to rounding.
real al_polygon_diffuse(AlPoly P, rvec3 n) {
    real sum = AL_R(0.0);
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= P.count) break;
        sum += al_arc(P, i) * dot(n, P.m[i]);
    }
    return sum / AL_TWO_PI;
}

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

// The light as an AlPoly. Seen from the front the contract's counter-clockwise
// order is clockwise from outside the sphere: reverse it. Edge normals come from
// x_i x (x_(i+1) - x_i) with the edge vector taken from the offsets.
AlPoly al_polygon_directions(AlCase c, real side) {
    AlPoly P;
    P.count = int(c.params.z);
    rvec3 center = rvec3(c.center);
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        if (i >= P.count) break;
        int k = side > AL_R(0.0) ? P.count - 1 - i : i;
        int k1 = side > AL_R(0.0) ? (k > 0 ? k - 1 : P.count - 1) : (k + 1 < P.count ? k + 1 : 0);
        rvec3 d = rvec3(c.verts[k]);
        P.v[i] = normalize(center + d);
        P.m[i] = normalize(cross(center + d, rvec3(c.verts[k1]) - d));
    }
    return P;
}

#ifdef AL_METHOD_POINT
// Baseline: the polygon's centre as a point light of the same power, solid angle
// ~ area cos(theta_l) / d^2. Error grows with the light's angular size; O(1), cheapest.
vec4 al_shade(AlCase c) {
    rvec3 n = rvec3(c.n);
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    int count = int(c.params.z);
    rvec3 area2 = rvec3(AL_R(0.0));
    rvec3 d0 = rvec3(c.verts[0]);
    for (int i = 2; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        area2 += cross(rvec3(c.verts[i - 1]) - d0, rvec3(c.verts[i]) - d0);
    }
    rvec3 centre = rvec3(c.center);
    real d2 = dot(centre, centre);
    rvec3 w = centre * inversesqrt(d2);
    real solid_angle = abs(dot(area2, w)) * AL_R(0.5) / d2;
    real nw = max(dot(n, w), AL_R(0.0));
    real N = real(c.params.x);
    real spec = al_phong_brdf(rvec3(c.r), w, N) * nw * solid_angle;
    return vec4(nw / AL_PI * solid_angle, spec, AL_R(0.0), AL_R(0.0));
}
#endif

#ifndef AL_METHOD_POINT
// Diffuse, specular and moment (CONTRACT.md 2) for Phong by boundary integrals:
// clip by the horizon of n (diffuse, exact), then by r's hemisphere ((r.w)_+
// vanishes beyond), and sum the per-arc terms of the method's al_phong_edge
// (method_exact_phong.glsl: quadrature; method_peak_phong.glsl: peak functions).
vec4 al_shade(AlCase c) {
    rvec3 n = rvec3(c.n);
    real side = al_polygon_side(c);
    if (side == AL_R(0.0)) return vec4(AL_R(0.0));
    real N = real(c.params.x);
    rvec3 r = rvec3(c.r);
    AlPoly lit = al_clip(al_polygon_directions(c, side), n);
    real diffuse = al_polygon_diffuse(lit, n);
    AlPoly D = al_clip(lit, r);
    // Azimuths about r of the vertices: each arc sweeps the wrapped difference of its
    // ends' azimuths (|sweep| < pi: D lies in r's hemisphere), and the wraps count
    // the winding number of D about r exactly.
    rvec3 e1, e2;
    al_tangent_frame(r, e1, e2);
    real psi0 = D.count > 0 ? al_atan2(dot(D.v[0], e2), dot(D.v[0], e1)) : AL_R(0.0);
    real psi_a = psi0;
    rvec3 sums = rvec3(AL_R(0.0));
    real wraps = AL_R(0.0);
    real sweep_near = AL_R(0.0), sweep_far = AL_R(0.0), size_near = AL_R(0.0), size_far = AL_R(0.0);
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= D.count) break;
        bool last = i + 1 >= D.count;
        rvec3 b = D.v[last ? 0 : i + 1];
        real psi_b = last ? psi0 : al_atan2(dot(b, e2), dot(b, e1));
        real sweep = psi_b - psi_a;
        if (sweep > AL_PI) {
            sweep -= AL_TWO_PI;
            wraps += AL_R(1.0);
        } else if (sweep < -AL_PI) {
            sweep += AL_TWO_PI;
            wraps -= AL_R(1.0);
        }
        psi_a = psi_b;
        AlPhongEdge e = al_phong_edge(D.v[i], b, D.m[i], r, n, N);
        sums += e.sums;
        if (e.near_edge) {
            sweep_near += sweep;
            size_near += abs(sweep);
        } else {
            sweep_far += sweep;
            size_far += abs(sweep);
        }
    }
    // The sweeps total -2 pi wraps (the winding number about r, 0 or 1 for a convex
    // D): so 2 pi winding - (near sweeps) equals the far sweeps. Take whichever group
    // cancels less.
    real winding = size_near <= size_far ? -AL_TWO_PI * wraps - sweep_near : sweep_far;
    real moment = (winding - sums.x) / AL_TWO_PI;
    real specular = (dot(r, n) * (winding - sums.y) + sums.z) / AL_TWO_PI;
    return vec4(diffuse, specular, moment, AL_R(0.0));
}
#endif
