#version 450
// Renders the scene of scene.json, one invocation per pixel: a camera ray is cast
// analytically against the scene's objects (plane, spheres, boxes) and the hit point is shaded
// by every light (polygon, disk, sphere, ellipsoid) through the generated arealight library.
// Written against CONTRACT.md section 5 only: ArealightSurface, ArealightShading, the
// arealight_<light>_<dist> functions and their AREALIGHT_HAS_<LIGHT>_<DIST> macros, so it
// compiles against the library of any scene (a (light, dist) pair the scene lacks has no
// function, and no call here).
// Pixel = sum over lights of intensity * (albedo * diffuse + specular), as `arealight render`
// draws the same scene; area lights are not shadowed (the integrals see the whole light).
layout(local_size_x = 8, local_size_y = 8) in;

// The library's tables (the LTC matrices of its GGX function) follow the five buffers below;
// main.cpp binds each at AREALIGHT_BINDING + its manifest's binding_offset.
#define AREALIGHT_BINDING 5
#include "arealight_scene.glsl"

// The host's layout: every record std430, vec3 values padded to vec4.
struct Light {
    vec4 data[8];  // polygon: vertices; disk: center, u, v; sphere: center and radius in w;
                   // ellipsoid: center, then its three semi-axes
    float intensity;
    int type;      // kPolygon, kDisk, kSphere, kEllipsoid
    int count;     // polygon: vertex count
    int two_sided;
};
const int kPolygon = 0;
const int kDisk = 1;
const int kSphere = 2;
const int kEllipsoid = 3;
struct Material {
    int dist;  // kGgx, kPhong, kBeckmann, kBlinn
    float param;
    float f0;
    float pad0;
};
const int kGgx = 0;
const int kPhong = 1;
const int kBeckmann = 2;
const int kBlinn = 3;
struct Object {
    vec4 a;  // plane: normal, offset; sphere: centre, radius; box: min
    vec4 b;  // box: max
    vec4 albedo;
    int type;
    int material;
    int pad0, pad1;
};
const int kPlane = 0;
const int kBall = 1;
const int kBox = 2;

layout(std430, set = 0, binding = 0) readonly buffer Frame {
    vec4 eye;
    vec4 forward;  // scaled so that right and up span the image plane at distance 1
    vec4 right;
    vec4 up;
    int width;
    int height;
    int light_count;
    int object_count;
} frame;
layout(std430, set = 0, binding = 1) readonly buffer Lights { Light lights[]; };
layout(std430, set = 0, binding = 2) readonly buffer Materials { Material materials[]; };
layout(std430, set = 0, binding = 3) readonly buffer Objects { Object objects[]; };
layout(std430, set = 0, binding = 4) writeonly buffer Pixels { uint pixels[]; };

const float kFar = 1e30;

// Nearest positive hit of the ray o + t d with object k (kFar when none), and its normal.
float intersect(int k, vec3 o, vec3 d, out vec3 normal) {
    Object ob = objects[k];
    normal = vec3(0.0, 1.0, 0.0);
    if (ob.type == kPlane) {
        float denom = dot(ob.a.xyz, d);
        float t = (ob.a.w - dot(ob.a.xyz, o)) / denom;
        normal = ob.a.xyz;
        return (abs(denom) > 1e-8 && t > 1e-4) ? t : kFar;
    }
    if (ob.type == kBall) {
        vec3 oc = o - ob.a.xyz;
        float b = dot(oc, d);
        float c = dot(oc, oc) - ob.a.w * ob.a.w;
        float disc = b * b - c;
        if (disc < 0.0) return kFar;
        float t = -b - sqrt(disc);
        if (t < 1e-4) return kFar;
        normal = (o + t * d - ob.a.xyz) / ob.a.w;
        return t;
    }
    // Box: slab test; the normal is the axis of the slab entered last.
    vec3 inv = 1.0 / d;
    vec3 t0 = (ob.a.xyz - o) * inv;
    vec3 t1 = (ob.b.xyz - o) * inv;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    float enter = max(max(near.x, near.y), near.z);
    float leave = min(min(far.x, far.y), far.z);
    if (enter > leave || enter < 1e-4) return kFar;
    if (enter == near.x) normal = vec3(-sign(d.x), 0.0, 0.0);
    else if (enter == near.y) normal = vec3(0.0, -sign(d.y), 0.0);
    else normal = vec3(0.0, 0.0, -sign(d.z));
    return enter;
}

