// What the CPU mirror (generator/mirror_tool.cpp) needs beyond GLM to compile the
// templates as C++: sampled textures and half-precision arithmetic, each as the
// GPU computes it. Every generated mirror shard includes this header.
//
// - AlSampler2D, texture(): the Vulkan runner's sampler (runtime/vulkan_runner.cpp:
//   linear min/mag filtering, normalized coordinates, CLAMP_TO_EDGE, one level).
// - al_half, al_hvec2..4: GLSL's float16_t and f16vec2..4 (the stitcher maps hreal and
//   hvec2..4 to them in fp16 variants), every operation rounded to IEEE binary16
//   (nearest even, subnormals kept, overflow to infinity). Vector functions round
//   after each scalar operation, in this order: dot = ((x x' + y y') + z z') + w w';
//   length = sqrt(dot(v, v)); normalize = v / length(v); cross = (y z' - y' z,
//   z x' - z' x, x y' - x' y); inversesqrt = 1 / sqrt(x); mix = x (1 - a) + y a.
//   These are lavapipe's (llvmpipe, Mesa 22.3: no fp16 fusion, rsq as 1 / sqrt,
//   normalize as a quotient): bit-identical there on random operands over the whole
//   range (tests/test_vulkan_runner.cpp). fma alone differs: al_half's rounds once,
//   lavapipe's twice (as a * b + c).
//
// The types live in arealight::mirror and are named at global scope; the functions
// (dot, max, texture, ...) are found by argument-dependent lookup from the generated
// code (namespace al_mirror_N { using namespace glm; ... }), where these non-template
// overloads win over GLM's templates. Mixed half/float expressions follow GLSL: an
// al_half converts implicitly to float (h + 1.0f is a float, as float16_t + float is
// in GLSL), but nothing converts implicitly to al_half (float16_t h = 1.0 is an error
// in GLSL too): write hreal(1.0).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <limits>
#include <type_traits>

#include "arealight/texture.hpp"

#if !defined(__FLT16_MANT_DIG__)
#error "mirror_support.hpp needs the compiler's _Float16 (GCC >= 12 or Clang on x86-64)"
#endif

