// Runs one variant over a case set on a backend: the CPU mirror or the generated
// SPIR-V on a Vulkan device. Host-side normalization follows CONTRACT.md 1.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/case_layout.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/generator.hpp"
#include "arealight/results.hpp"
#include "arealight/texture.hpp"
#include "arealight/variant.hpp"

namespace arealight {

enum class Backend { Cpu, Vulkan };
const char* to_string(Backend b);

// Whether the variant computes this case: same distribution and light type, a
// polygon no larger than `verts`, and sidedness it supports.
bool case_applies(const Variant& v, const Case& c);

// Whether the variant computes a quantity beside diffuse and specular (ndf or
// moment: its family's second_quantity).
bool has_second_quantity(const Variant& v);

// Cases in the validation kernel's layout (arealight/case_layout.hpp): each case's
// values as given, rounded to fp32. No geometry: the library function does it.
std::vector<float> pack_cases(const std::vector<const Case*>& cases);

struct EvalOptions {
    Backend backend = Backend::Vulkan;
    std::string device;    // Vulkan device name substring; empty = first
    bool optimize = true;  // SPIRV-Tools performance passes
    // Vulkan: the kernel around the GLSL library, or the HLSL kernel around the HLSL
    // library (generate_hlsl_kernel; fp32 variants, language_supports).
    Language language = Language::Glsl;
    // Vulkan: a folder of compiled kernels shared by processes (spirv_cache.hpp); empty:
    // compile each kernel once per evaluator. The test suite's AREALIGHT_SPIRV_CACHE.
    std::string spirv_cache;
};

struct EvalStats {
    std::size_t evaluated = 0, skipped = 0;
    double seconds = 0.0;  // backend time: mirror loop, or Vulkan submit + wait
};

class Evaluator {
  public:
    // nullptr with a diagnostic when the backend cannot start (no Vulkan device).
    static std::unique_ptr<Evaluator> create(const EvalOptions& opt,
                                             const DiagnosticConsumer& diag);
    ~Evaluator();

    // The Vulkan device's name, or "cpu mirror".
    std::string device_name() const;

    // Results for the applicable cases, in file order; nullopt on failure.
    std::optional<ResultSet> run(const Variant& v, const CaseSet& cases,
                                 const DiagnosticConsumer& diag, EvalStats* stats = nullptr);
    // Raw 4-float results for already-packed cases (benchmarks reuse one packing):
    // by default only what the library function returns (diffuse, specular), the
    // kernel that is timed and counted; KernelOutputs::All adds ndf or moment.
    bool run_packed(const Variant& v, const std::vector<float>& packed, std::size_t count,
                    std::vector<float>& results, const DiagnosticConsumer& diag,
                    double* seconds = nullptr,
                    KernelOutputs outputs = KernelOutputs::Shading);

  private:
    struct Impl;
    explicit Evaluator(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// The tables the variant's shader samples, in binding order (texture k: set 0,
// binding 2 + k on Vulkan; the mirror's k-th sampler): for the families whose
// samplers are {"al_ltc_matrix", "al_ltc_amplitude"} (method=ltc),
// &builtin_ltc_textures(v.dist)[0] and [1], which live for the program; empty for a
// family without samplers. Throws std::invalid_argument, naming the variant and the
// sampler, for a sampler name it has no table for. Evaluator::run and run_packed bind
// these on both backends.
std::vector<const Texture2D*> variant_textures(const Variant& v);
// The same, with the error as a diagnostic instead of an exception.
std::optional<std::vector<const Texture2D*>> variant_textures(const Variant& v,
                                                              const DiagnosticConsumer& diag);

// GLSL -> validated (optimized) SPIR-V of a variant's validation kernel; compiler
// messages are prefixed with the variant's name. Shading: the kernel that is timed
// and counted (the library function alone).
std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, bool optimize,
                                                 const DiagnosticConsumer& diag,
                                                 KernelOutputs outputs = KernelOutputs::Shading);
// The module `arealight generate --variant NAME --spv FILE` writes (CONTRACT.md 4):
// the validation kernel with every output (KernelOutputs::All), optimized unless
// `optimize` is false. What outside checks and the GPU cost (gpu_cost.hpp) measure.
std::optional<std::vector<uint32_t>> generated_kernel_spirv(const Variant& v,
                                                            const DiagnosticConsumer& diag,
                                                            bool optimize = true);
// The HLSL validation kernel's SPIR-V (generate_hlsl_kernel through glslang's HLSL front
// end): what the GLSL kernel computes, from the HLSL library.
std::optional<std::vector<uint32_t>> build_hlsl_spirv(const Variant& v, bool optimize,
                                                      const DiagnosticConsumer& diag,
                                                      KernelOutputs outputs = KernelOutputs::Shading);
// Same, for GLSL text already stitched for `v` (tests inject broken templates).
std::optional<std::vector<uint32_t>> build_spirv(const Variant& v, const std::string& glsl,
                                                 bool optimize, const DiagnosticConsumer& diag);

}  // namespace arealight
