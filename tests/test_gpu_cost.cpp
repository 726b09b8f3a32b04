// The GPU cost (RADV/ACO on a null device): ordering on known shaders, cost = the
// larger of as written and unrolled, the in-process unroll against spirv-opt's command
// line, an unknown chip family refused before the driver sees it, lavapipe unharmed in
// the same process, and the gpu object through the quality data. Where RADV is absent
// the RADV cases pass after saying why.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "arealight/compiler.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/gpu_cost.hpp"
#include "arealight/gpu_cost_json.hpp"
#include "arealight/quality.hpp"
#include "arealight/report.hpp"
#include "arealight/unroll_loops.hpp"
#include "arealight/variant.hpp"
#include "arealight/vulkan_runner.hpp"
#include "diagnostic_support.hpp"
#include "scratch_folder.hpp"
#include "test_support.hpp"

using namespace arealight;

namespace {

// ACO counts a loop as 8 iterations: unrolled, a 100-iteration loop whose body
// dominates is 100/8 = 12.5 times heavier; at least this factor must show.
constexpr double kMinUnrollGain = 5.0;
// A loop of 100 sin() is far above a load, a multiply and a store as written too.
constexpr double kMinLoopOverTrivial = 4.0;
// The Vulkan kernel against the CPU mirror of one variant: both fp32, a few ulp apart.
constexpr double kMirrorAgreement = 1e-5;

const char* const kTrivial = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) buffer Data { float x[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    x[i] = x[i] * 2.0;
}
)";

const char* const kConstantLoop = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) buffer Data { float x[]; };
layout(push_constant) uniform Push { uint count; uint base; } pc;
void main() {
    uint i = pc.base + gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    float a = x[i];
    for (int k = 0; k < 100; ++k) a = sin(a) * cos(a * 1.5) + exp2(a * 0.001) + inversesqrt(abs(a) + 1.0);
    x[i] = a;
}
)";

using test::Collected;

std::vector<uint32_t> compiled(const char* glsl, const char* name) {
    return test::compile(glsl, name);
}

// A meter on navi21, or nullptr after saying why RADV is absent (the case then passes).
std::unique_ptr<GpuCostMeter> meter_or_skip() {
    Collected diag;
    auto meter = GpuCostMeter::create(GpuCostOptions{}, diag.consumer());
    if (!meter) WARN("RADV absent, GPU cost not tested: " << diag.text);
    return meter;
}

std::vector<uint32_t> read_words(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::vector<uint32_t> w(bytes.size() / 4);
    if (!w.empty()) std::memcpy(w.data(), bytes.data(), w.size() * 4);
    return w;
}

void write_words(const std::string& path, const std::vector<uint32_t>& w) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(w.data()), static_cast<std::streamsize>(w.size() * 4));
}

std::string describe(const GpuCost& c) {
    return nlohmann::ordered_json(gpu_cost_json(c)).dump();
}

}  // namespace

TEST_CASE("gpu cost: a constant loop costs more than a trivial kernel, unrolled far more",
          "[gpu_cost]") {
    auto meter = meter_or_skip();
    if (!meter) return;
    Collected diag;
    const auto trivial = meter->measure(compiled(kTrivial, "trivial.comp"), diag.consumer());
    const auto loop = meter->measure(compiled(kConstantLoop, "loop.comp"), diag.consumer());
    INFO(diag.text);
    REQUIRE(trivial);
    REQUIRE(loop);
    INFO("trivial: " << describe(*trivial));
    INFO("loop:    " << describe(*loop));
    CHECK(trivial->family == "navi21");
    CHECK(trivial->wave == 64);
    CHECK_FALSE(trivial->mesa.empty());
    CHECK(trivial->instructions > 0);
    CHECK(trivial->vgprs > 0);
    CHECK(trivial->waves_per_simd > 0);
    // No loop: the unrolled module compiles to the same figure.
    CHECK(trivial->inverse_throughput_unrolled == trivial->inverse_throughput);
    CHECK(loop->inverse_throughput > kMinLoopOverTrivial * trivial->inverse_throughput);
    CHECK(loop->inverse_throughput_unrolled > kMinUnrollGain * loop->inverse_throughput);
    CHECK(loop->cost == std::max(loop->inverse_throughput, loop->inverse_throughput_unrolled));
    CHECK(trivial->cost == trivial->inverse_throughput);
    CHECK(loop->ratio_to_point == 0);  // a module has no baseline
}