namespace arealight::mirror {

// ---------------------------------------------------------------------------------
// Textures

// A sampler binding of a mirror: the texture the mirror's run() bound (nullptr: none,
// and texture() returns NaN, so a missing table cannot pass for data).
struct AlSampler2D {
    const Texture2D* tex = nullptr;
};

namespace detail {

// One axis of the linear filter: the two texel indices and the second one's weight.
// Vulkan spec, "Texel Filtering" / "Unnormalized Texel Coordinate Operations", fp32:
// u = s * size - 0.5, i0 = floor(u), alpha = frac(u), i1 = i0 + 1, each index clamped
// to [0, size - 1] (CLAMP_TO_EDGE). Where both clamp to the same texel the weight is
// irrelevant and set to 0, so edges return the texel exactly.
struct Axis {
    int i0, i1;
    float alpha;
};
inline Axis axis(float s, std::uint32_t size) {
    const float u = s * static_cast<float>(size) - 0.5f;
    const int last = static_cast<int>(size) - 1;
    // Far outside [0, 1] (or NaN) every index clamps to one edge: decide before
    // converting, so that no float -> int conversion overflows.
    if (!(u >= 0.0f)) return {0, 0, 0.0f};
    if (u >= static_cast<float>(last)) return {last, last, 0.0f};
    const float f = std::floor(u);
    const int i0 = static_cast<int>(f);
    return {i0, i0 + 1, u - f};
}

// v0 + a (v1 - v0) with one rounding of the product-add, as llvmpipe's lerp
// (lp_build_lerp: fmuladd, an fma on x86-64 with FMA): equal to the spec's
// (1 - a) v0 + a v1 up to fp32 rounding, and exactly v0 at a = 0.
inline float lerp(float a, float v0, float v1) {
    return std::fma(a, v1 - v0, v0);
}

}  // namespace detail

// Linear filtering of s.tex at normalized (uv.x, uv.y) with CLAMP_TO_EDGE, in fp32:
// the texel weights of the Vulkan spec ((1 - a)(1 - b) T[i0, j0] + a (1 - b) T[i1, j0] +
// (1 - a) b T[i0, j1] + a b T[i1, j1], detail::axis), evaluated as two lerps along x
// and one along y (detail::lerp), which is how lavapipe rounds them: bit-identical to
// it (full fp32 weights, no quantisation) on 90k random and special coordinates, where
// the spec's sum of four weighted texels differs by up to 2.3e-7 relative.
inline glm::vec4 texture(const AlSampler2D& s, glm::vec2 uv) {
    const Texture2D* t = s.tex;
    if (!t || t->width == 0 || t->height == 0 ||
        t->rgba.size() != static_cast<std::size_t>(t->width) * t->height * 4) {
        return glm::vec4(std::numeric_limits<float>::quiet_NaN());
    }
    const detail::Axis x = detail::axis(uv.x, t->width), y = detail::axis(uv.y, t->height);
    auto texel = [t](int i, int j, int c) {
        return t->rgba[(static_cast<std::size_t>(j) * t->width + static_cast<std::size_t>(i)) * 4 +
                       static_cast<std::size_t>(c)];
    };
    glm::vec4 out;
    for (int c = 0; c < 4; ++c) {
        const float row0 = detail::lerp(x.alpha, texel(x.i0, y.i0, c), texel(x.i1, y.i0, c));
        const float row1 = detail::lerp(x.alpha, texel(x.i0, y.i1, c), texel(x.i1, y.i1, c));
        out[c] = detail::lerp(y.alpha, row0, row1);
    }
    return out;
}

// ---------------------------------------------------------------------------------
// Half precision

namespace detail {

// Rounds to the nearest binary16 value (ties to even; below 2^-14 to subnormals, below
// 2^-25 to zero; from 65520 on to infinity), returned as the float of equal value.
// Through the compiler's _Float16, whose conversions round in software or with F16C;
// the value leaves as a float at once, so no excess precision survives.
inline float round_half(float f) {
    const _Float16 h = static_cast<_Float16>(f);
    return static_cast<float>(h);
}
// From double in one rounding (double -> float -> half could round twice).
inline float round_half(double d) {
    const _Float16 h = static_cast<_Float16>(d);
    return static_cast<float>(h);
}

}  // namespace detail

// GLSL float16_t. Holds a float whose value is always a binary16 value; every
// operation computes exactly or in fp32 and rounds once to binary16 (for + - * / and
// sqrt that is the correctly rounded binary16 result: fp32 has 2 * 11 + 2 bits).
class al_half {
  public:
    constexpr al_half() = default;
    // GLSL float16_t(x): explicit, rounding to nearest even.
    template <typename T, std::enable_if_t<std::is_arithmetic<T>::value, int> = 0>
    explicit al_half(T x) : v_(convert(x)) {}

    // float(h), and the implicit float16_t -> float conversion of GLSL.
    constexpr operator float() const { return v_; }
    constexpr float value() const { return v_; }
    // The IEEE binary16 encoding.
    std::uint16_t bits() const {
        const _Float16 h = static_cast<_Float16>(v_);
        std::uint16_t b;
        std::memcpy(&b, &h, sizeof b);
        return b;
    }
    static al_half from_bits(std::uint16_t b) {
        _Float16 h;
        std::memcpy(&h, &b, sizeof h);
        return exact(static_cast<float>(h));
    }
    // A float known to be a binary16 value already (no rounding).
    static constexpr al_half exact(float v) {
        al_half h;
        h.v_ = v;
        return h;
    }
    // Rounds a float result to binary16.
    static al_half round(float v) { return exact(detail::round_half(v)); }

    al_half& operator+=(al_half o) { return *this = round(v_ + o.v_); }
    al_half& operator-=(al_half o) { return *this = round(v_ - o.v_); }
    al_half& operator*=(al_half o) { return *this = round(v_ * o.v_); }
    al_half& operator/=(al_half o) { return *this = round(v_ / o.v_); }

