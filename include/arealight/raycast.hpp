// Primary visibility of a render scene: one camera ray per pixel centre, intersected
// analytically with the objects and the lights' emitting faces. The shading of what
// it finds is the shading library's job (render.hpp), not this one's.
#pragma once

#include <vector>

#include "arealight/render_scene.hpp"

namespace arealight {

struct PixelHit {
    enum class Kind { Background, Surface, Light } kind = Kind::Background;
    // Surface: the shading point, its normal turned toward the eye, and the unit
    // direction from it to the eye; light: `light` is the index of the light seen.
    Vec3 p{}, n{}, v{};
    int object = -1;
    int light = -1;
};

// width * height hits, row 0 at the top. The vertical field of view is the camera's;
// pixels are square.
std::vector<PixelHit> cast_camera_rays(const RenderScene& scene, int width, int height);

}  // namespace arealight
