// Energy-conserving Phong, CONTRACT.md 2: f = (N+2)/(2 pi) (r.w)_+^N.

// (r.w)_+^N for unit r, w and N in [1, 1e5]. Relative error ~N ulp of log(r.w),
// from 1 - r.w = |r - w|^2 / 2 (no cancellation) and log1p.
real al_phong_power(rvec3 r, rvec3 w, real N) {
    real c = dot(r, w);
    if (c <= AL_R(0.0)) return AL_R(0.0);
    rvec3 d = r - w;
    return al_exp(N * al_log1p(AL_R(-0.5) * dot(d, d)));
}

// The BRDF value itself (point evaluation, for the point-light baseline).
real al_phong_brdf(rvec3 r, rvec3 w, real N) {
    return (N + AL_R(2.0)) / AL_TWO_PI * al_phong_power(r, w, N);
}