  private:
    template <typename T>
    static float convert(T x) {
        if constexpr (std::is_same<T, float>::value || std::is_same<T, double>::value)
            return detail::round_half(x);
        else if constexpr (std::is_same<T, bool>::value)
            return x ? 1.0f : 0.0f;
        else
            return detail::round_half(static_cast<double>(x));
    }
    float v_ = 0.0f;
};

inline al_half operator+(al_half a, al_half b) {
    return al_half::round(float(a) + float(b));
}
inline al_half operator-(al_half a, al_half b) {
    return al_half::round(float(a) - float(b));
}
inline al_half operator*(al_half a, al_half b) {
    return al_half::round(float(a) * float(b));
}
inline al_half operator/(al_half a, al_half b) {
    return al_half::round(float(a) / float(b));
}
inline al_half operator-(al_half a) {
    return al_half::exact(-float(a));
}
inline al_half operator+(al_half a) {
    return a;
}
inline bool operator==(al_half a, al_half b) {
    return float(a) == float(b);
}
inline bool operator!=(al_half a, al_half b) {
    return float(a) != float(b);
}
inline bool operator<(al_half a, al_half b) {
    return float(a) < float(b);
}
inline bool operator<=(al_half a, al_half b) {
    return float(a) <= float(b);
}
inline bool operator>(al_half a, al_half b) {
    return float(a) > float(b);
}
inline bool operator>=(al_half a, al_half b) {
    return float(a) >= float(b);
}

// Scalar functions (GLSL.std.450 on float16_t), one rounding each unless stated.
inline al_half abs(al_half x) {
    return al_half::exact(std::fabs(float(x)));
}
inline al_half sign(al_half x) {
    const float v = float(x);
    return al_half::exact(v > 0.0f ? 1.0f : v < 0.0f ? -1.0f : v);
}
// GLSL's min(x, y) = y < x ? y : x, max(x, y) = x < y ? y : x; clamp = min(max(x, lo), hi).
inline al_half min(al_half x, al_half y) {
    return y < x ? y : x;
}
inline al_half max(al_half x, al_half y) {
    return x < y ? y : x;
}
inline al_half clamp(al_half x, al_half lo, al_half hi) {
    return min(max(x, lo), hi);
}
inline al_half sqrt(al_half x) {
    return al_half::round(std::sqrt(float(x)));
}
// 1 / sqrt(x) as two operations, each rounded: lavapipe's rule (its rsq is a square
// root, then a reciprocal; bit-identical in tests/test_vulkan_runner.cpp), which may
// differ from the correctly rounded reciprocal square root by an ulp.
inline al_half inversesqrt(al_half x) {
    return al_half::exact(1.0f) / sqrt(x);
}
// a * b + c rounded once (the product of two binary16 values and the sum are exact
// enough in double for one correct rounding to binary16). Note: lavapipe's fp16 fma
// rounds twice (a * b, then + c), like the unfused expression.
inline al_half fma(al_half a, al_half b, al_half c) {
    return al_half::exact(detail::round_half(static_cast<double>(float(a)) * float(b) + float(c)));
}
// GLSL mix(x, y, a) = x (1 - a) + y a, each operation rounded: ((x * (1 - a)) + (y * a)).
inline al_half mix(al_half x, al_half y, al_half a) {
    return x * (al_half::exact(1.0f) - a) + y * a;
}

// GLSL f16vec2..4: components al_half, every component operation as al_half's.
struct al_hvec2;
struct al_hvec3;
struct al_hvec4;

namespace detail {
template <typename T>
using if_scalar =
    std::enable_if_t<std::is_arithmetic<T>::value || std::is_same<T, al_half>::value, int>;
template <typename T>
al_half to_half(T x) {
    if constexpr (std::is_same<T, al_half>::value)
        return x;
    else
        return al_half(x);
}
}  // namespace detail

struct al_hvec2 {
    al_half x, y;

    al_hvec2() = default;
    // Splat: f16vec2(s).
    template <typename T, detail::if_scalar<T> = 0>
    explicit al_hvec2(T s) : x(detail::to_half(s)), y(x) {}
    template <typename A, typename B, detail::if_scalar<A> = 0, detail::if_scalar<B> = 0>
    al_hvec2(A a, B b) : x(detail::to_half(a)), y(detail::to_half(b)) {}
    // f16vec2(vec2): each component rounded.
    explicit al_hvec2(const glm::vec2& v) : x(v.x), y(v.y) {}
    // The implicit f16vec2 -> vec2 conversion of GLSL, and vec2(h).
    operator glm::vec2() const { return {float(x), float(y)}; }

