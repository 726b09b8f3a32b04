// The library entry for ellipsoid lights (CONTRACT.md 1, 5): x = c + A y with
// A = [a0 a1 a2] (orthogonal semi-axes) maps the unit sphere onto the ellipsoid,
// and cones through p to cones through y_p = A^-1 (p - c), so the silhouette is
// the image of the unit sphere's from y_p (library/sphere.glsl): the circle in the
// plane y.y_p = 1, centre y_p / t^2, radius rho = sqrt(1 - 1/t^2), t = |y_p|. Its
// image is an ellipse with centre at rho^2 (c - p) from p and conjugate
// semi-diameters rho A e1, rho A e2 (e1, e2 orthonormal, both perpendicular to
// y_p). p inside or on the ellipsoid (t <= 1) gets 0.

AlCase al_ellipsoid_record(ArealightSurface s, vec3 center, vec3 axes[3]) {
    rvec3 a0 = rvec3(axes[0]), a1 = rvec3(axes[1]), a2 = rvec3(axes[2]);
    rvec3 to_c = rvec3(center) - rvec3(s.p);
    real l0 = dot(a0, a0), l1 = dot(a1, a1), l2 = dot(a2, a2);
    // y_p = A^-1 (p - c): A's columns are orthogonal.
    rvec3 yp = -rvec3(dot(a0, to_c) / l0, dot(a1, to_c) / l1, dot(a2, to_c) / l2);
    real t = length(yp);
    bool lit = t > AL_R(1.0) && l0 > AL_R(0.0) && l1 > AL_R(0.0) && l2 > AL_R(0.0) && !isinf(t);
    real rho2 = lit ? (t - AL_R(1.0)) * (t + AL_R(1.0)) / (t * t) : AL_R(0.0);
    rvec3 e1, e2;
    al_tangent_frame(lit ? yp / t : rvec3(AL_R(0.0), AL_R(0.0), AL_R(1.0)), e1, e2);
    real rho = sqrt(rho2);
    rvec3 U = rho * (e1.x * a0 + e1.y * a1 + e1.z * a2);
    rvec3 V = rho * (e2.x * a0 + e2.y * a1 + e2.z * a2);
    return al_light_record(al_ellipse_record(s, rho2 * to_c, U, V, lit));
}

vec4 al_ellipsoid_evaluate(ArealightSurface s, vec3 center, vec3 axes[3]) {
    return al_clean(al_shade(al_ellipsoid_record(s, center, axes)));
}
