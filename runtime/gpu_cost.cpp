#include "arealight/gpu_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <utility>

#include "arealight/atomic_file.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/fnv_hash.hpp"
#include "arealight/read_file.hpp"
#include "arealight/report.hpp"
#include "arealight/unroll_loops.hpp"
#include "arealight/variant.hpp"
#include "radv_device.hpp"

namespace arealight {
namespace {

// RADV's statistic names (Mesa 22.3, src/amd/vulkan: radv_GetPipelineExecutableStatisticsKHR).
constexpr const char* kInstructions = "Instructions";
constexpr const char* kVgprs = "VGPRs";
constexpr const char* kSpilledVgprs = "Spilled VGPRs";
constexpr const char* kScratch = "Scratch size";
constexpr const char* kLatency = "Latency";
constexpr const char* kInverseThroughput = "Inverse Throughput";
constexpr const char* kWavesPerSimd = "Subgroups per SIMD";

// "Mesa 22.3.6" (VkPhysicalDeviceDriverProperties::driverInfo) -> "22.3.6".
std::string mesa_version(const std::string& driver_info) {
    const std::string prefix = "Mesa ";
    return driver_info.rfind(prefix, 0) == 0 ? driver_info.substr(prefix.size()) : driver_info;
}

// The cache file of a module, "<dir>/<family>-<mesa>-<words>-<hash>.json": with the word
// count beside the hash, a clash between two of the few thousand modules a project
// compiles is negligible.
std::string cache_path(const GpuCostOptions& opt, const std::string& family,
                       const std::string& mesa, const std::vector<uint32_t>& words) {
    return fmt::format("{}/{}-{}-{}-{:016x}.json", opt.cache_dir, family, mesa, words.size(),
                       fnv1a(words));
}

// A cache entry: the module's statistics, or that its compile did not finish within
// `stopped_after` seconds (ACO on some unrolled modules runs for minutes into many GB), so
// that a run with no larger limit does not spend that time again.
struct CachedCompile {
    std::optional<RadvStatistics> stats;
    double stopped_after = 0.0;  // > 0: stopped at this limit
};

std::optional<CachedCompile> read_cached(const std::string& path) {
    // A missing or unreadable entry is a miss, never an error.
    auto text = read_file(path, nullptr);
    if (!text) return std::nullopt;
    const auto doc = nlohmann::json::parse(*text, nullptr, false);
    if (doc.is_object() && doc.contains("stopped_after_seconds") &&
        doc["stopped_after_seconds"].is_number() && doc["stopped_after_seconds"].get<double>() > 0)
        return CachedCompile{std::nullopt, doc["stopped_after_seconds"].get<double>()};
    if (!doc.is_object() || !doc.contains("subgroup_size") || !doc.contains("values") ||
        !doc["subgroup_size"].is_number_unsigned() || !doc["values"].is_object())
        return std::nullopt;
    RadvStatistics s;
    s.subgroup_size = doc["subgroup_size"].get<uint32_t>();
    for (auto it = doc["values"].begin(); it != doc["values"].end(); ++it) {
        if (!it->is_number()) return std::nullopt;
        s.values[it.key()] = it->get<double>();
    }
    return CachedCompile{s, 0.0};
}

void write_cached(const std::string& path, const RadvStatistics& s) {
    nlohmann::json doc;
    doc["subgroup_size"] = s.subgroup_size;
    doc["values"] = nlohmann::json::object();
    for (const auto& [name, value] : s.values) doc["values"][name] = value;
    // A cache that cannot be written only costs the next run a compile.
    write_file_atomic(path, doc.dump() + "\n", nullptr);
}

void write_stopped(const std::string& path, double seconds) {
    nlohmann::json doc;
    doc["stopped_after_seconds"] = seconds;
    write_file_atomic(path, doc.dump() + "\n", nullptr);
}

}  // namespace

const std::vector<std::string>& radv_families() {
    // Mesa 22.3's ac_get_family_name table (what the null winsys compares with).
    static const std::vector<std::string> names = {
        "tahiti",    "pitcairn",  "verde",     "oland",    "hainan",     "bonaire",   "hawaii",
        "kaveri",    "kabini",    "iceland",   "tonga",    "carrizo",    "fiji",      "stoney",
        "polaris10", "polaris11", "polaris12", "vegam",    "vega10",     "vega12",    "vega20",
        "raven",     "raven2",    "renoir",    "arcturus", "aldebaran",  "navi10",    "navi12",
        "navi14",    "navi21",    "navi22",    "navi23",   "navi24",     "vangogh",   "rembrandt",
        "gfx1036",   "gfx1100",   "gfx1101",   "gfx1102",  "gfx1103_r1", "gfx1103_r2"};
    return names;
}

bool is_radv_family(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const auto& all = radv_families();
    return std::find(all.begin(), all.end(), lower) != all.end();
}

struct GpuCostMeter::Impl {
    GpuCostOptions opt;
    std::unique_ptr<RadvDevice> device;
    std::string mesa;
    // RADV statistics by module: the unrolled module of a loop-free kernel is often
    // the module itself, and a baseline serves many variants. Modules whose compile
    // was stopped are remembered too (nullopt), not tried again.
    std::map<std::vector<uint32_t>, std::optional<RadvStatistics>> compiled;
    std::map<std::string, std::vector<uint32_t>> kernels;  // by canonical variant name

