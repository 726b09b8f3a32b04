// Shared vocabulary of every variant: the case record the host uploads, the
// result record, and numerically careful helpers. Valid GLSL 4.50 and, through
// the mirror prolog, C++ with GLM (one source of truth for both backends).

const float AL_PI = 3.14159265358979f;
const float AL_TWO_PI = 6.28318530717959f;

// One case, normalized on the host (CONTRACT.md 1), in double precision: p moved
// to the origin, lengths divided by the light's distance, and the frame rotated
// so that the light's centre lies on +z. Near the light, directions then differ
// from the pole in small components that fp32 holds to full relative precision
// (in a world frame the edges' distances to r would carry 6e-8 absolute error).
// n, v unit; r = 2 (n.v) n - v formed on the host for the same reason. verts =
// polygon vertices relative to the centre. params = (exponent or alpha,
// two_sided, vertex count, 0). 208 bytes, std430.
struct AlCase {
    vec4 n;
    vec4 v;
    vec4 r;
    vec4 params;
    vec4 center;
    vec4 verts[8];
};

// atan(y / x) on [-1, 1]: argument reduction by pi/6 to |t| <= tan(pi/12), then
// the odd Taylor series to t^13 (truncation < 2e-10 relative). Relative error a
// few ulp, also for tiny t. Drivers' atan (lavapipe: 2e-5) is not accurate enough.
float al_atan_unit(float t) {
    float a = abs(t), base = 0.0f;
    if (a > 0.26794919f) {
        a = (a * 1.7320508f - 1.0f) / (a + 1.7320508f);
        base = 0.52359878f;
    }
    float a2 = a * a;
    float p = a * (1.0f + a2 * (-1.0f / 3.0f + a2 * (0.2f + a2 * (-1.0f / 7.0f + a2 * (1.0f / 9.0f +
                  a2 * (-1.0f / 11.0f + a2 * (1.0f / 13.0f)))))));
    return t < 0.0f ? -(base + p) : base + p;
}

// atan2(y, x) in (-pi, pi], 0 for (0, 0). Error a few ulp (al_atan_unit).
float al_atan2(float y, float x) {
    float ax = abs(x), ay = abs(y);
    if (ax == 0.0f && ay == 0.0f) return 0.0f;
    float r = ay <= ax ? al_atan_unit(ay / ax) : 1.57079633f - al_atan_unit(ax / ay);
    if (x < 0.0f) r = 3.14159265f - r;
    return y < 0.0f ? -r : r;
}

// Natural log for x > 0: frexp reduction to m in [sqrt(1/2), sqrt(2)), then
// 2 atanh((m - 1)/(m + 1)) to the 11th power (truncation < 4e-10). Error a few ulp
// (lavapipe's log: 7e-6 relative).
float al_log(float x) {
    int e;
    float m = frexp(x, e);
    if (m < 0.70710678f) {
        m *= 2.0f;
        e -= 1;
    }
    float w = (m - 1.0f) / (m + 1.0f), w2 = w * w;
    float s = 2.0f * w * (1.0f + w2 * (1.0f / 3.0f + w2 * (0.2f + w2 * (1.0f / 7.0f + w2 * (1.0f / 9.0f +
                  w2 / 11.0f)))));
    return float(e) * 0.69314718f + s;
}

// log(1 + z) for z in (-1, inf). Relative error ~1 ulp; for |z| < 1/4 the series
// 2 atanh(z / (2 + z)) (5 terms, truncation < 3e-9 relative) avoids log(1 + z)'s cancellation.
float al_log1p(float z) {
    if (abs(z) < 0.25f) {
        float w = z / (2.0f + z);
        float w2 = w * w;
        return 2.0f * w * (1.0f + w2 * (1.0f / 3.0f + w2 * (0.2f + w2 * (1.0f / 7.0f + w2 / 9.0f))));
    }
    return al_log(1.0f + z);
}

// exp(z) - 1 for z <= 0 (used for 1 - x^k). Relative error a few ulp: Taylor to z^8
// for |z| < 1/2 (truncation < 1e-9 relative), exp(z) - 1 beyond, where it cannot cancel.
float al_expm1(float z) {
    if (abs(z) < 0.5f) {
        return z * (1.0f + z * (0.5f + z * (1.0f / 6.0f + z * (1.0f / 24.0f +
                    z * (1.0f / 120.0f + z * (1.0f / 720.0f + z * (1.0f / 5040.0f + z / 40320.0f)))))));
    }
    return exp(z) - 1.0f;
}

// Replaces NaN, infinities and negatives by 0: no bad value leaves a shader
// (CONTRACT.md 2 asks for finite values >= 0 everywhere).
float al_clean(float x) { return (x >= 0.0f && x <= 3.0e38f) ? x : 0.0f; }
vec4 al_clean(vec4 x) { return vec4(al_clean(x.x), al_clean(x.y), al_clean(x.z), al_clean(x.w)); }
