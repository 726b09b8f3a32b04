// The CPU mirror's support (include/arealight/mirror_support.hpp): binary16 rounding of
// al_half and its vectors, the GLSL surface the templates use (found by ADL from a
// namespace that uses glm, as the generated mirror is), and texture()'s bilinear rule.
// The device side of both (lavapipe against these) is in tests/test_vulkan_runner.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <random>
#include <type_traits>

#include "arealight/mirror_support.hpp"

namespace {

const float kInf = std::numeric_limits<float>::infinity();
// 2^e as a float.
float p2(int e) {
    return std::ldexp(1.0f, e);
}
// texture() against the spec's weights in double: fp32 coordinates and lerps, a few ulp.
constexpr double kBilinearRelTol = 1e-6;

// The generated mirror's setting: its own namespace, `using namespace glm`, and
// unqualified calls (arealight::mirror's overloads must win over GLM's templates).
namespace al_mirror_probe {
using namespace glm;
al_half scalar_calls(al_half a, al_half b, al_half c) {
    return fma(clamp(mix(a, b, c), min(a, b), max(a, b)), sign(a), abs(c)) + sqrt(abs(b)) +
           inversesqrt(abs(a) + al_half(1.0));
}
al_hvec3 vector_calls(al_hvec3 u, al_hvec3 v, al_half s) {
    al_hvec3 r = normalize(cross(u, v)) * length(u) + abs(u) * dot(u, v);
    r += mix(u, v, s) - clamp(v, al_half(-1.0), al_half(1.0)) + max(u, v) - min(u, s) / s;
    r *= sign(v).x;
    return -r + sqrt(abs(u)) + inversesqrt(abs(v) + al_hvec3(1.0)) + fma(u, v, u);
}
vec4 sample(const AlSampler2D& s, vec2 uv) {
    return texture(s, uv);
}
}  // namespace al_mirror_probe

}  // namespace

using arealight::Texture2D;

TEST_CASE("al_half rounds to binary16, ties to even", "[mirror][fp16]") {
    const float one = 1.0f;
    CHECK(float(al_half(one + p2(-11))) == 1.0f);                     // tie: to even 1
    CHECK(float(al_half(one + 3 * p2(-11))) == one + p2(-9));         // tie: to even
    CHECK(float(al_half(one + p2(-11) + p2(-20))) == one + p2(-10));  // above the tie
    CHECK(float(al_half(one + p2(-12))) == 1.0f);                     // below the tie
    CHECK(float(al_half(-(one + 3 * p2(-11)))) == -(one + p2(-9)));
    // Overflow: 65504 is the largest; from 65520 (its tie with 2^16) on, infinity.
    CHECK(float(al_half(65504.0f)) == 65504.0f);
    CHECK(float(al_half(65519.0f)) == 65504.0f);
    CHECK(float(al_half(65520.0f)) == kInf);
    CHECK(float(al_half(-65520.0f)) == -kInf);
    CHECK(float(al_half(1e30)) == kInf);
    // Subnormals: spacing 2^-24; 2^-25 ties to 0, 3 * 2^-25 ties to the even 2^-23, and
    // just above 2^-25 is 2^-24.
    CHECK(float(al_half(p2(-14))) == p2(-14));  // smallest normal
    CHECK(float(al_half(p2(-24))) == p2(-24));  // smallest subnormal
    CHECK(float(al_half(p2(-25))) == 0.0f);
    CHECK(float(al_half(p2(-25) + p2(-30))) == p2(-24));
    CHECK(float(al_half(3 * p2(-25))) == p2(-23));
    CHECK(float(al_half(5 * p2(-26))) == p2(-24));
    CHECK(float(al_half(p2(-14) - p2(-25))) == p2(-14));  // ties up to the smallest normal
    CHECK(al_half(p2(-24)).bits() == 0x0001);
    CHECK(al_half(65504.0f).bits() == 0x7bff);
    CHECK(al_half(-0.0f).bits() == 0x8000);
    CHECK(std::signbit(float(al_half(-0.0f))));
    CHECK(std::isnan(float(al_half(std::numeric_limits<float>::quiet_NaN()))));
    CHECK(float(al_half::from_bits(0x3c01)) == one + p2(-10));
    // From double in one rounding: through float this would tie and round to 1.
    CHECK(float(al_half(1.0 + std::ldexp(1.0, -11) + std::ldexp(1.0, -40))) == one + p2(-10));
    // From int.
    CHECK(float(al_half(2049)) == 2048.0f);
    CHECK(float(al_half(2051)) == 2052.0f);
    CHECK(float(al_half(-3)) == -3.0f);
}