    const RadvStatistics* compile(const std::vector<uint32_t>& spirv,
                                  const DiagnosticConsumer& diag, bool& stopped) {
        stopped = false;
        auto it = compiled.find(spirv);
        if (it == compiled.end()) {
            const std::string path =
                opt.cache_dir.empty() ? "" : cache_path(opt, device->family(), mesa, spirv);
            std::optional<RadvStatistics> stats;
            // An entry that says the compile was stopped at a limit no smaller than this
            // run's stands for the same outcome; a larger limit tries again.
            const std::optional<CachedCompile> cached =
                path.empty() ? std::nullopt : read_cached(path);
            const bool known_stopped =
                cached && !cached->stats && cached->stopped_after >= opt.compile_seconds;
            if (cached && cached->stats) stats = cached->stats;
            if (!stats && !known_stopped) {
                stats = device->compile(spirv, diag, opt.compile_seconds,
                                        opt.compile_memory_bytes, &stopped);
                if (!stats && !stopped) return nullptr;
                if (!path.empty()) {
                    if (stats) write_cached(path, *stats);
                    else write_stopped(path, opt.compile_seconds);
                }
            } else if (known_stopped && diag) {
                diag({Severity::Warning, "", 0,
                      fmt::format("gpu cost: the module's compile did not finish within {} s "
                                  "before ({}): not tried again",
                                  cached->stopped_after, path)});
            }
            it = compiled.emplace(spirv, std::move(stats)).first;
        }
        stopped = !it->second;
        return it->second ? &*it->second : nullptr;
    }

