// The CPU mirror: each variant's stitched template text compiled as C++ over GLM
// at build time (see generator/mirror_tool.cpp), looked up by canonical name.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "arealight/texture.hpp"

namespace arealight {

// Shades `count` packed cases (arealight/case_layout.hpp) into 4 floats each,
// exactly as the validation kernel's main() does: the library function's diffuse
// and specular, and with `second` the variant's ndf or moment. textures[k] is the table the
// variant's k-th sampler reads (VariantFamily::samplers, the Vulkan run's binding
// 2 + k; variant_textures() in include/arealight/evaluator.hpp gives them); a sampler
// without one (k >= texture_count) reads NaN. The samplers are thread_local: one run
// per thread at a time, and the textures must outlive the call.
using MirrorFn = void (*)(const void* cases, float* results, std::size_t count,
                          const Texture2D* const* textures, std::size_t texture_count,
                          bool second);

struct MirrorEntry {
    const char* variant;  // canonical name
    MirrorFn run;
    std::size_t samplers;  // how many textures run() reads
};

// Every variant compiled into this binary, in enumerate_variants() order.
const std::vector<MirrorEntry>& mirror_registry();

// nullptr when the variant has no mirror in this build.
MirrorFn find_mirror(const std::string& canonical_variant);
const MirrorEntry* find_mirror_entry(const std::string& canonical_variant);

// One peak-function edge integral of a variant's mirror (a test hook): the fit of
// the near-form integrand (1 - x^k) / (1 - x^2) (far_edge false) or of
// x^k / (1 - x^2) over the arc from tau_a = atan2(ag, af) to tau_b = atan2(bg, bf),
// x = c cos(tau), c = sqrt(1 - s^2) (templates/method/peak_phong.glsl).
using EdgeProbeFn = float (*)(float ag, float af, float bg, float bf, float s, float k,
                              bool far_edge);
struct EdgeProbeEntry {
    const char* variant;  // canonical name (sided, verts and specular at their defaults)
    EdgeProbeFn fn;
};
const std::vector<EdgeProbeEntry>& edge_probe_registry();

}  // namespace arealight