TEST_CASE("al_half rounds every operation and fma once", "[mirror][fp16]") {
    const al_half one(1.0), a(1.0f + p2(-10)), b(1.0f + 3 * p2(-10));
    CHECK(float(one + al_half(p2(-11))) == 1.0f);
    CHECK(float(a + al_half(p2(-11))) == 1.0f + p2(-9));
    CHECK(float(a * a) == 1.0f + p2(-9));  // exact 1 + 2^-9 + 2^-20
    CHECK(float(one / al_half(3.0)) == float(al_half(1.0 / 3.0)));
    CHECK(float(al_half(256.0) * al_half(256.0)) == kInf);
    CHECK(float(al_half(-65504.0) - al_half(32.0)) == -kInf);  // -65536: past the tie
    CHECK(float(al_half(-65504.0) - al_half(8.0)) == -65504.0f);
    CHECK(float(al_half(p2(-14)) * al_half(0.5)) == p2(-15));  // subnormal, exact
    CHECK(float(al_half(p2(-24)) * al_half(0.5)) == 0.0f);     // tie to 0
    CHECK(float(al_half(p2(-24)) * al_half(0.75)) == p2(-24));
    CHECK(float(sqrt(al_half(2.0))) == float(al_half(std::sqrt(2.0))));
    CHECK(float(sqrt(al_half(p2(-24)))) == p2(-12));
    // No excess precision between operations: a * b = 1 + 2^-8 + 3 * 2^-20 rounds to
    // 1 + 2^-8 before c is added; fma keeps the product exact.
    const al_half c(-(1.0f + p2(-8)));
    CHECK(float(a * b + c) == 0.0f);
    CHECK(float(fma(a, b, c)) == 3 * p2(-20));
    // Compound assignment rounds too.
    al_half s = one;
    s += al_half(p2(-11));
    CHECK(float(s) == 1.0f);
    s -= al_half(p2(-11));
    CHECK(float(s) == 1.0f - p2(-11));
    s *= al_half(3.0);
    INFO("s = " << float(s));
    CHECK(float(s) == float(al_half(3.0 * (1.0 - std::ldexp(1.0, -11)))));
    s /= al_half(0.0);
    CHECK(float(s) == kInf);
    CHECK(float(-a) == -(1.0f + p2(-10)));
    // Functions: exact ones, then GLSL's definitions.
    CHECK(float(abs(al_half(-2.5))) == 2.5f);
    CHECK(float(sign(al_half(-2.5))) == -1.0f);
    CHECK(float(sign(al_half(0.0))) == 0.0f);
    CHECK(float(min(al_half(1.0), al_half(-2.0))) == -2.0f);
    CHECK(float(max(al_half(1.0), al_half(-2.0))) == 1.0f);
    CHECK(float(clamp(al_half(5.0), al_half(-1.0), al_half(2.0))) == 2.0f);
    CHECK(float(clamp(al_half(-5.0), al_half(-1.0), al_half(2.0))) == -1.0f);
    // inversesqrt: sqrt rounded, then 1 / it rounded (lavapipe's rule).
    CHECK(float(inversesqrt(al_half(4.0))) == 0.5f);
    CHECK(float(inversesqrt(al_half(3.0))) == float(al_half(1.0) / sqrt(al_half(3.0))));
    // mix = x (1 - a) + y a, each rounded.
    const al_half x(3.0), y(7.0), t(0.1);
    CHECK(float(mix(x, y, t)) == float(x * (al_half(1.0) - t) + y * t));
    CHECK(float(mix(x, y, al_half(0.5))) == 5.0f);
    // Comparisons.
    CHECK(al_half(1.0) < al_half(2.0));
    CHECK(al_half(2.0) >= al_half(2.0));
    CHECK(al_half(1.0) != al_half(1.0f + p2(-10)));
    CHECK(al_half(1.0) == al_half(1.0f + p2(-12)));
}