// Nearest positive t of the ray o + t d on the unit sphere, after the ray is taken into
// the frame where the light is that sphere (kFar when missed).
float unit_sphere_hit(vec3 o, vec3 d) {
    float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
    float disc = b * b - a * c;
    if (disc < 0.0) return kFar;
    float t = (-b - sqrt(disc)) / a;
    return t > 1e-4 ? t : kFar;
}

// Distance along the ray to light i's emitting surface (kFar when missed): the camera
// sees the lights themselves.
float intersect_light(int i, vec3 o, vec3 d) {
    Light l = lights[i];
    vec3 c = l.data[0].xyz;
    if (l.type == kSphere) return unit_sphere_hit((o - c) / l.data[0].w, d / l.data[0].w);
    if (l.type == kEllipsoid) {
        // The axes are orthogonal: coordinates along each, in units of its length.
        vec3 oc = o - c, ol, dl;
        for (int k = 0; k < 3; ++k) {
            vec3 a = l.data[k + 1].xyz;
            ol[k] = dot(oc, a) / dot(a, a);
            dl[k] = dot(d, a) / dot(a, a);
        }
        return unit_sphere_hit(ol, dl);
    }
    vec3 n = l.type == kDisk
                 ? cross(l.data[1].xyz, l.data[2].xyz)
                 : cross(l.data[1].xyz - l.data[0].xyz, l.data[2].xyz - l.data[0].xyz);
    float denom = dot(n, d);
    if (denom >= 0.0 && l.two_sided == 0) return kFar;
    float t = dot(n, l.data[0].xyz - o) / denom;
    if (!(t > 1e-4)) return kFar;
    vec3 x = o + t * d;
    if (l.type == kDisk) {
        vec3 u = l.data[1].xyz, v = l.data[2].xyz;
        float a = dot(x - c, u) / dot(u, u), b = dot(x - c, v) / dot(v, v);
        return a * a + b * b <= 1.0 ? t : kFar;
    }
    for (int k = 0; k < l.count; ++k) {
        vec3 a = l.data[k].xyz;
        vec3 b = l.data[(k + 1) % l.count].xyz;
        if (dot(cross(b - a, x - a), n) < 0.0) return kFar;
    }
    return t;
}