    al_half& operator[](int i) { return i == 0 ? x : y; }
    al_half operator[](int i) const { return i == 0 ? x : y; }
    al_hvec2& operator+=(const al_hvec2& o) {
        x += o.x;
        y += o.y;
        return *this;
    }
    al_hvec2& operator-=(const al_hvec2& o) {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    al_hvec2& operator*=(const al_hvec2& o) {
        x *= o.x;
        y *= o.y;
        return *this;
    }
    al_hvec2& operator/=(const al_hvec2& o) {
        x /= o.x;
        y /= o.y;
        return *this;
    }
    al_hvec2& operator+=(al_half s) {
        x += s;
        y += s;
        return *this;
    }
    al_hvec2& operator-=(al_half s) {
        x -= s;
        y -= s;
        return *this;
    }
    al_hvec2& operator*=(al_half s) {
        x *= s;
        y *= s;
        return *this;
    }
    al_hvec2& operator/=(al_half s) {
        x /= s;
        y /= s;
        return *this;
    }
};

struct al_hvec3 {
    al_half x, y, z;

    al_hvec3() = default;
    template <typename T, detail::if_scalar<T> = 0>
    explicit al_hvec3(T s) : x(detail::to_half(s)), y(x), z(x) {}
    template <typename A, typename B, typename C, detail::if_scalar<A> = 0,
              detail::if_scalar<B> = 0, detail::if_scalar<C> = 0>
    al_hvec3(A a, B b, C c) : x(detail::to_half(a)), y(detail::to_half(b)), z(detail::to_half(c)) {}
    template <typename C, detail::if_scalar<C> = 0>
    al_hvec3(const al_hvec2& v, C c) : x(v.x), y(v.y), z(detail::to_half(c)) {}
    explicit al_hvec3(const glm::vec3& v) : x(v.x), y(v.y), z(v.z) {}
    explicit al_hvec3(const al_hvec4& v);
    operator glm::vec3() const { return {float(x), float(y), float(z)}; }