TEST_CASE("al_half follows GLSL's conversions", "[mirror][fp16]") {
    // float16_t -> float implicitly; float -> float16_t only explicitly.
    static_assert(std::is_convertible<al_half, float>::value, "");
    static_assert(!std::is_convertible<float, al_half>::value, "");
    static_assert(!std::is_convertible<double, al_half>::value, "");
    static_assert(!std::is_convertible<glm::vec3, al_hvec3>::value, "");
    static_assert(std::is_convertible<al_hvec3, glm::vec3>::value, "");
    // Mixed half and float arithmetic is float, as in GLSL.
    static_assert(std::is_same<decltype(al_half(1.0) + 1.0f), float>::value, "");
    static_assert(std::is_same<decltype(al_hvec3(1.0) * 2.0f), glm::vec3>::value, "");
    static_assert(std::is_same<decltype(al_hvec3(1.0) + glm::vec3(1.0f)), glm::vec3>::value, "");
    static_assert(std::is_same<decltype(al_hvec3(1.0) * al_half(2.0)), al_hvec3>::value, "");
    static_assert(std::is_same<decltype(dot(al_hvec3(), al_hvec3())), al_half>::value, "");
    const al_half h(0.1);
    CHECK(float(h) == float(al_half(0.1f)));
    CHECK(al_half(1.0) + 1e-4f == 1.0f + 1e-4f);  // in float: not rounded to half
    const glm::vec3 v3 = glm::vec3(al_hvec3(0.1, 0.2, 0.3));
    CHECK(v3.x == float(al_half(0.1)));
    CHECK(v3.z == float(al_half(0.3)));
    CHECK(glm::vec2(al_hvec2(1.5, 2.5)) == glm::vec2(1.5f, 2.5f));
    CHECK(glm::vec4(al_hvec4(al_hvec3(1, 2, 3), 4.0f)) == glm::vec4(1, 2, 3, 4));
    CHECK(glm::vec3(h) == glm::vec3(float(h)));
}

TEST_CASE("al_hvec constructs, operates and reduces per component, rounding each step",
          "[mirror][fp16]") {
    const float one = 1.0f;
    // From glm vectors: each component rounded.
    const al_hvec3 r(glm::vec3(one + p2(-11), 3 * p2(-25), 70000.0f));
    CHECK(float(r.x) == 1.0f);
    CHECK(float(r.y) == p2(-23));
    CHECK(float(r.z) == kInf);
    const al_hvec4 q(glm::vec4(0.1f, -0.2f, 0.3f, -0.4f));
    CHECK(float(q.w) == float(al_half(-0.4f)));
    // Splat and components.
    const al_hvec3 s(0.5);
    CHECK((s.x == al_half(0.5) && s.y == al_half(0.5) && s.z == al_half(0.5)));
    CHECK(al_hvec2(2) == al_hvec2(2.0f, 2.0f));
    const al_hvec3 u(1.0f, 2.0, 3);
    CHECK(u[1] == al_half(2.0));
    // Operators: vector-vector, vector-scalar, scalar-vector, unary, compound.
    CHECK(u + s == al_hvec3(1.5, 2.5, 3.5));
    CHECK(u - s == al_hvec3(0.5, 1.5, 2.5));
    CHECK(u * u == al_hvec3(1, 4, 9));
    CHECK(u / al_hvec3(2.0) == al_hvec3(0.5, 1.0, 1.5));
    CHECK(u * al_half(2.0) == al_hvec3(2, 4, 6));
    CHECK(al_half(2.0) * u == al_hvec3(2, 4, 6));
    CHECK(u / al_half(4.0) == al_hvec3(0.25, 0.5, 0.75));
    CHECK(al_half(6.0) / u == al_hvec3(6, 3, 2));
    CHECK(-u == al_hvec3(-1, -2, -3));
    al_hvec3 w = u;
    w += al_hvec3(one + p2(-11));  // 2 + 2^-11 ties to 2; 3 + ... to 3; 4 + ... to 4
    CHECK(w == al_hvec3(2, 3, 4));
    w *= al_half(0.5);
    CHECK(w == al_hvec3(1, 1.5, 2));
    w -= u;
    w /= al_half(0.5);
    CHECK(w == al_hvec3(0, -1, -2));
    w += al_half(2.0);
    w -= al_half(0.5);
    CHECK(w == al_hvec3(1.5, 0.5, -0.5));
    CHECK(u + al_half(1.0) == al_hvec3(2, 3, 4));
    CHECK(al_half(1.0) - u == al_hvec3(0, -1, -2));
    // Each component's product rounded.
    const al_hvec3 a(one + p2(-10));
    CHECK(a * a == al_hvec3(one + p2(-9)));
}