    const std::vector<uint32_t>* kernel(const Variant& v, const DiagnosticConsumer& diag) {
        const std::string name = canonical_name(v);
        auto it = kernels.find(name);
        if (it == kernels.end()) {
            auto words = generated_kernel_spirv(v, diag);
            if (!words) return nullptr;
            it = kernels.emplace(name, std::move(*words)).first;
        }
        return &it->second;
    }
};

GpuCostMeter::GpuCostMeter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuCostMeter::~GpuCostMeter() = default;

std::unique_ptr<GpuCostMeter> GpuCostMeter::create(const GpuCostOptions& opt,
                                                   const DiagnosticConsumer& diag) {
    auto device = RadvDevice::create(opt.family, opt.icd, diag);
    if (!device) return nullptr;
    if (!opt.cache_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(opt.cache_dir, ec);
        if (ec && diag)
            diag({Severity::Warning, opt.cache_dir, 0,
                  fmt::format("gpu cost: cache folder {}: {}; compiling without it",
                              opt.cache_dir, ec.message())});
    }
    auto impl = std::make_unique<Impl>();
    impl->opt = opt;
    impl->mesa = mesa_version(device->driver_info());
    impl->device = std::move(device);
    return std::unique_ptr<GpuCostMeter>(new GpuCostMeter(std::move(impl)));
}

const std::string& GpuCostMeter::family() const {
    return impl_->device->family();
}
const std::string& GpuCostMeter::mesa() const {
    return impl_->mesa;
}

std::optional<GpuCost> GpuCostMeter::measure(const std::vector<uint32_t>& spirv,
                                             const DiagnosticConsumer& diag) {
    bool stopped = false;
    const RadvStatistics* written = impl_->compile(spirv, diag, stopped);
    if (!written) return std::nullopt;
    const auto unrolled_words = unroll_constant_loops(spirv, diag);
    if (!unrolled_words) return std::nullopt;
    // Stopped (past the time or memory limit): a diagnostic came as an error; what it
    // means here is a figure left out.
    auto warning = [&](const Diagnostic& d) {
        if (!diag) return;
        Diagnostic w = d;
        w.severity = Severity::Warning;
        diag(w);
    };
    const RadvStatistics* unrolled = impl_->compile(*unrolled_words, warning, stopped);
    if (!unrolled && !stopped) return std::nullopt;
    if (stopped && diag)
        diag({Severity::Warning, "", 0,
              "gpu cost: the unrolled module was not compiled; its cost is the figure as "
              "written (inverse_throughput_unrolled 0)"});

    std::string missing;
    auto stat = [&](const RadvStatistics& s, const char* name) -> uint64_t {
        auto it = s.values.find(name);
        if (it == s.values.end() || !std::isfinite(it->second) || it->second < 0) {
            missing += std::string(missing.empty() ? "" : ", ") + name;
            return 0;
        }
        return static_cast<uint64_t>(it->second);
    };
    GpuCost c;
    c.family = family();
    c.mesa = mesa();
    c.wave = written->subgroup_size;
    c.instructions = stat(*written, kInstructions);
    c.vgprs = stat(*written, kVgprs);
    c.spilled_vgprs = stat(*written, kSpilledVgprs);
    c.scratch_bytes = stat(*written, kScratch);
    c.latency = stat(*written, kLatency);
    c.inverse_throughput = stat(*written, kInverseThroughput);
    c.waves_per_simd = stat(*written, kWavesPerSimd);
    c.inverse_throughput_unrolled = unrolled ? stat(*unrolled, kInverseThroughput) : 0;
    c.cost = std::max(c.inverse_throughput, c.inverse_throughput_unrolled);
    if (!missing.empty()) {
        if (diag)
            diag({Severity::Error, "", 0,
                  "gpu cost (RADV " + family() + "): the driver reported no " + missing});
        return std::nullopt;
    }
    return c;
}

std::optional<GpuCost> GpuCostMeter::measure(const Variant& v, const DiagnosticConsumer& diag) {
    const auto* words = impl_->kernel(v, diag);
    if (!words) return std::nullopt;
    auto cost = measure(*words, diag);
    if (!cost) return std::nullopt;
    const Variant base = baseline_of(v);
    if (!is_valid(base)) return cost;
    const auto* base_words = impl_->kernel(base, diag);
    if (!base_words) return std::nullopt;
    const auto base_cost = measure(*base_words, diag);
    if (!base_cost) return std::nullopt;
    if (base_cost->cost > 0)
        cost->ratio_to_point =
            static_cast<double>(cost->cost) / static_cast<double>(base_cost->cost);
    return cost;
}

std::optional<GpuCost> gpu_cost(const std::vector<uint32_t>& spirv, const GpuCostOptions& opt,
                                const DiagnosticConsumer& diag) {
    auto meter = GpuCostMeter::create(opt, diag);
    if (!meter) return std::nullopt;
    return meter->measure(spirv, diag);
}

std::optional<GpuCost> gpu_cost(const Variant& v, const GpuCostOptions& opt,
                                const DiagnosticConsumer& diag) {
    auto meter = GpuCostMeter::create(opt, diag);
    if (!meter) return std::nullopt;
    return meter->measure(v, diag);
}

}  // namespace arealight