TEST_CASE("gpu cost: the cache folder keeps each module's statistics for the next meter",
          "[gpu_cost]") {
    if (!meter_or_skip()) return;
    test::ScratchFolder scratch("gpu_cache");
    GpuCostOptions opt;
    opt.cache_dir = scratch / "cache";
    const auto words = compiled(kTrivial, "trivial.comp");
    Collected diag;
    auto first = GpuCostMeter::create(opt, diag.consumer());
    REQUIRE(first);
    const auto measured = first->measure(words, diag.consumer());
    INFO(diag.text);
    REQUIRE(measured);
    // One file per module compiled: a loop-free module is its own unrolled module.
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(opt.cache_dir))
        files.push_back(e.path());
    REQUIRE(files.size() == 1);
    CHECK(files[0].filename().string().rfind("navi21-" + measured->mesa + "-", 0) == 0);
    // A second meter reads the file instead of compiling: a figure planted in it comes
    // back as the module's cost.
    std::ifstream in(files[0]);
    auto doc = nlohmann::json::parse(in);
    const double planted = 123457;
    doc["values"]["Inverse Throughput"] = planted;
    std::ofstream(files[0]) << doc.dump();
    auto second = GpuCostMeter::create(opt, diag.consumer());
    REQUIRE(second);
    const auto cached = second->measure(words, diag.consumer());
    REQUIRE(cached);
    CHECK(cached->cost == static_cast<uint64_t>(planted));
    CHECK(cached->instructions == measured->instructions);
    // An unreadable entry is a miss: compiled again, the true figure, and rewritten.
    std::ofstream(files[0]) << "not json";
    auto third = GpuCostMeter::create(opt, diag.consumer());
    REQUIRE(third);
    const auto again = third->measure(words, diag.consumer());
    REQUIRE(again);
    CHECK(again->cost == measured->cost);
    std::ifstream reread(files[0]);
    CHECK(nlohmann::json::parse(reread, nullptr, false).is_object());
}

TEST_CASE("gpu cost: a compile stopped at its limit is remembered, and retried at a larger one",
          "[gpu_cost]") {
    if (!meter_or_skip()) return;
    test::ScratchFolder scratch("gpu_cache_stopped");
    GpuCostOptions opt;
    opt.cache_dir = scratch / "cache";
    opt.compile_seconds = 1e-4;  // no compile finishes this fast: each is stopped
    const auto words = compiled(kTrivial, "trivial.comp");
    auto entries = [&] {
        std::vector<nlohmann::json> docs;
        for (const auto& e : std::filesystem::directory_iterator(opt.cache_dir)) {
            std::ifstream in(e.path());
            docs.push_back(nlohmann::json::parse(in, nullptr, false));
        }
        return docs;
    };
    Collected first_diag;
    auto first = GpuCostMeter::create(opt, first_diag.consumer());
    REQUIRE(first);
    CHECK_FALSE(first->measure(words, first_diag.consumer()));
    auto docs = entries();
    INFO(first_diag.text);
    REQUIRE(docs.size() == 1);
    CHECK(docs[0].value("stopped_after_seconds", 0.0) == opt.compile_seconds);
    // The same limit: not compiled again, and said so.
    Collected second_diag;
    auto second = GpuCostMeter::create(opt, second_diag.consumer());
    REQUIRE(second);
    CHECK_FALSE(second->measure(words, second_diag.consumer()));
    INFO(second_diag.text);
    CHECK(second_diag.text.find("not tried again") != std::string::npos);
    // A larger limit compiles it, and the entry becomes its statistics.
    opt.compile_seconds = 60;
    Collected third_diag;
    auto third = GpuCostMeter::create(opt, third_diag.consumer());
    REQUIRE(third);
    const auto measured = third->measure(words, third_diag.consumer());
    INFO(third_diag.text);
    REQUIRE(measured);
    CHECK(measured->cost > 0);
    docs = entries();
    REQUIRE(docs.size() == 1);
    CHECK(docs[0].contains("values"));
}