TEST_CASE("al_hvec geometric functions round after each scalar operation", "[mirror][fp16]") {
    // dot = ((x x' + y y') + z z'): 2048 + 1 ties to 2048, twice; another order gives 2050.
    CHECK(float(dot(al_hvec3(2048, 1, 1), al_hvec3(1, 1, 1))) == 2048.0f);
    CHECK(float(dot(al_hvec3(1, 1, 2048), al_hvec3(1, 1, 1))) == 2050.0f);
    CHECK(float(dot(al_hvec4(1, 2, 3, 4), al_hvec4(1, 1, 1, 1))) == 10.0f);
    CHECK(float(dot(al_hvec2(3, 4), al_hvec2(3, 4))) == 25.0f);
    // length = sqrt(dot), normalize = v / length (each quotient rounded).
    CHECK(float(length(al_hvec3(3, 4, 0))) == 5.0f);
    const al_hvec3 n = normalize(al_hvec3(3, 4, 0));
    CHECK(n == al_hvec3(al_half(3.0) / al_half(5.0), al_half(4.0) / al_half(5.0), al_half(0.0)));
    CHECK(float(n.x) == float(al_half(0.6)));
    // cross: (a.y b.z - b.y a.z, ...), products and differences rounded.
    CHECK(cross(al_hvec3(1, 0, 0), al_hvec3(0, 1, 0)) == al_hvec3(0, 0, 1));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> d(-4.0f, 4.0f);
    for (int k = 0; k < 100; ++k) {
        const al_hvec3 p(al_half(d(rng)), al_half(d(rng)), al_half(d(rng)));
        const al_hvec3 q(al_half(d(rng)), al_half(d(rng)), al_half(d(rng)));
        const al_hvec3 c = cross(p, q);
        CHECK(c.x == p.y * q.z - q.y * p.z);
        CHECK(c.y == p.z * q.x - q.z * p.x);
        CHECK(c.z == p.x * q.y - q.x * p.y);
        CHECK(dot(p, q) == (p.x * q.x + p.y * q.y) + p.z * q.z);
        CHECK(length(p) == sqrt((p.x * p.x + p.y * p.y) + p.z * p.z));
    }
    // Component-wise functions.
    const al_hvec3 v(-2, 0.25, 9);
    CHECK(abs(v) == al_hvec3(2, 0.25, 9));
    CHECK(sign(v) == al_hvec3(-1, 1, 1));
    CHECK(sqrt(abs(v)) == al_hvec3(al_half(std::sqrt(2.0)), al_half(0.5), al_half(3.0)));
    CHECK(inversesqrt(al_hvec3(4, 0.25, 16)) == al_hvec3(0.5, 2, 0.25));
    CHECK(min(v, al_hvec3(0)) == al_hvec3(-2, 0, 0));
    CHECK(max(v, al_half(0.5)) == al_hvec3(0.5, 0.5, 9));
    CHECK(clamp(v, al_half(0), al_half(1)) == al_hvec3(0, 0.25, 1));
    CHECK(mix(al_hvec3(0), al_hvec3(4), al_half(0.25)) == al_hvec3(1));
    CHECK(fma(al_hvec3(2), v, al_hvec3(1)) == al_hvec3(-3, 1.5, 19));
}

TEST_CASE("the GLSL surface resolves by ADL from a namespace using glm", "[mirror][fp16]") {
    const al_half a(0.75), b(-1.5), c(0.25);
    const al_half r = al_mirror_probe::scalar_calls(a, b, c);
    CHECK(std::isfinite(float(r)));
    const al_hvec3 v = al_mirror_probe::vector_calls(al_hvec3(1, 2, 3), al_hvec3(-1, 0.5, 2), c);
    CHECK(std::isfinite(float(v.x)));
    Texture2D t;
    t.width = t.height = 1;
    t.rgba = {1, 2, 3, 4};
    CHECK(al_mirror_probe::sample(AlSampler2D{&t}, glm::vec2(0.3f, 0.9f)) == glm::vec4(1, 2, 3, 4));
}

