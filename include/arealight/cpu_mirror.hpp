// The CPU mirror: each variant's stitched template text compiled as C++ over GLM
// at build time (see generator/mirror_tool.cpp), looked up by canonical name.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace arealight {

// Shades `count` packed cases (the AlCase layout of templates/common.glsl) into
// 4 floats each, exactly as the shader's main() does.
using MirrorFn = void (*)(const void* cases, float* results, std::size_t count);

struct MirrorEntry {
    const char* variant;  // canonical name
    MirrorFn run;
};

// Every variant compiled into this binary, in enumerate_variants() order.
const std::vector<MirrorEntry>& mirror_registry();

// nullptr when the variant has no mirror in this build.
MirrorFn find_mirror(const std::string& canonical_variant);

}  // namespace arealight
