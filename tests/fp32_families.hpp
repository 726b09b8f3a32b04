// Each (distribution, method, light) once, at its default keys, or at precision=fp32 where
// the default is fp64; families with no fp32 form are left out. The libraries that GLSL ES
// 3.10 and HLSL take (both fp32 only).
#pragma once

#include <string>
#include <vector>

#include "eval_support.hpp"

namespace arealight::test {

inline std::vector<Variant> fp32_families() {
    std::vector<Variant> families;
    for (const Variant& v : enumerate_variants()) {
        bool seen = false;
        for (const Variant& f : families)
            seen = seen || (f.dist == v.dist && f.method == v.method && f.light == v.light);
        if (seen) continue;
        Variant d = variant(std::string("dist=") + to_string(v.dist) + ",method=" +
                            to_string(v.method) + ",light=" + to_string(v.light));
        if (effective_precision(d) != Precision::Fp32) {
            d.precision = Precision::Fp32;
            if (!is_valid(d)) continue;
        }
        families.push_back(d);
    }
    return families;
}

}  // namespace arealight::test