TEST_CASE("gpu cost: a variant is measured on generate's kernel, against its point light",
          "[gpu_cost]") {
    auto meter = meter_or_skip();
    if (!meter) return;
    Collected diag;
    const auto point = parse_variant("dist=ggx,method=point,light=polygon", diag.consumer());
    const auto ltc = parse_variant("dist=ggx,method=ltc,light=polygon", diag.consumer());
    REQUIRE(point);
    REQUIRE(ltc);
    const auto p = meter->measure(*point, diag.consumer());
    const auto l = meter->measure(*ltc, diag.consumer());
    const auto kernel = generated_kernel_spirv(*ltc, diag.consumer());
    INFO(diag.text);
    REQUIRE(p);
    REQUIRE(l);
    REQUIRE(kernel);
    INFO("point: " << describe(*p));
    INFO("ltc:   " << describe(*l));
    CHECK(p->ratio_to_point == 1.0);
    CHECK(l->cost > p->cost);
    CHECK(l->ratio_to_point == Approx(double(l->cost) / double(p->cost)).epsilon(1e-12));
    // The module of `generate --spv`, measured on its own, gives the same figures.
    auto alone = meter->measure(*kernel, diag.consumer());
    REQUIRE(alone);
    alone->ratio_to_point = l->ratio_to_point;
    CHECK(*alone == *l);
}

TEST_CASE("gpu cost: the in-process unroll is spirv-opt --loop-unroll -O, word for word",
          "[gpu_cost]") {
#ifndef AREALIGHT_SPIRV_OPT
    WARN("spirv-opt not found at configure time: the independent check is skipped");
#else
    test::ScratchFolder dir("gpu_unroll");
    Collected diag;
    const auto fp32_exact =
        parse_variant("dist=phong,method=exact,light=polygon,nodes=8,precision=fp32", {});
    REQUIRE(fp32_exact);
    const auto kernel = generated_kernel_spirv(*fp32_exact, diag.consumer());
    INFO(diag.text);
    REQUIRE(kernel);
    const std::vector<std::pair<std::string, std::vector<uint32_t> > > modules = {
        {"loop", compiled(kConstantLoop, "loop.comp")}, {"phong_exact", *kernel}};
    for (const auto& [name, words] : modules) {
        INFO(name);
        REQUIRE(spirv_loop_count(words) > 0);
        const auto marked = mark_loops_unroll(words);
        const std::string in = dir / (name + ".marked.spv"), out = dir / (name + ".spv");
        write_words(in, marked);
        const std::string cmd =
            std::string(AREALIGHT_SPIRV_OPT) + " --loop-unroll -O " + in + " -o " + out;
        REQUIRE(std::system(cmd.c_str()) == 0);
        const auto ours = unroll_constant_loops(words, diag.consumer());
        INFO(diag.text);
        REQUIRE(ours);
        const auto theirs = read_words(out);
        CHECK(ours->size() == theirs.size());
        CHECK(*ours == theirs);
        CHECK(spirv_loop_count(*ours) < spirv_loop_count(words));
    }
#endif
}

TEST_CASE("gpu cost: an unknown chip family is a diagnostic, not an abort", "[gpu_cost]") {
    Collected diag;
    GpuCostOptions opt;
    opt.family = "gfx1030";  // an LLVM target name: RADV would abort on it
    CHECK_FALSE(is_radv_family(opt.family));
    CHECK(is_radv_family("NAVI21"));
    CHECK_FALSE(GpuCostMeter::create(opt, diag.consumer()));
    INFO(diag.text);
    CHECK(diag.lines == 1);
    CHECK(diag.text.find("gfx1030") != std::string::npos);

    // A missing driver is the same: one line why, no meter.
    Collected missing;
    GpuCostOptions none;
    none.icd = "/nonexistent/radeon_icd.json";
    CHECK_FALSE(gpu_cost(compiled(kTrivial, "trivial.comp"), none, missing.consumer()));
    INFO(missing.text);
    CHECK(missing.lines == 1);
    CHECK(missing.text.find("/nonexistent/radeon_icd.json") != std::string::npos);
}

