// FNV-1a, 64 bits: the one content hash of the project (pipeline and GPU-cost cache keys,
// the library's include guard). Not cryptographic; callers that must rule out a clash
// keep the data beside the key.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace arealight {

inline constexpr uint64_t kFnvOffset = 1469598103934665603ull;

inline uint64_t fnv1a(uint64_t h, unsigned char byte) {
    return (h ^ byte) * 1099511628211ull;
}

inline uint64_t fnv1a(std::string_view text) {
    uint64_t h = kFnvOffset;
    for (unsigned char c : text) h = fnv1a(h, c);
    return h;
}

// SPIR-V words, each as its four little-endian bytes.
inline uint64_t fnv1a(const std::vector<uint32_t>& words) {
    uint64_t h = kFnvOffset;
    for (uint32_t w : words)
        for (int i = 0; i < 4; ++i) h = fnv1a(h, static_cast<unsigned char>(w >> (8 * i)));
    return h;
}

}  // namespace arealight
