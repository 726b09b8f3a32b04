// The `gpu` object of report rows, bench output and quality entries (GpuCost as JSON):
// its fields in one fixed order, integers as integers, read back exactly.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "arealight/gpu_cost.hpp"

namespace arealight {

nlohmann::ordered_json gpu_cost_json(const GpuCost& c);

// nullopt with `why` ("field 'cost': must be an integer >= 0", ...) when a field is
// missing or of the wrong kind.
std::optional<GpuCost> parse_gpu_cost(const nlohmann::json& j, std::string& why);

}  // namespace arealight