TEST_CASE("gpu cost: lavapipe runs in the same process after RADV, from a clean environment",
          "[gpu_cost]") {
    auto meter = meter_or_skip();
    if (!meter) return;
    Collected diag;
    const char* before = std::getenv("RADV_FORCE_FAMILY");
    const std::string family_before = before ? before : "(unset)";
    const auto v = parse_variant("dist=phong,method=point,light=polygon", {});
    REQUIRE(v);
    REQUIRE(meter->measure(*v, diag.consumer()));
    const char* after = std::getenv("RADV_FORCE_FAMILY");
    CHECK((after ? after : "(unset)") == family_before);
    // Validation still runs on the loader's first device, lavapipe, and agrees with the
    // CPU mirror of the same variant.
    CaseSet cases;
    cases.cases.push_back(
        test::polygon_case("square", {{-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}}, {0, 0, 1},
                           glm::normalize(glm::dvec3(0.3, 0, 1)), Distribution::Phong, 50));
    EvalOptions vulkan, cpu;
    cpu.backend = Backend::Cpu;
    auto on_gpu = Evaluator::create(vulkan, diag.consumer());
    auto on_cpu = Evaluator::create(cpu, diag.consumer());
    INFO(diag.text);
    REQUIRE(on_gpu);
    REQUIRE(on_cpu);
    CHECK(on_gpu->device_name().find("llvmpipe") != std::string::npos);
    const auto a = on_gpu->run(*v, cases, diag.consumer());
    const auto b = on_cpu->run(*v, cases, diag.consumer());
    INFO(diag.text);
    REQUIRE(a);
    REQUIRE(b);
    REQUIRE(a->results.size() == 1);
    REQUIRE(b->results.size() == 1);
    REQUIRE(a->results[0].specular);
    REQUIRE(b->results[0].specular);
    CHECK(*a->results[0].specular > 0);
    CHECK(*a->results[0].specular == Approx(*b->results[0].specular).epsilon(kMirrorAgreement));
}

TEST_CASE("gpu cost: the gpu object round-trips through the quality data", "[gpu_cost]") {
    GpuCost g;
    g.family = "navi21";
    g.mesa = "22.3.6";
    g.wave = 64;
    g.instructions = 914;
    g.vgprs = 96;
    g.spilled_vgprs = 3;
    g.scratch_bytes = 27648;
    g.latency = 12345;
    g.inverse_throughput = 1593;
    g.inverse_throughput_unrolled = 977;
    g.cost = 1593;
    g.waves_per_simd = 10;
    g.ratio_to_point = 1593.0 / 498.0;
    QualityData data;
    data.reports = {"docs/report-ggx/report.json"};
    MeasuredVariant with, without;
    with.variant = "dist=ggx,method=ltc,light=polygon";
    with.rel_l2 = {{"diffuse", 1e-7}, {"specular", 0.015}};
    with.error_rel_l2 = 0.015;
    with.x86_instructions = 3000;
    with.ratio_to_point = 2.5;
    with.cases = 100;
    with.report = data.reports.front();
    with.gpu = g;
    without = with;
    without.variant = "dist=ggx,method=point,light=polygon";
    without.gpu.reset();
    data.variants = {with, without};
    Collected diag;
    const std::string text = format_quality(data);
    const auto back = parse_quality(text, "measured.json", diag.consumer());
    INFO(diag.text);
    INFO(text);
    REQUIRE(back);
    REQUIRE(back->variants.size() == 2);
    REQUIRE(back->variants[0].gpu);
    CHECK(*back->variants[0].gpu == g);
    CHECK_FALSE(back->variants[1].gpu);
    CHECK(format_quality(*back) == text);

    // A malformed gpu object is an error that names the field.
    auto doc = nlohmann::json::parse(text);
    doc["variants"][0]["gpu"]["cost"] = -1;
    Collected bad;
    CHECK_FALSE(parse_quality(doc.dump(), "bad.json", bad.consumer()));
    INFO(bad.text);
    CHECK(bad.text.find("cost") != std::string::npos);
}

