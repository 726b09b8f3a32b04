// VulkanRunner on lavapipe (or whatever device the loader finds first): dispatch, batching, errors.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "arealight/vulkan_runner.hpp"

using namespace arealight;

namespace {

// float32 results against a double reference: a few ulp of sqrt and an exact doubling.
constexpr double kRelativeTolerance = 1e-6;

// The runner's contract: local_size_x = 64, bindings 0/1, push constants count and base.
const char* const kTwiceAndSqrt = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer In { float in_values[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Out { float out_values[]; };
layout(push_constant) uniform Push { uint count; uint base; } pc;

void main() {
    uint i = pc.base + gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    out_values[i * 2u + 0u] = in_values[i] * 2.0;
    out_values[i * 2u + 1u] = sqrt(in_values[i]);
}
)";

struct Collected {
    std::string text;
    DiagnosticConsumer consumer() {
        return [this](const Diagnostic& d) {
            text += std::string(to_string(d.severity)) + ": " + d.message + "\n";
        };
    }
};

std::vector<uint32_t> compiled_shader() {
    Collected diag;
    auto spirv = compile_glsl(kTwiceAndSqrt, "twice_sqrt.comp", CompileOptions{}, diag.consumer());
    INFO(diag.text);
    REQUIRE(spirv);
    return *spirv;
}

std::unique_ptr<VulkanRunner> make_runner() {
    Collected diag;
    auto runner = VulkanRunner::create("", diag.consumer());
    INFO(diag.text);
    REQUIRE(runner);
    return runner;
}

// Log-uniform magnitudes in [1e-3, 1e3] with a fixed seed.
std::vector<float> inputs(std::size_t n) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> exponent(-3.0, 3.0);
    std::vector<float> v(n);
    for (auto& x : v) x = static_cast<float>(std::pow(10.0, exponent(rng)));
    return v;
}

double rel_err(double x, double ref) {
    return std::abs(x - ref) / std::abs(ref);
}

// Counts mismatches and describes the first few, so a failure shows the actual values.
std::size_t check_twice_sqrt(const std::vector<float>& in, const std::vector<float>& out,
                             std::string& report) {
    std::size_t bad = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
        const double expected[2] = {2.0 * in[i], std::sqrt(static_cast<double>(in[i]))};
        for (int k = 0; k < 2; ++k) {
            const double actual = out[i * 2 + k];
            if (!(rel_err(actual, expected[k]) <= kRelativeTolerance)) {
                if (++bad <= 5) {
                    report += "item " + std::to_string(i) + "[" + std::to_string(k) + "]: actual " +
                              std::to_string(actual) + ", expected " + std::to_string(expected[k]) +
                              "\n";
                }
            }
        }
    }
    return bad;
}

}  // namespace

TEST_CASE("runner computes 2x and sqrt for 1000 inputs", "[vulkan]") {
    const auto spirv = compiled_shader();
    auto runner = make_runner();
    const auto in = inputs(1000);
    std::vector<float> out;
    Collected diag;
    double seconds = -1.0;
    REQUIRE(runner->run(spirv, in.data(), in.size() * sizeof(float), in.size(), out, 2,
                        diag.consumer(), &seconds));
    INFO("device " << runner->device_name() << "\n" << diag.text);
    REQUIRE(out.size() == 2000);
    std::string mismatches;
    const std::size_t bad = check_twice_sqrt(in, out, mismatches);
    INFO(mismatches);
    CHECK(bad == 0);
    CHECK(seconds >= 0.0);

    // Second run reuses the cached pipeline and gives the same answer.
    std::vector<float> again;
    REQUIRE(runner->run(spirv, in.data(), in.size() * sizeof(float), in.size(), again, 2,
                        diag.consumer()));
    CHECK(again == out);
}

TEST_CASE("runner accepts a count of 0", "[vulkan]") {
    const auto spirv = compiled_shader();
    auto runner = make_runner();
    std::vector<float> out = {1.0f, 2.0f};
    Collected diag;
    REQUIRE(runner->run(spirv, nullptr, 0, 0, out, 2, diag.consumer()));
    INFO(diag.text);
    CHECK(out.empty());
}

TEST_CASE("runner splits counts beyond one dispatch into batches", "[vulkan]") {
    const auto spirv = compiled_shader();
    auto runner = make_runner();
    const std::size_t n = 65535u * 64u + 1000u;  // one full batch plus a partial one
    const auto in = inputs(n);
    std::vector<float> out;
    Collected diag;
    REQUIRE(runner->run(spirv, in.data(), in.size() * sizeof(float), n, out, 2, diag.consumer()));
    INFO(diag.text);
    REQUIRE(out.size() == 2 * n);
    std::string mismatches;
    const std::size_t bad = check_twice_sqrt(in, out, mismatches);
    INFO(mismatches);
    CHECK(bad == 0);
}

TEST_CASE("a device name that matches nothing lists the available devices", "[vulkan]") {
    auto first = make_runner();
    Collected diag;
    auto runner = VulkanRunner::create("no-such-device-xyzzy", diag.consumer());
    INFO(diag.text);
    CHECK(runner == nullptr);
    CHECK(diag.text.find("no-such-device-xyzzy") != std::string::npos);
    CHECK(diag.text.find(first->device_name()) != std::string::npos);
}

TEST_CASE("runner rejects input that is not SPIR-V and leaves output untouched", "[vulkan]") {
    auto runner = make_runner();
    std::vector<float> out = {42.0f};
    Collected diag;
    const float one = 1.0f;
    CHECK_FALSE(runner->run({1, 2, 3, 4, 5}, &one, sizeof(one), 1, out, 1, diag.consumer()));
    CHECK(out == std::vector<float>{42.0f});
    CHECK(diag.text.find("SPIR-V") != std::string::npos);
}
