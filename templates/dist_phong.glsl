// Energy-conserving Phong, CONTRACT.md 2: f = (N+2)/(2 pi) (r.w)_+^N.

// (r.w)_+^N for unit r, w and N in [1, 1e5]. Relative error ~N ulp of log(r.w),
// from 1 - r.w = |r - w|^2 / 2 (no cancellation) and log1p.
float al_phong_power(vec3 r, vec3 w, float N) {
    float c = dot(r, w);
    if (c <= 0.0f) return 0.0f;
    vec3 d = r - w;
    return exp(N * al_log1p(-0.5f * dot(d, d)));
}

// The BRDF value itself (point evaluation, for the point-light baseline).
float al_phong_brdf(vec3 r, vec3 w, float N) {
    return (N + 2.0f) / AL_TWO_PI * al_phong_power(r, w, N);
}