TEST_CASE("gpu cost in a report: the front, the plots and the tables follow it", "[gpu_cost]") {
    // Two rows of one distribution and shape, equally wrong: the cheaper on lavapipe is
    // the dearer on the GPU.
    auto row = [](const std::string& name, double time_ratio, uint64_t cost, double gpu_ratio) {
        ReportRow r;
        r.variant = *parse_variant(name, {});
        r.name = name;
        r.cases = 3;
        r.ratio = time_ratio;
        QuantityScore s;
        s.quantity = "specular";
        s.n = 3;
        s.rel_l2 = 1e-3;
        r.scores = {s};
        GpuCost g;
        g.family = "navi21";
        g.wave = 64;
        g.vgprs = 96;
        g.waves_per_simd = 10;
        g.inverse_throughput = g.cost = cost;
        g.ratio_to_point = gpu_ratio;
        r.gpu = g;
        return r;
    };
    Report r;
    r.pattern = "dist=ggx";
    r.gpu_device = "RADV navi21 (null device), Mesa 22.3.6";
    r.rows = {
        row("dist=ggx,method=ltc,light=polygon", 2.0, 5000, 10.0),
        row("dist=ggx,method=exact,light=polygon,nodes=2,precision=fp32,radial=2", 5.0, 1500, 3.0)};
    REQUIRE(r.by_gpu_cost());
    mark_pareto(r.rows);
    CHECK_FALSE(r.rows[0].pareto);
    CHECK(r.rows[1].pareto);
    const auto pics = report_pictures(r);
    std::vector<std::string> names;
    for (const auto& p : pics) names.push_back(p.first);
    CHECK(names == std::vector<std::string>{"report.svg", "report_time.svg", "report_x86.svg"});
    CHECK(pics[0].second.find("GPU cost / point light") != std::string::npos);
    CHECK(pics[1].second.find("lavapipe") != std::string::npos);
    const std::string md = report_markdown(r);
    CHECK(md.find("| GPU cost | × point | VGPRs | waves |") != std::string::npos);
    CHECK(md.find("| 5000 | 10.00 | 96 | 10 |") != std::string::npos);
    const auto doc = nlohmann::json::parse(report_json(r));
    std::string why;
    const auto back = parse_gpu_cost(doc["rows"][1]["gpu"], why);
    INFO(why);
    REQUIRE(back);
    CHECK(*back == *r.rows[1].gpu);

    // Without a GPU cost in every row, the time ratio decides and report.svg plots it.
    r.rows[1].gpu.reset();
    CHECK_FALSE(r.by_gpu_cost());
    mark_pareto(r.rows);
    CHECK(r.rows[0].pareto);
    CHECK_FALSE(r.rows[1].pareto);
    const auto time_only = report_pictures(r);
    REQUIRE(time_only.size() == 2);
    CHECK(time_only[0].second.find("lavapipe") != std::string::npos);
    CHECK(report_markdown(r).find("| – | – | – | – |") != std::string::npos);
}

