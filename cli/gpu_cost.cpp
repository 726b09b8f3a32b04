#include "gpu_cost.hpp"

#include <fmt/format.h>

#include <cstring>

#include "arealight/gpu_cost_json.hpp"
#include "arealight/read_file.hpp"
#include "arealight/variant.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"

namespace arealight::cli {

int run_gpu_cost(const GpuCostArgs& args) {
    if (args.variants.empty() && args.spv.empty()) {
        print_diagnostic({Severity::Error, "", 0, "gpu-cost: --variant or --spv is required"});
        return kUsage;
    }
    std::vector<Variant> variants;
    for (const auto& name : args.variants) {
        auto v = parse_variant(name, print_diagnostic);
        if (!v) return kBadInput;
        variants.push_back(*v);
    }
    GpuCostOptions opt;
    opt.family = args.gpu_family;
    opt.cache_dir = args.gpu_cache;
    auto meter = GpuCostMeter::create(opt, print_diagnostic);
    if (!meter) return kRuntime;
    auto line = [](const std::string& key, const std::string& what, const GpuCost& c) {
        nlohmann::ordered_json j;
        j[key] = what;
        j["gpu"] = gpu_cost_json(c);
        fmt::print("{}\n", j.dump());
    };
    for (const auto& v : variants) {
        auto c = meter->measure(v, print_diagnostic);
        if (!c) return kRuntime;
        line("variant", canonical_name(v), *c);
    }
    for (const auto& path : args.spv) {
        auto bytes = read_file(path, print_diagnostic);
        if (!bytes) return kBadInput;
        if (bytes->size() % 4 != 0) {
            print_diagnostic({Severity::Error, path, 0, path + ": not a whole number of words"});
            return kBadInput;
        }
        std::vector<uint32_t> words(bytes->size() / 4);
        if (!words.empty()) std::memcpy(words.data(), bytes->data(), bytes->size());
        auto c = meter->measure(words, print_diagnostic);
        if (!c) return kRuntime;
        line("file", path, *c);
    }
    return kOk;
}

}  // namespace arealight::cli
