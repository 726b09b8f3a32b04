#version 450
// Renders the scene of scene.json, one invocation per pixel: a camera ray is cast
// analytically against the scene's objects (plane, spheres, boxes) and the hit point is shaded
// by every polygon light through the generated arealight library. Written against CONTRACT.md
// section 5 only: ArealightSurface, ArealightShading and arealight_polygon_<dist>.
// Pixel = sum over lights of intensity * (albedo * diffuse + specular), as `arealight render`
// draws the same scene; area lights are not shadowed (the integrals see the whole light).
layout(local_size_x = 8, local_size_y = 8) in;

#include "arealight_scene.glsl"

// The host's layout: every record std430, vec3 values padded to vec4.
struct Light {
    vec4 vertices[8];
    float intensity;
    int count;
    int two_sided;
    int pad0;
};
struct Material {
    int dist;  // kDistGgx or kDistPhong
    float param;
    float f0;
    float pad0;
};
const int kDistGgx = 0;
const int kDistPhong = 1;
struct Object {
    vec4 a;  // plane: normal, offset; sphere: centre, radius; box: min
    vec4 b;  // box: max
    vec4 albedo;
    int type;
    int material;
    int pad0, pad1;
};
const int kPlane = 0;
const int kSphere = 1;
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
    if (ob.type == kSphere) {
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

// Distance along the ray to light i's emitting side (kFar when missed): the camera sees the
// lights themselves.
float intersect_light(int i, vec3 o, vec3 d) {
    Light l = lights[i];
    vec3 n = cross(l.vertices[1].xyz - l.vertices[0].xyz, l.vertices[2].xyz - l.vertices[0].xyz);
    float denom = dot(n, d);
    if (denom >= 0.0 && l.two_sided == 0) return kFar;
    float t = dot(n, l.vertices[0].xyz - o) / denom;
    if (!(t > 1e-4)) return kFar;
    vec3 x = o + t * d;
    for (int k = 0; k < l.count; ++k) {
        vec3 a = l.vertices[k].xyz;
        vec3 b = l.vertices[(k + 1) % l.count].xyz;
        if (dot(cross(b - a, x - a), n) < 0.0) return kFar;
    }
    return t;
}

vec3 shade(vec3 p, vec3 n, vec3 v, Material m, vec3 albedo) {
    ArealightSurface s = ArealightSurface(p, n, v, m.param, m.f0);
    vec3 color = vec3(0.0);
    for (int i = 0; i < frame.light_count; ++i) {
        vec3 vertices[8];
        for (int k = 0; k < 8; ++k) vertices[k] = lights[i].vertices[k].xyz;
        bool two_sided = lights[i].two_sided != 0;
        ArealightShading r;
        if (m.dist == kDistGgx) {
            r = arealight_polygon_ggx(s, vertices, lights[i].count, two_sided);
        } else {
            r = arealight_polygon_phong(s, vertices, lights[i].count, two_sided);
        }
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
