#include "arealight/gpu_cost_json.hpp"

#include <cmath>
#include <utility>

namespace arealight {
namespace {

// The integer fields between "wave" and "ratio_to_point", in the order they are written.
const std::pair<const char*, uint64_t GpuCost::*> kCounts[] = {
    {"instructions", &GpuCost::instructions},
    {"vgprs", &GpuCost::vgprs},
    {"spilled_vgprs", &GpuCost::spilled_vgprs},
    {"scratch_bytes", &GpuCost::scratch_bytes},
    {"latency", &GpuCost::latency},
    {"inverse_throughput", &GpuCost::inverse_throughput},
    {"inverse_throughput_unrolled", &GpuCost::inverse_throughput_unrolled},
    {"cost", &GpuCost::cost},
    {"waves_per_simd", &GpuCost::waves_per_simd},
};

}  // namespace

nlohmann::ordered_json gpu_cost_json(const GpuCost& c) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    j["family"] = c.family;
    j["mesa"] = c.mesa;
    j["wave"] = c.wave;
    for (const auto& [key, field] : kCounts) j[key] = c.*field;
    j["ratio_to_point"] = c.ratio_to_point;
    return j;
}

std::optional<GpuCost> parse_gpu_cost(const nlohmann::json& j, std::string& why) {
    why.clear();
    if (!j.is_object()) {
        why = "must be an object";
        return std::nullopt;
    }
    auto field = [&](const char* key) -> const nlohmann::json* {
        auto it = j.find(key);
        return it == j.end() ? nullptr : &*it;
    };
    auto fail = [&](const char* key, const char* what) -> std::optional<GpuCost> {
        why = std::string("field '") + key + "': " + what;
        return std::nullopt;
    };
    GpuCost c;
    for (const char* key : {"family", "mesa"}) {
        const auto* v = field(key);
        if (!v || !v->is_string()) return fail(key, "must be a string");
        (key == std::string("family") ? c.family : c.mesa) = v->get<std::string>();
    }
    const auto* wave = field("wave");
    if (!wave || !wave->is_number_unsigned()) return fail("wave", "must be an integer >= 0");
    c.wave = wave->get<uint32_t>();
    for (const auto& [key, member] : kCounts) {
        const auto* v = field(key);
        if (!v || !v->is_number_unsigned()) return fail(key, "must be an integer >= 0");
        c.*member = v->get<uint64_t>();
    }
    const auto* ratio = field("ratio_to_point");
    if (!ratio || !ratio->is_number() || !std::isfinite(ratio->get<double>()) ||
        ratio->get<double>() < 0)
        return fail("ratio_to_point", "must be a finite number >= 0");
    c.ratio_to_point = ratio->get<double>();
    return c;
}

}  // namespace arealight
