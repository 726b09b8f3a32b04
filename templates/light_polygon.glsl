// Polygon lights (CONTRACT.md 1): orientation, sidedness, exact horizon clipping
// and the shading driver of each method.

#define AL_POLY_CAP (AL_MAX_VERTS + 2)

// A convex spherical polygon of unit directions, counter-clockwise seen from
// outside the unit sphere; m[i] is the inward unit normal of the arc v[i] -> v[i+1].
// Normals are carried through clipping rather than recomputed from short arcs,
// where cross products of nearly equal fp32 directions lose their digits.
struct AlPoly {
    vec3 v[AL_POLY_CAP];
    vec3 m[AL_POLY_CAP];
    int count;
};

void al_poly_push(AL_INOUT(AlPoly) P, vec3 v, vec3 m) {
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
AlPoly al_clip(AlPoly P, vec3 c) {
    AlPoly R;
    R.count = 0;
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= P.count) break;
        vec3 a = P.v[i], b = P.v[i + 1 < P.count ? i + 1 : 0];
        float da = dot(c, a), db = dot(c, b);
        if (da >= 0.0f) al_poly_push(R, a, P.m[i]);
        if ((da >= 0.0f) != (db >= 0.0f)) {
            vec3 x = normalize((da * b - db * a) / (da - db));
            al_poly_push(R, x, da >= 0.0f ? c : P.m[i]);
        }
    }
    return R;
}

// Length of arc i of P, in (0, pi): atan2 of the sine along the arc's own normal.
float al_arc(AlPoly P, int i) {
    vec3 a = P.v[i], b = P.v[i + 1 < P.count ? i + 1 : 0];
    return al_atan2(dot(b, cross(P.m[i], a)), dot(a, b));
}

// Irradiance / pi of a clipped polygon: Lambert's formula sum_i arc_i (n . m_i) / (2 pi).
// Exact to rounding.
float al_polygon_diffuse(AlPoly P, vec3 n) {
    float sum = 0.0f;
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= P.count) break;
        sum += al_arc(P, i) * dot(n, P.m[i]);
    }
    return sum / AL_TWO_PI;
}

// Which side of the light p (the origin) sees: +1 front, -1 back, 0 on its plane
// or not emitting towards p (one-sided back face).
float al_polygon_side(AlCase c) {
    vec3 d0 = vec3(c.verts[0]), d1 = vec3(c.verts[1]), d2 = vec3(c.verts[2]);
    float side = -dot(cross(d1 - d0, d2 - d0), vec3(c.center) + d0);
    if (side == 0.0f) return 0.0f;
#if AL_SIDED == 1
    return side > 0.0f ? 1.0f : 0.0f;
#elif AL_SIDED == 2
    return side > 0.0f ? 1.0f : -1.0f;
#else
    if (side > 0.0f) return 1.0f;
    return c.params.y != 0.0f ? -1.0f : 0.0f;
#endif
}

// The light as an AlPoly. Seen from the front the contract's counter-clockwise
// order is clockwise from outside the sphere: reverse it. Edge normals come from
// x_i x (x_(i+1) - x_i) with the edge vector taken from the offsets.
AlPoly al_polygon_directions(AlCase c, float side) {
    AlPoly P;
    P.count = int(c.params.z);
    vec3 center = vec3(c.center);
    for (int i = 0; i < AL_MAX_VERTS; ++i) {
        if (i >= P.count) break;
        int k = side > 0.0f ? P.count - 1 - i : i;
        int k1 = side > 0.0f ? (k > 0 ? k - 1 : P.count - 1) : (k + 1 < P.count ? k + 1 : 0);
        vec3 d = vec3(c.verts[k]);
        P.v[i] = normalize(center + d);
        P.m[i] = normalize(cross(center + d, vec3(c.verts[k1]) - d));
    }
    return P;
}

#ifdef AL_METHOD_POINT
// Baseline: the polygon's centre as a point light of the same power, solid angle
// ~ area cos(theta_l) / d^2. Error grows with the light's angular size; O(1), cheapest.
vec4 al_shade(AlCase c) {
    vec3 n = vec3(c.n);
    float side = al_polygon_side(c);
    if (side == 0.0f) return vec4(0.0f);
    int count = int(c.params.z);
    vec3 area2 = vec3(0.0f);
    vec3 d0 = vec3(c.verts[0]);
    for (int i = 2; i < AL_MAX_VERTS; ++i) {
        if (i >= count) break;
        area2 += cross(vec3(c.verts[i - 1]) - d0, vec3(c.verts[i]) - d0);
    }
    vec3 centre = vec3(c.center);
    float d2 = dot(centre, centre);
    vec3 w = centre * inversesqrt(d2);
    float solid_angle = abs(dot(area2, w)) * 0.5f / d2;
    float nw = max(dot(n, w), 0.0f);
    float N = c.params.x;
    float spec = al_phong_brdf(vec3(c.r), w, N) * nw * solid_angle;
    return vec4(nw / AL_PI * solid_angle, spec, 0.0f, 0.0f);
}
#endif

#ifdef AL_METHOD_EXACT
// Exact diffuse, specular and moment (CONTRACT.md 2) for Phong: clip by the horizon
// of n (diffuse), then by r's hemisphere ((r.w)_+ vanishes beyond), and sum the
// boundary integrals of method_exact_phong.glsl.
vec4 al_shade(AlCase c) {
    vec3 n = vec3(c.n);
    float side = al_polygon_side(c);
    if (side == 0.0f) return vec4(0.0f);
    float N = c.params.x;
    vec3 r = vec3(c.r);
    AlPoly lit = al_clip(al_polygon_directions(c, side), n);
    float diffuse = al_polygon_diffuse(lit, n);
    AlPoly D = al_clip(lit, r);
    vec3 sums = vec3(0.0f);
    bool inside = D.count >= 3;
    float sweep_near = 0.0f, sweep_far = 0.0f, size_near = 0.0f, size_far = 0.0f;
    for (int i = 0; i < AL_POLY_CAP; ++i) {
        if (i >= D.count) break;
        inside = inside && dot(D.m[i], r) >= 0.0f;
        AlPhongEdge e = al_phong_edge(D.v[i], D.v[i + 1 < D.count ? i + 1 : 0], D.m[i], r, n, N);
        sums += e.sums;
        if (e.near_edge) {
            sweep_near += e.sweep;
            size_near += abs(e.sweep);
        } else {
            sweep_far += e.sweep;
            size_far += abs(e.sweep);
        }
    }
    // 2 pi [r in D] - sum over near arcs of their sweep equals the far arcs' sweep:
    // take whichever group cancels less.
    float winding = size_near <= size_far ? (inside ? AL_TWO_PI : 0.0f) - sweep_near : sweep_far;
    float moment = (winding - sums.x) / AL_TWO_PI;
    float specular = (dot(r, n) * (winding - sums.y) + sums.z) / AL_TWO_PI;
    return vec4(diffuse, specular, moment, 0.0f);
}
#endif