namespace {

// A w x h table with texel (i, j), channel c = 100 j + 10 i + c: small integers, so
// that lerps at the weights used below are exact.
Texture2D integer_table(std::uint32_t w, std::uint32_t h) {
    Texture2D t;
    t.width = w;
    t.height = h;
    for (std::uint32_t j = 0; j < h; ++j)
        for (std::uint32_t i = 0; i < w; ++i)
            for (int c = 0; c < 4; ++c) t.rgba.push_back(100.0f * j + 10.0f * i + c);
    return t;
}
glm::vec4 texel(const Texture2D& t, int i, int j) {
    const float* p = &t.rgba[(static_cast<std::size_t>(j) * t.width + i) * 4];
    return {p[0], p[1], p[2], p[3]};
}

// The spec's weights, in double, with CLAMP_TO_EDGE.
glm::dvec4 spec_bilinear(const Texture2D& t, double s, double r) {
    const double u = s * t.width - 0.5, v = r * t.height - 0.5;
    const double fu = std::floor(u), fv = std::floor(v), a = u - fu, b = v - fv;
    auto clampi = [](double i, std::uint32_t n) {
        return static_cast<int>(std::min<double>(std::max<double>(i, 0.0), n - 1.0));
    };
    const int i0 = clampi(fu, t.width), i1 = clampi(fu + 1, t.width);
    const int j0 = clampi(fv, t.height), j1 = clampi(fv + 1, t.height);
    auto T = [&](int i, int j) { return glm::dvec4(texel(t, i, j)); };
    return (1 - a) * (1 - b) * T(i0, j0) + a * (1 - b) * T(i1, j0) + (1 - a) * b * T(i0, j1) +
           a * b * T(i1, j1);
}

}  // namespace

TEST_CASE("texture() filters bilinearly with CLAMP_TO_EDGE", "[mirror][texture]") {
    using arealight::mirror::texture;
    for (const auto& size : {glm::uvec2(4, 4), glm::uvec2(8, 2), glm::uvec2(1, 4)}) {
        const Texture2D t = integer_table(size.x, size.y);
        const AlSampler2D s{&t};
        const float w = static_cast<float>(t.width), h = static_cast<float>(t.height);
        INFO(t.width << " x " << t.height);
        for (std::uint32_t j = 0; j < t.height; ++j) {
            for (std::uint32_t i = 0; i < t.width; ++i) {
                const int ii = static_cast<int>(i), jj = static_cast<int>(j);
                INFO("texel " << i << ", " << j);
                // Centres: the texel exactly.
                CHECK(texture(s, {(i + 0.5f) / w, (j + 0.5f) / h}) == texel(t, ii, jj));
                // Edges: clamped to the border texels, whatever the distance outside.
                CHECK(texture(s, {0.0f, (j + 0.5f) / h}) == texel(t, 0, jj));
                CHECK(texture(s, {-3.0f, (j + 0.5f) / h}) == texel(t, 0, jj));
                CHECK(texture(s, {1.0f, (j + 0.5f) / h}) == texel(t, t.width - 1, jj));
                CHECK(texture(s, {7.5f, (j + 0.5f) / h}) == texel(t, t.width - 1, jj));
                CHECK(texture(s, {(i + 0.5f) / w, -1e30f}) == texel(t, ii, 0));
                CHECK(texture(s, {(i + 0.5f) / w, 1.0f}) == texel(t, ii, t.height - 1));
                // Midpoints between texel centres: the mean of the two (of four).
                if (i + 1 < t.width) {
                    const glm::vec4 mid = texture(s, {(i + 1.0f) / w, (j + 0.5f) / h});
                    CHECK(mid == (texel(t, ii, jj) + texel(t, ii + 1, jj)) * 0.5f);
                }
                if (i + 1 < t.width && j + 1 < t.height) {
                    const glm::vec4 mid = texture(s, {(i + 1.0f) / w, (j + 1.0f) / h});
                    CHECK(mid == (texel(t, ii, jj) + texel(t, ii + 1, jj) + texel(t, ii, jj + 1) +
                                  texel(t, ii + 1, jj + 1)) *
                                     0.25f);
                }
            }
        }
        // Anywhere: the spec's weights, to fp32 rounding.
        std::mt19937 rng(17);
        std::uniform_real_distribution<float> coord(-0.2f, 1.2f);
        double worst = 0.0;
        for (int k = 0; k < 2000; ++k) {
            const glm::vec2 uv(coord(rng), coord(rng));
            const glm::vec4 got = texture(s, uv);
            const glm::dvec4 want = spec_bilinear(t, uv.x, uv.y);
            for (int c = 0; c < 4; ++c)
                worst =
                    std::max(worst, std::abs(got[c] - want[c]) / std::max(std::abs(want[c]), 1.0));
        }
        INFO("worst relative difference to the spec's weights " << worst);
        CHECK(worst <= kBilinearRelTol);
    }
    // An unbound sampler reads NaN; NaN coordinates read an edge texel.
    CHECK(std::isnan(texture(AlSampler2D{}, {0.5f, 0.5f}).x));
    const Texture2D t = integer_table(4, 4);
    CHECK(texture(AlSampler2D{&t}, {std::nanf(""), 0.125f}) == texel(t, 0, 0));
}
