// What `arealight render` draws: a CONTRACT 7 scene (lights, materials) plus the fields
// only the renderer reads, which other readers ignore as unknown fields:
//
//   "camera":  {"eye": [x,y,z], "target": [x,y,z], "up": [x,y,z], "fov_deg": 40}
//   "objects": [ {"type": "plane",  "point": P, "normal": N,        "material": I, "albedo": [r,g,b]},
//                {"type": "sphere", "center": C, "radius": R,      "material": I, "albedo": [r,g,b]},
//                {"type": "box",    "min": [x,y,z], "max": [x,y,z], "material": I, "albedo": [r,g,b]} ]
//   lights[i].intensity: optional uniform radiance of light i (default 1)
//
// fov_deg is the vertical field of view; a box is axis-aligned; albedo (each channel in
// [0, 1]) multiplies `diffuse` only, `specular` is white.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"

namespace arealight {

struct Camera {
    Vec3 eye{}, target{}, up{};
    double fov_deg = 0.0;
};

enum class ObjectType { Plane, Sphere, Box };

struct SceneObject {
    ObjectType type = ObjectType::Plane;
    Vec3 point{}, normal{};  // plane
    Vec3 center{};           // sphere
    double radius = 0.0;     // sphere
    Vec3 min{}, max{};       // box
    int material = 0;        // index into RenderScene::materials
    Vec3 albedo{};
};

struct RenderScene {
    std::vector<Light> lights;
    std::vector<double> intensities;  // one per light
    std::vector<Material> materials;
    std::string method;  // quality.method, empty when absent
    Camera camera;
    std::vector<SceneObject> objects;
};

// Parses and validates a scene for rendering. On failure returns nullopt and reports
// every problem as "FILE: WHERE: field 'FIELD': reason" (WHERE: camera, object N,
// light N, material N).
std::optional<RenderScene> read_render_scene(const std::string& path,
                                             const DiagnosticConsumer& diag);
// Same, from text already in memory; `name` stands for the file in messages.
std::optional<RenderScene> parse_render_scene(const std::string& text, const std::string& name,
                                              const DiagnosticConsumer& diag);

}  // namespace arealight