// One light's diffuse and specular at s through the library's function for its type and
// the material's distribution; zero for a pair the library does not have (the scene
// generated it, so the pair does not occur).
ArealightShading shade_light(ArealightSurface s, Light l, int dist) {
    ArealightShading r = ArealightShading(0.0, 0.0);
    bool two_sided = l.two_sided != 0;
    vec3 c = l.data[0].xyz;
    if (l.type == kPolygon) {
        vec3 vertices[8];
        for (int k = 0; k < 8; ++k) vertices[k] = l.data[k].xyz;
#ifdef AREALIGHT_HAS_POLYGON_GGX
        if (dist == kGgx) r = arealight_polygon_ggx(s, vertices, l.count, two_sided);
#endif
#ifdef AREALIGHT_HAS_POLYGON_PHONG
        if (dist == kPhong) r = arealight_polygon_phong(s, vertices, l.count, two_sided);
#endif
#ifdef AREALIGHT_HAS_POLYGON_BECKMANN
        if (dist == kBeckmann) r = arealight_polygon_beckmann(s, vertices, l.count, two_sided);
#endif
#ifdef AREALIGHT_HAS_POLYGON_BLINN
        if (dist == kBlinn) r = arealight_polygon_blinn(s, vertices, l.count, two_sided);
#endif
    } else if (l.type == kDisk) {
        vec3 u = l.data[1].xyz, v = l.data[2].xyz;
#ifdef AREALIGHT_HAS_DISK_GGX
        if (dist == kGgx) r = arealight_disk_ggx(s, c, u, v, two_sided);
#endif
#ifdef AREALIGHT_HAS_DISK_PHONG
        if (dist == kPhong) r = arealight_disk_phong(s, c, u, v, two_sided);
#endif
#ifdef AREALIGHT_HAS_DISK_BECKMANN
        if (dist == kBeckmann) r = arealight_disk_beckmann(s, c, u, v, two_sided);
#endif
#ifdef AREALIGHT_HAS_DISK_BLINN
        if (dist == kBlinn) r = arealight_disk_blinn(s, c, u, v, two_sided);
#endif
    } else if (l.type == kSphere) {
        float radius = l.data[0].w;
#ifdef AREALIGHT_HAS_SPHERE_GGX
        if (dist == kGgx) r = arealight_sphere_ggx(s, c, radius);
#endif
#ifdef AREALIGHT_HAS_SPHERE_PHONG
        if (dist == kPhong) r = arealight_sphere_phong(s, c, radius);
#endif
#ifdef AREALIGHT_HAS_SPHERE_BECKMANN
        if (dist == kBeckmann) r = arealight_sphere_beckmann(s, c, radius);
#endif
#ifdef AREALIGHT_HAS_SPHERE_BLINN
        if (dist == kBlinn) r = arealight_sphere_blinn(s, c, radius);
#endif
    } else {
        vec3 axes[3];
        for (int k = 0; k < 3; ++k) axes[k] = l.data[k + 1].xyz;
#ifdef AREALIGHT_HAS_ELLIPSOID_GGX
        if (dist == kGgx) r = arealight_ellipsoid_ggx(s, c, axes);
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_PHONG
        if (dist == kPhong) r = arealight_ellipsoid_phong(s, c, axes);
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_BECKMANN
        if (dist == kBeckmann) r = arealight_ellipsoid_beckmann(s, c, axes);
#endif
#ifdef AREALIGHT_HAS_ELLIPSOID_BLINN
        if (dist == kBlinn) r = arealight_ellipsoid_blinn(s, c, axes);
#endif
    }
    return r;
}

vec3 shade(vec3 p, vec3 n, vec3 v, Material m, vec3 albedo) {
    ArealightSurface s = ArealightSurface(p, n, v, m.param, m.f0);
    vec3 color = vec3(0.0);
    for (int i = 0; i < frame.light_count; ++i) {
        ArealightShading r = shade_light(s, lights[i], m.dist);
        color += lights[i].intensity * (albedo * r.diffuse + r.specular);
    }
    return color;
}

// Clamped to [0, 1], then the sRGB transfer curve.
uint encode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 srgb = mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
    uvec3 q = uvec3(clamp(srgb, 0.0, 1.0) * 255.0 + 0.5);
    return q.r | (q.g << 8) | (q.b << 16) | (255u << 24);
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= frame.width || px.y >= frame.height) return;
    vec2 ndc = (vec2(px) + 0.5) / vec2(frame.width, frame.height) * 2.0 - 1.0;
    vec3 o = frame.eye.xyz;
    vec3 d = normalize(frame.forward.xyz + ndc.x * frame.right.xyz - ndc.y * frame.up.xyz);

    float best = kFar;
    vec3 normal = vec3(0.0);
    int hit = -1;
    for (int k = 0; k < frame.object_count; ++k) {
        vec3 nk;
        float t = intersect(k, o, d, nk);
        if (t < best) {
            best = t;
            normal = nk;
            hit = k;
        }
    }
    vec3 color = vec3(0.02);  // background
    int seen_light = -1;
    for (int i = 0; i < frame.light_count; ++i) {
        float t = intersect_light(i, o, d);
        if (t < best) {
            best = t;
            seen_light = i;
        }
    }
    if (seen_light >= 0) {
        color = vec3(lights[seen_light].intensity);
    } else if (hit >= 0) {
        Object ob = objects[hit];
        color = shade(o + best * d, normal, -d, materials[ob.material], ob.albedo.rgb);
    }
    pixels[px.y * frame.width + px.x] = encode(color);
}
