#include "arealight/benchmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "arealight/compiler.hpp"
#include "arealight/machine_code.hpp"

namespace arealight {

std::optional<std::vector<BenchRow>> benchmark(Evaluator& ev, const CaseSet& cases,
                                               const BenchOptions& opt,
                                               const DiagnosticConsumer& diag,
                                               const ProgressConsumer& progress) {
    std::vector<BenchRow> rows;
    // Instruction counts are deterministic: one measurement per variant.
    std::vector<std::size_t> spirv_counts(opt.variants.size(), 0),
        x86_counts(opt.variants.size(), 0);
    if (!opt.shader_cache_dir.empty()) {
        // A module already compiled (an equal variant, or one whose shader is the same)
        // is in lavapipe's cache already: count it once.
        std::map<std::vector<uint32_t>, std::size_t> x86_of;
        for (std::size_t k = 0; k < opt.variants.size(); ++k) {
            auto words = build_spirv(opt.variants[k], true, diag);
            if (!words) return std::nullopt;
            spirv_counts[k] = spirv_instruction_count(*words);
            if (auto known = x86_of.find(*words); known != x86_of.end()) {
                x86_counts[k] = known->second;
                continue;
            }
            auto code = lavapipe_machine_code(opt.variants[k], opt.shader_cache_dir, diag);
            if (!code) return std::nullopt;
            x86_counts[k] = code->instructions;
            x86_of.emplace(*words, x86_counts[k]);
        }
    }
    std::vector<std::optional<GpuCost>> gpu(opt.variants.size());
    if (opt.gpu) {
        if (auto meter = GpuCostMeter::create(*opt.gpu, diag)) {
            for (std::size_t k = 0; k < opt.variants.size(); ++k) {
                gpu[k] = meter->measure(opt.variants[k], diag);
                if (!gpu[k]) return std::nullopt;
            }
        }
    }
    std::vector<double> exponents = opt.exponents;
    if (exponents.empty()) exponents.push_back(0.0);
    const std::size_t total = exponents.size() * opt.variants.size() * opt.repeats;
    std::size_t done = 0;
    for (double N : exponents) {
        CaseSet set = cases;
        if (N > 0)
            for (auto& c : set.cases) c.material.exponent = N;
        // One packing per variant, repeated up to min_cases so that a dispatch
        // is long enough to time.
        std::vector<std::vector<float>> packed(opt.variants.size());
        std::vector<std::size_t> counts(opt.variants.size());
        for (std::size_t k = 0; k < opt.variants.size(); ++k) {
            std::vector<const Case*> todo;
            for (const auto& c : set.cases)
                if (case_applies(opt.variants[k], c)) todo.push_back(&c);
            if (todo.empty()) {
                if (diag)
                    diag({Severity::Error, "", 0,
                          "benchmark: no case applies to " + canonical_name(opt.variants[k])});
                return std::nullopt;
            }
            std::vector<const Case*> reps;
            while (reps.size() < opt.min_cases) reps.insert(reps.end(), todo.begin(), todo.end());
            packed[k] = pack_cases(reps);
            counts[k] = reps.size();
        }
        // Interleaved repeats: drift and noise from other load hit every variant alike.
        std::vector<std::vector<double>> times(opt.variants.size());
        std::vector<float> out;
        for (int rep = 0; rep < opt.repeats; ++rep) {
            for (std::size_t k = 0; k < opt.variants.size(); ++k) {
                double s = 0;
                if (!ev.run_packed(opt.variants[k], packed[k], counts[k], out, diag, &s))
                    return std::nullopt;
                times[k].push_back(s / counts[k] * 1e9);
                if (progress) progress(++done, total);
            }
        }
        std::vector<double> medians;
        for (auto& t : times) {
            std::sort(t.begin(), t.end());
            medians.push_back(t[t.size() / 2]);
        }
        for (std::size_t k = 0; k < opt.variants.size(); ++k) {
            rows.push_back({canonical_name(opt.variants[k]), N, counts[k], medians[k],
                            medians[k] / medians[0], spirv_counts[k], x86_counts[k], gpu[k]});
        }
    }
    return rows;
}

std::string format_bench(const std::vector<BenchRow>& rows) {
    std::size_t w = 7;
    for (const auto& r : rows) w = std::max(w, r.variant.size());
    std::string t =
        fmt::format("{:<{}} {:>9} {:>8} {:>12} {:>9} {:>8} {:>8} {:>9} {:>8} {:>6} {:>6}\n",
                    "variant", w, "exponent", "cases", "ns/case", "x base", "SPIR-V", "x86-64",
                    "GPU cost", "x point", "VGPRs", "waves");
    for (const auto& r : rows) {
        auto gpu = [&](auto field) { return r.gpu ? fmt::format("{}", field(*r.gpu)) : "-"; };
        t += fmt::format(
            "{:<{}} {:>9} {:>8} {:>12.1f} {:>9.2f} {:>8} {:>8} {:>9} {:>8} {:>6} {:>6}\n",
            r.variant, w, r.exponent > 0 ? fmt::format("{:g}", r.exponent) : "case", r.cases,
            r.median_ns_per_case, r.ratio, r.spirv_instructions, r.x86_instructions,
            gpu([](const GpuCost& g) { return g.cost; }),
            gpu([](const GpuCost& g) { return fmt::format("{:.2f}", g.ratio_to_point); }),
            gpu([](const GpuCost& g) { return g.vgprs; }),
            gpu([](const GpuCost& g) { return g.waves_per_simd; }));
    }
    // Which compiler measured the GPU columns.
    for (const auto& r : rows)
        if (r.gpu) {
            t += fmt::format(
                "GPU cost: ACO inverse throughput (cycles per wave, loops unrolled "
                "where constant) on RADV {}, Mesa {}, wave{}\n",
                r.gpu->family, r.gpu->mesa, r.gpu->wave);
            break;
        }
    return t;
}

}  // namespace arealight
