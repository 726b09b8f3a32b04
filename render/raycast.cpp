#include "arealight/raycast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arealight {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
// Hits nearer than this (relative to the scene's unit) are the ray's own origin.
constexpr double kMinT = 1e-9;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 mul(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalize(const Vec3& a) { return mul(a, 1.0 / std::sqrt(dot(a, a))); }

struct Ray {
    Vec3 o, d;  // d unit
};

// Distance to the nearest hit beyond kMinT and the outward normal there, or kInf.
double hit_plane(const Ray& r, const Vec3& point, const Vec3& normal, Vec3& n) {
    const double dn = dot(r.d, normal);
    if (dn == 0) return kInf;
    const double t = dot(sub(point, r.o), normal) / dn;
    if (!(t > kMinT)) return kInf;
    n = normalize(normal);
    return t;
}

double hit_sphere(const Ray& r, const Vec3& c, double radius, Vec3& n) {
    const Vec3 oc = sub(r.o, c);
    const double b = dot(oc, r.d), q = dot(oc, oc) - radius * radius;
    const double disc = b * b - q;
    if (disc < 0) return kInf;
    const double s = std::sqrt(disc);
    double t = -b - s;
    if (!(t > kMinT)) t = -b + s;  // the eye inside: the far side
    if (!(t > kMinT)) return kInf;
    n = normalize(sub(add(r.o, mul(r.d, t)), c));
    return t;
}

// Slabs; the normal is that of the face whose slab was entered last.
double hit_box(const Ray& r, const Vec3& lo, const Vec3& hi, Vec3& n) {
    double t0 = -kInf, t1 = kInf;
    int axis0 = 0, axis1 = 0;
    for (int k = 0; k < 3; ++k) {
        if (r.d[k] == 0) {
            if (r.o[k] < lo[k] || r.o[k] > hi[k]) return kInf;
            continue;
        }
        double a = (lo[k] - r.o[k]) / r.d[k], b = (hi[k] - r.o[k]) / r.d[k];
        if (a > b) std::swap(a, b);
        if (a > t0) t0 = a, axis0 = k;
        if (b < t1) t1 = b, axis1 = k;
    }
    if (t0 > t1) return kInf;
    const bool outside = t0 > kMinT;
    const double t = outside ? t0 : t1;
    if (!(t > kMinT)) return kInf;
    const int axis = outside ? axis0 : axis1;
    n = {0, 0, 0};
    // Entering, the face opposes the ray; leaving (the eye inside), it faces along it.
    n[axis] = (r.d[axis] > 0) == outside ? -1.0 : 1.0;
    return t;
}

// A convex polygon light, seen from its emitting side (either side when two-sided).
double hit_polygon(const Ray& r, const Light& L) {
    if (L.vertices.size() < 3) return kInf;
    const auto& V = L.vertices;
    const Vec3 front = cross(sub(V[1], V[0]), sub(V[2], V[0]));
    const double dn = dot(r.d, front);
    if (dn == 0 || (!L.two_sided && dn > 0)) return kInf;
    const double t = dot(sub(V[0], r.o), front) / dn;
    if (!(t > kMinT)) return kInf;
    const Vec3 x = add(r.o, mul(r.d, t));
    for (std::size_t i = 0; i < V.size(); ++i) {
        const Vec3& a = V[i];
        const Vec3& b = V[(i + 1) % V.size()];
        if (dot(cross(sub(b, a), sub(x, a)), front) < 0) return kInf;
    }
    return t;
}

// A disk light (CONTRACT 1: orthogonal semi-axes u, v, emitting towards u x v): the
// plane's hit, inside when its coordinates along u and v lie in the unit disc.
double hit_disk(const Ray& r, const Light& L) {
    const Vec3 front = cross(L.u, L.v);
    const double dn = dot(r.d, front);
    if (dn == 0 || (!L.two_sided && dn > 0)) return kInf;
    const double t = dot(sub(L.center, r.o), front) / dn;
    if (!(t > kMinT)) return kInf;
    const Vec3 x = sub(add(r.o, mul(r.d, t)), L.center);
    const double a = dot(x, L.u) / dot(L.u, L.u), b = dot(x, L.v) / dot(L.v, L.v);
    return a * a + b * b <= 1 ? t : kInf;
}

// An ellipsoid light, c + A y over the unit sphere (A's columns the orthogonal axes):
// the ray carried by A^-1 is a ray with the same parameter t, met by the unit sphere.
double hit_ellipsoid(const Ray& r, const Light& L) {
    Vec3 o{}, d{};
    for (int k = 0; k < 3; ++k) {
        const Vec3& a = L.axes[k];
        const double aa = dot(a, a);
        if (!(aa > 0)) return kInf;
        o[k] = dot(sub(r.o, L.center), a) / aa;
        d[k] = dot(r.d, a) / aa;
    }
    // |o + t d|^2 = 1; the near root unless the eye is inside.
    const double A = dot(d, d), B = dot(o, d), C = dot(o, o) - 1;
    const double disc = B * B - A * C;
    if (!(A > 0) || disc < 0) return kInf;
    const double s = std::sqrt(disc);
    // Roots (-B -+ s) / A, the near one in the cancellation-free form C / (-B + s).
    double t = B < 0 ? C / (-B + s) : (-B - s) / A;
    if (!(t > kMinT)) t = (-B + s) / A;
    return t > kMinT ? t : kInf;
}

double hit_light(const Ray& r, const Light& L) {
    switch (L.type) {
        case LightType::Polygon:
            return hit_polygon(r, L);
        case LightType::Disk:
            return hit_disk(r, L);
        case LightType::Sphere: {
            Vec3 n{};
            return hit_sphere(r, L.center, L.radius, n);
        }
        case LightType::Ellipsoid:
            return hit_ellipsoid(r, L);
    }
    return kInf;
}

double hit_object(const Ray& r, const SceneObject& o, Vec3& n) {
    switch (o.type) {
        case ObjectType::Plane:
            return hit_plane(r, o.point, o.normal, n);
        case ObjectType::Sphere:
            return hit_sphere(r, o.center, o.radius, n);
        case ObjectType::Box:
            return hit_box(r, o.min, o.max, n);
    }
    return kInf;
}

}  // namespace