TEST_CASE("the recommended row: cheapest within 2e-2 at the default shape and fp32, ringed",
          "[gpu_cost]") {
    auto row = [](const std::string& name, double error, double gpu_ratio) {
        ReportRow r;
        const auto v = parse_variant(name, {});
        INFO(name);
        REQUIRE(v);
        r.variant = *v;
        r.name = name;
        r.cases = 3;
        r.ratio = gpu_ratio;
        QuantityScore s;
        s.quantity = "specular";
        s.n = 3;
        s.rel_l2 = error;
        r.scores = {s};
        GpuCost g;
        g.family = "navi21";
        g.wave = 64;
        g.inverse_throughput = g.cost = static_cast<uint64_t>(100 * gpu_ratio);
        g.ratio_to_point = gpu_ratio;
        r.gpu = g;
        return r;
    };
    Report r;
    r.pattern = "phong polygons and ggx spheres";
    r.gpu_device = "RADV navi21 (null device), Mesa 22.3.6";
    r.rows = {
        row("dist=phong,method=point,light=polygon", 0.5, 1.0),     // too wrong
        row("dist=phong,method=lorentz,light=polygon", 0.015, 2.0),  // the cheapest within 2e-2
        row("dist=phong,method=lorentz,light=polygon,verts=4", 0.015, 1.5),  // another shape
        row("dist=phong,method=exact,light=polygon", 1e-7, 1.2),     // fp64: never
        row("dist=phong,method=pearson,light=polygon", 0.01, 50.0),
        // No sphere row is within 2e-2: the most accurate one.
        row("dist=ggx,method=ltc,light=sphere", 0.04, 3.0),
        row("dist=ggx,method=point,light=sphere", 0.3, 1.0)};
    mark_recommended(r.rows);
    std::vector<bool> got;
    for (const auto& x : r.rows) got.push_back(x.recommended);
    CHECK(got == std::vector<bool>{false, true, false, false, false, true, false});
    const auto pics = report_pictures(r);
    REQUIRE(!pics.empty());
    CHECK(pics[0].second.find("recommended (error &lt;= 2e-2, fp32)") != std::string::npos);
    CHECK(pics[0].second.find("r=\"8\" fill=\"none\"") != std::string::npos);
    CHECK(report_markdown(r).find(" ★ |") != std::string::npos);
    CHECK(nlohmann::json::parse(report_json(r))["rows"][1]["recommended"] == true);
}

TEST_CASE("a report read back from its JSON writes the same JSON, and says where it is broken",
          "[gpu_cost]") {
    ReportRow a;
    a.variant = *parse_variant("dist=ggx,method=ltc,light=polygon", {});
    a.name = canonical_name(a.variant);
    a.baseline = "dist=ggx,method=point,light=polygon";
    a.cases = 7;
    a.spirv_instructions = 900;
    a.x86_instructions = 8000;
    a.table_bytes = 131072;
    a.texture_fetches = 2;
    a.ns_per_case = 190.5;
    a.ratio = 2.46;
    for (const char* q : {"diffuse", "specular", "ndf"}) {
        QuantityScore s;
        s.quantity = q;
        s.n = 7;
        s.median = 1e-3;
        s.p95 = 0.2;
        s.max = 0.5;
        s.rel_l2 = 0.012;
        s.worst = "case-3";
        a.scores.push_back(s);
    }
    GpuCost g;
    g.family = "navi21";
    g.mesa = "22.3.6";
    g.wave = 64;
    g.instructions = 2700;
    g.vgprs = 96;
    g.inverse_throughput = g.cost = 986;
    g.ratio_to_point = 1.98;
    a.gpu = g;
    Report r;
    r.pattern = "dist=ggx,light=polygon";
    r.case_files = {"typical.cases.json"};
    r.device = "llvmpipe";
    r.gpu_device = "RADV navi21 (null device), Mesa 22.3.6";
    r.seconds = 12;
    r.rows = {a};
    mark_pareto(r.rows);
    mark_recommended(r.rows);
    const std::string json = report_json(r);
    Collected diag;
    const auto back = read_report_json(json, "r.json", diag.consumer());
    INFO(diag.text);
    REQUIRE(back);
    CHECK(report_json(*back) == json);
    CHECK(report_markdown(*back) == report_markdown(r));
    CHECK(back->rows[0].recommended);

    auto doc = nlohmann::json::parse(json);
    doc["rows"][0].erase("cases");
    Collected broken;
    CHECK_FALSE(read_report_json(doc.dump(), "r.json", broken.consumer()));
    INFO(broken.text);
    CHECK(broken.text.find("r.json: row 0") != std::string::npos);
    CHECK(broken.text.find("cases") != std::string::npos);
    Collected not_report;
    CHECK_FALSE(read_report_json("{\"format\": \"x\"}", "x.json", not_report.consumer()));
    CHECK(not_report.text.find("x.json: field 'format'") != std::string::npos);
}
