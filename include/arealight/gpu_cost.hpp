// What a kernel costs on a GPU, without a GPU: Mesa's RADV driver compiles the SPIR-V
// with its ACO back end for one AMD chip family on a null device, and reports the
// result's instructions, registers, scratch, occupancy, and ACO's own latency and
// throughput model. That model counts every loop as 8 iterations, so the module is
// also measured with its constant-trip-count loops unrolled (unroll_loops.hpp), and
// the cost is the larger figure (CONTRACT.md 4): the number outside checks recompute
// with shared/tools/radvstats on `arealight generate --spv` output and on it after
// shared/tools/spv_unroll.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arealight/diagnostics.hpp"

namespace arealight {

struct Variant;

// The RADV figures of one module (the `gpu` object of reports and quality data).
struct GpuCost {
    std::string family;  // RADV_FORCE_FAMILY, lower case: navi21, gfx1100, vega10, ...
    std::string mesa;    // the driver's version, e.g. "22.3.6"
    uint32_t wave = 0;   // the wave size it was compiled for (64: compute default)
    // Of the module as written:
    uint64_t instructions = 0, vgprs = 0, spilled_vgprs = 0, scratch_bytes = 0;
    uint64_t latency = 0;             // ACO's estimate, cycles
    uint64_t inverse_throughput = 0;  // ACO's estimate, cycles per wave
    uint64_t waves_per_simd = 0;      // "Subgroups per SIMD": the occupancy registers allow
    // ACO's inverse throughput of the module with its constant loops unrolled; 0 where
    // that module's compile was stopped (GpuCostOptions::compile_seconds).
    uint64_t inverse_throughput_unrolled = 0;
    uint64_t cost = 0;  // max(inverse_throughput, inverse_throughput_unrolled)
    // cost over the point baseline's (report.hpp baseline_of), measured the same way;
    // 0 when there is no baseline.
    double ratio_to_point = 0;

    bool operator==(const GpuCost& o) const {
        return family == o.family && mesa == o.mesa && wave == o.wave &&
               instructions == o.instructions && vgprs == o.vgprs &&
               spilled_vgprs == o.spilled_vgprs && scratch_bytes == o.scratch_bytes &&
               latency == o.latency && inverse_throughput == o.inverse_throughput &&
               waves_per_simd == o.waves_per_simd &&
               inverse_throughput_unrolled == o.inverse_throughput_unrolled && cost == o.cost &&
               ratio_to_point == o.ratio_to_point;
    }
    bool operator!=(const GpuCost& o) const { return !(*this == o); }
};

inline constexpr const char* kRadvIcd = "/usr/share/vulkan/icd.d/radeon_icd.x86_64.json";

struct GpuCostOptions {
    std::string family = "navi21";  // one of radv_families(), any case
    std::string icd = kRadvIcd;     // the RADV ICD manifest; its library_path is loaded
    // Each compile runs in a forked copy of the process, stopped past this time or
    // memory (beyond what the process maps): ACO runs for minutes and into many GB on a
    // few unrolled modules (dist=phong,method=arvo: radvstats too). 0 s: in process, no
    // limit. An unrolled module stopped so has inverse_throughput_unrolled 0 and the
    // cost as written, with a warning; a module as written stopped so has no GpuCost.
    double compile_seconds = 60;
    uint64_t compile_memory_bytes = uint64_t{6} << 30;
    // A folder of RADV's statistics by module (family, Mesa version and a hash of the
    // words name each file): a module compiled once, in any run, is not compiled again.
    // Empty: no cache. `--gpu-cache` / AREALIGHT_GPU_CACHE on the command line.
    std::string cache_dir;
};

// The chip families RADV_FORCE_FAMILY accepts in Mesa 22.3 (lower case). A name it
// does not know makes the driver abort the process, so every name is checked here.
const std::vector<std::string>& radv_families();
bool is_radv_family(const std::string& name);  // case-insensitive

// One RADV null device, kept for many modules, with a cache of what it measured
// (keyed by the module's words). Not thread-safe; see runtime/radv_device.hpp for the
// environment it sets while it creates its device.
class GpuCostMeter {
  public:
    // nullptr, with one warning line saying why (no manifest, the library does not
    // load, an unknown family, no null device), when RADV cannot be used.
    static std::unique_ptr<GpuCostMeter> create(const GpuCostOptions& opt,
                                                const DiagnosticConsumer& diag);
    ~GpuCostMeter();
    GpuCostMeter(const GpuCostMeter&) = delete;
    GpuCostMeter& operator=(const GpuCostMeter&) = delete;

    const std::string& family() const;
    const std::string& mesa() const;

    // The figures of `spirv` (ratio_to_point 0); nullopt with a diagnostic when the
    // module does not unroll or compile.
    std::optional<GpuCost> measure(const std::vector<uint32_t>& spirv,
                                   const DiagnosticConsumer& diag);
    // Those of the variant's validation kernel as `arealight generate --spv` writes it
    // (generated_kernel_spirv), with ratio_to_point against baseline_of(v)'s.
    std::optional<GpuCost> measure(const Variant& v, const DiagnosticConsumer& diag);

  private:
    struct Impl;
    explicit GpuCostMeter(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// One-off forms of the meter's (a device each call: for many modules keep a meter).
std::optional<GpuCost> gpu_cost(const std::vector<uint32_t>& spirv, const GpuCostOptions& opt,
                                const DiagnosticConsumer& diag);
std::optional<GpuCost> gpu_cost(const Variant& v, const GpuCostOptions& opt,
                                const DiagnosticConsumer& diag);

}  // namespace arealight