    al_half& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
    al_half operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
    al_hvec3& operator+=(const al_hvec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    al_hvec3& operator-=(const al_hvec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    al_hvec3& operator*=(const al_hvec3& o) {
        x *= o.x;
        y *= o.y;
        z *= o.z;
        return *this;
    }
    al_hvec3& operator/=(const al_hvec3& o) {
        x /= o.x;
        y /= o.y;
        z /= o.z;
        return *this;
    }
    al_hvec3& operator+=(al_half s) {
        x += s;
        y += s;
        z += s;
        return *this;
    }
    al_hvec3& operator-=(al_half s) {
        x -= s;
        y -= s;
        z -= s;
        return *this;
    }
    al_hvec3& operator*=(al_half s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    al_hvec3& operator/=(al_half s) {
        x /= s;
        y /= s;
        z /= s;
        return *this;
    }
};

struct al_hvec4 {
    al_half x, y, z, w;

    al_hvec4() = default;
    template <typename T, detail::if_scalar<T> = 0>
    explicit al_hvec4(T s) : x(detail::to_half(s)), y(x), z(x), w(x) {}
    template <typename A, typename B, typename C, typename D, detail::if_scalar<A> = 0,
              detail::if_scalar<B> = 0, detail::if_scalar<C> = 0, detail::if_scalar<D> = 0>
    al_hvec4(A a, B b, C c, D d)
        : x(detail::to_half(a)),
          y(detail::to_half(b)),
          z(detail::to_half(c)),
          w(detail::to_half(d)) {}
    template <typename D, detail::if_scalar<D> = 0>
    al_hvec4(const al_hvec3& v, D d) : x(v.x), y(v.y), z(v.z), w(detail::to_half(d)) {}
    explicit al_hvec4(const glm::vec4& v) : x(v.x), y(v.y), z(v.z), w(v.w) {}
    operator glm::vec4() const { return {float(x), float(y), float(z), float(w)}; }

    al_half& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    al_half operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    al_hvec4& operator+=(const al_hvec4& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        w += o.w;
        return *this;
    }
    al_hvec4& operator-=(const al_hvec4& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        w -= o.w;
        return *this;
    }
    al_hvec4& operator*=(const al_hvec4& o) {
        x *= o.x;
        y *= o.y;
        z *= o.z;
        w *= o.w;
        return *this;
    }
    al_hvec4& operator/=(const al_hvec4& o) {
        x /= o.x;
        y /= o.y;
        z /= o.z;
        w /= o.w;
        return *this;
    }
    al_hvec4& operator+=(al_half s) {
        x += s;
        y += s;
        z += s;
        w += s;
        return *this;
    }
    al_hvec4& operator-=(al_half s) {
        x -= s;
        y -= s;
        z -= s;
        w -= s;
        return *this;
    }
    al_hvec4& operator*=(al_half s) {
        x *= s;
        y *= s;
        z *= s;
        w *= s;
        return *this;
    }
    al_hvec4& operator/=(al_half s) {
        x /= s;
        y /= s;
        z /= s;
        w /= s;
        return *this;
    }
};

// f16vec3(f16vec4): the first three components.
inline al_hvec3::al_hvec3(const al_hvec4& v) : x(v.x), y(v.y), z(v.z) {}

// Component-wise operators and functions for the three vector types, generated from
// one definition each (al_map applies a scalar function to every component).
#define AL_HVEC_DEFINE(V, N)                                                             \
    inline V al_map(const V& a, al_half (*f)(al_half)) {                                 \
        V r;                                                                             \
        for (int i = 0; i < N; ++i) r[i] = f(a[i]);                                      \
        return r;                                                                        \
    }                                                                                    \
    inline V operator+(const V& a, const V& b) {                                         \
        V r = a;                                                                         \
        return r += b;                                                                   \
    }                                                                                    \
    inline V operator-(const V& a, const V& b) {                                         \
        V r = a;                                                                         \
        return r -= b;                                                                   \
    }                                                                                    \
    inline V operator*(const V& a, const V& b) {                                         \
        V r = a;                                                                         \
        return r *= b;                                                                   \
    }                                                                                    \
    inline V operator/(const V& a, const V& b) {                                         \
        V r = a;                                                                         \
        return r /= b;                                                                   \
    }                                                                                    \
    inline V operator*(const V& a, al_half s) {                                          \
        V r = a;                                                                         \
        return r *= s;                                                                   \
    }                                                                                    \
    inline V operator/(const V& a, al_half s) {                                          \
        V r = a;                                                                         \
        return r /= s;                                                                   \
    }                                                                                    \
    inline V operator*(al_half s, const V& a) {                                          \
        return V(s) * a;                                                                 \
    }                                                                                    \
    inline V operator/(al_half s, const V& a) {                                          \
        return V(s) / a;                                                                 \
    }                                                                                    \
    inline V operator+(const V& a, al_half s) {                                          \
        return a + V(s);                                                                 \
    }                                                                                    \
    inline V operator+(al_half s, const V& a) {                                          \
        return V(s) + a;                                                                 \
    }                                                                                    \
    inline V operator-(const V& a, al_half s) {                                          \
        return a - V(s);                                                                 \
    }                                                                                    \
    inline V operator-(al_half s, const V& a) {                                          \
        return V(s) - a;                                                                 \
    }                                                                                    \
    inline V operator-(const V& a) {                                                     \
        return al_map(a, [](al_half x) { return -x; });                                  \
    }                                                                                    \
    inline V operator+(const V& a) {                                                     \
        return a;                                                                        \
    }                                                                                    \
    inline bool operator==(const V& a, const V& b) {                                     \
        for (int i = 0; i < N; ++i)                                                      \
            if (a[i] != b[i]) return false;                                              \
        return true;                                                                     \
    }                                                                                    \
    inline bool operator!=(const V& a, const V& b) {                                     \
        return !(a == b);                                                                \
    }                                                                                    \
    inline V abs(const V& a) {                                                           \
        return al_map(a, [](al_half x) { return abs(x); });                              \
    }                                                                                    \
    inline V sign(const V& a) {                                                          \
        return al_map(a, [](al_half x) { return sign(x); });                             \
    }                                                                                    \
    inline V sqrt(const V& a) {                                                          \
        return al_map(a, [](al_half x) { return sqrt(x); });                             \
    }                                                                                    \
    inline V inversesqrt(const V& a) {                                                   \
        return al_map(a, [](al_half x) { return inversesqrt(x); });                      \
    }                                                                                    \
    inline V min(const V& a, const V& b) {                                               \
        V r;                                                                             \
        for (int i = 0; i < N; ++i) r[i] = min(a[i], b[i]);                              \
        return r;                                                                        \
    }                                                                                    \
    inline V max(const V& a, const V& b) {                                               \
        V r;                                                                             \
        for (int i = 0; i < N; ++i) r[i] = max(a[i], b[i]);                              \
        return r;                                                                        \
    }                                                                                    \
    inline V min(const V& a, al_half b) {                                                \
        return min(a, V(b));                                                             \
    }                                                                                    \
    inline V max(const V& a, al_half b) {                                                \
        return max(a, V(b));                                                             \
    }                                                                                    \
    inline V clamp(const V& x, const V& lo, const V& hi) {                               \
        return min(max(x, lo), hi);                                                      \
    }                                                                                    \
    inline V clamp(const V& x, al_half lo, al_half hi) {                                 \
        return min(max(x, lo), hi);                                                      \
    }                                                                                    \
    inline V mix(const V& x, const V& y, const V& a) {                                   \
        V r;                                                                             \
        for (int i = 0; i < N; ++i) r[i] = mix(x[i], y[i], a[i]);                        \
        return r;                                                                        \
    }                                                                                    \
    inline V mix(const V& x, const V& y, al_half a) {                                    \
        return mix(x, y, V(a));                                                          \
    }                                                                                    \
    inline V fma(const V& a, const V& b, const V& c) {                                   \
        V r;                                                                             \
        for (int i = 0; i < N; ++i) r[i] = fma(a[i], b[i], c[i]);                        \
        return r;                                                                        \
    }                                                                                    \
    /* ((a0 b0 + a1 b1) + a2 b2) + a3 b3: each product and each sum rounded. */          \
    inline al_half dot(const V& a, const V& b) {                                         \
        al_half s = a[0] * b[0];                                                         \
        for (int i = 1; i < N; ++i) s = s + a[i] * b[i];                                 \
        return s;                                                                        \
    }                                                                                    \
    /* sqrt(dot(a, a)), both rounded. */                                                 \
    inline al_half length(const V& a) {                                                  \
        return sqrt(dot(a, a));                                                          \
    }                                                                                    \
    /* a / sqrt(dot(a, a)), each step rounded: lavapipe's rule (bit-identical there). */ \
    inline V normalize(const V& a) {                                                     \
        return a / length(a);                                                            \
    }                                                                                    \
    /* GLSL promotes mixed half/float vectors to float. */                               \
    inline glm::vec##N operator+(const V& a, const glm::vec##N& b) {                     \
        return glm::vec##N(a) + b;                                                       \
    }                                                                                    \
    inline glm::vec##N operator+(const glm::vec##N& a, const V& b) {                     \
        return a + glm::vec##N(b);                                                       \
    }                                                                                    \
    inline glm::vec##N operator-(const V& a, const glm::vec##N& b) {                     \
        return glm::vec##N(a) - b;                                                       \
    }                                                                                    \
    inline glm::vec##N operator-(const glm::vec##N& a, const V& b) {                     \
        return a - glm::vec##N(b);                                                       \
    }                                                                                    \
    inline glm::vec##N operator*(const V& a, const glm::vec##N& b) {                     \
        return glm::vec##N(a) * b;                                                       \
    }                                                                                    \
    inline glm::vec##N operator*(const glm::vec##N& a, const V& b) {                     \
        return a * glm::vec##N(b);                                                       \
    }                                                                                    \
    inline glm::vec##N operator/(const V& a, const glm::vec##N& b) {                     \
        return glm::vec##N(a) / b;                                                       \
    }                                                                                    \
    inline glm::vec##N operator/(const glm::vec##N& a, const V& b) {                     \
        return a / glm::vec##N(b);                                                       \
    }                                                                                    \
    inline glm::vec##N operator*(const V& a, float s) {                                  \
        return glm::vec##N(a) * s;                                                       \
    }                                                                                    \
    inline glm::vec##N operator*(float s, const V& a) {                                  \
        return s * glm::vec##N(a);                                                       \
    }                                                                                    \
    inline glm::vec##N operator/(const V& a, float s) {                                  \
        return glm::vec##N(a) / s;                                                       \
    }

AL_HVEC_DEFINE(al_hvec2, 2)
AL_HVEC_DEFINE(al_hvec3, 3)
AL_HVEC_DEFINE(al_hvec4, 4)
#undef AL_HVEC_DEFINE

// (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y): each product and
// difference rounded.
inline al_hvec3 cross(const al_hvec3& a, const al_hvec3& b) {
    return al_hvec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
}

}  // namespace arealight::mirror

using arealight::mirror::al_half;
using arealight::mirror::al_hvec2;
using arealight::mirror::al_hvec3;
using arealight::mirror::al_hvec4;
using arealight::mirror::AlSampler2D;