std::vector<PixelHit> cast_camera_rays(const RenderScene& scene, int width, int height) {
    const Camera& cam = scene.camera;
    const Vec3 forward = normalize(sub(cam.target, cam.eye));
    const Vec3 right = normalize(cross(forward, cam.up));
    const Vec3 up = cross(right, forward);
    const double half_h = std::tan(cam.fov_deg * kPi / 360.0);
    const double half_w = half_h * width / height;
    std::vector<PixelHit> hits(static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double sx = (2.0 * (x + 0.5) / width - 1.0) * half_w;
            const double sy = (1.0 - 2.0 * (y + 0.5) / height) * half_h;
            const Ray ray{cam.eye, normalize(add(forward, add(mul(right, sx), mul(up, sy))))};
            PixelHit& h = hits[static_cast<std::size_t>(y) * width + x];
            double nearest = kInf;
            for (std::size_t i = 0; i < scene.objects.size(); ++i) {
                Vec3 n{};
                const double t = hit_object(ray, scene.objects[i], n);
                if (t < nearest) {
                    nearest = t;
                    h.kind = PixelHit::Kind::Surface;
                    h.object = static_cast<int>(i);
                    h.p = add(ray.o, mul(ray.d, t));
                    h.v = mul(ray.d, -1.0);
                    // A plane is seen from either side; shade the side the eye is on.
                    h.n = dot(n, h.v) < 0 ? mul(n, -1.0) : n;
                }
            }
            for (std::size_t i = 0; i < scene.lights.size(); ++i) {
                const double t = hit_light(ray, scene.lights[i]);
                if (t < nearest) {
                    nearest = t;
                    h.kind = PixelHit::Kind::Light;
                    h.light = static_cast<int>(i);
                }
            }
        }
    }
    return hits;
}

}  // namespace arealight
