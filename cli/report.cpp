#include "report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "arealight/atomic_file.hpp"
#include "arealight/case_io.hpp"
#include "arealight/evaluator.hpp"
#include "arealight/machine_code.hpp"
#include "arealight/report.hpp"
#include "exit_code.hpp"
#include "print_diagnostic.hpp"
#include "progress.hpp"

namespace arealight::cli {

namespace {

// Reads and concatenates case files; ids must be unique across them.
std::optional<CaseSet> read_case_files(const std::vector<std::string>& paths) {
    CaseSet all;
    std::map<std::string, std::string> seen;  // id -> file
    for (const auto& path : paths) {
        auto set = read_cases(path, print_diagnostic);
        if (!set) return std::nullopt;
        for (auto& c : set->cases) {
            auto [it, fresh] = seen.emplace(c.id, path);
            if (!fresh) {
                print_diagnostic(
                    {Severity::Error, path, 0,
                     fmt::format("{}: case '{}': id already used in {}", path, c.id, it->second)});
                return std::nullopt;
            }
            all.cases.push_back(std::move(c));
        }
    }
    return all;
}

}  // namespace

int run_report(const ReportArgs& a, bool sweep) {
    auto cases = read_case_files(a.cases);
    if (!cases) return kBadInput;
    std::vector<Variant> matching;
    for (const auto& v : enumerate_variants())
        if (variant_matches(v, a.pattern)) matching.push_back(v);
    if (matching.empty()) {
        print_diagnostic(
            {Severity::Error, "", 0,
             fmt::format("no variant matches '{}' (arealight variants lists them)", a.pattern)});
        return kBadInput;
    }
    ReportOptions opt;
    opt.pattern = a.pattern;
    opt.repeats = a.repeats;
    opt.dispatch_seconds = a.dispatch_ms * 1e-3;
    opt.threads = a.threads;
    opt.gpu->family = a.gpu_family;
    opt.gpu->cache_dir = a.gpu_cache;
    if (sweep) {
        auto bad = [&](const std::string& m) {
            print_diagnostic({Severity::Error, "", 0, "sweep: " + m});
            return kBadInput;
        };
        const auto axis = parse_sweep_axis(a.axis);
        if (!axis) return bad(fmt::format("--axis '{}': expected param or view", a.axis));
        opt.axis = *axis;
        std::set<Distribution> dists;
        for (const auto& v : matching) dists.insert(v.dist);
        std::string names;
        for (auto d : dists) names += std::string(names.empty() ? "" : ", ") + to_string(d);
        // The range a value must lie in, and what it is called.
        double lo = 0, hi = 1;
        std::string what = "cos θ_v";
        if (opt.axis == SweepAxis::Param) {
            if (dists.size() > 1)
                return bad(fmt::format(
                    "--axis param: the variants matching '{}' span several distributions ({}), "
                    "whose parameters differ; add dist=... to the pattern, or sweep --axis view",
                    a.pattern, names));
            const auto& p = sweep_parameter(*dists.begin());
            lo = p.min;
            hi = p.max;
            what = p.field;
            if (!a.exponents.empty() && p.field != "exponent")
                return bad(
                    fmt::format("--exponent: {} has no exponent; its parameter is {} (--value)",
                                names, p.field));
        } else if (!a.exponents.empty()) {
            return bad("--exponent sweeps the exponent: it needs --axis param");
        }
        opt.values = a.values;
        opt.values.insert(opt.values.end(), a.exponents.begin(), a.exponents.end());
        for (double x : opt.values) {
            const bool ok = opt.axis == SweepAxis::View ? x > 0 && x <= 1 : x >= lo && x <= hi;
            if (!ok || !std::isfinite(x))
                return bad(fmt::format("value {:g}: {} must lie in {}{:g}, {:g}]", x, what,
                                       opt.axis == SweepAxis::View ? "(" : "[", lo, hi));
        }
    }
    if (!a.refs.empty()) {
        ResultSet ref;
        for (const auto& path : a.refs) {
            auto r = read_results(path, print_diagnostic);
            if (!r) return kBadInput;
            ref.results.insert(ref.results.end(), r->results.begin(), r->results.end());
        }
        // Every case a matching variant will run needs its oracle value.
        std::set<std::string> have;
        for (const auto& r : ref.results) have.insert(r.id);
        for (const auto& c : cases->cases) {
            const bool used = std::any_of(matching.begin(), matching.end(),
                                          [&](const Variant& v) { return case_applies(v, c); });
            if (used && !have.count(c.id)) {
                print_diagnostic({Severity::Error, "", 0,
                                  fmt::format("case '{}' has no value in the --ref files", c.id)});
                return kBadInput;
            }
        }
        opt.reference = ref;
    }
    // Before any Vulkan call: Mesa reads its cache location once per process.
    // Declared before the evaluator, so that it outlives every Vulkan object.
    PrivateShaderCache cache;
    opt.shader_cache_dir = cache.path();
    EvalOptions eo;
    auto ev = Evaluator::create(eo, print_diagnostic);
    if (!ev) return kRuntime;
    std::map<std::string, std::unique_ptr<ProgressPrinter>> printers;
    auto progress = [&](const std::string& phase, std::size_t done, std::size_t total) {
        auto& p = printers[phase];
        // compile and time count variants; the oracle phases ("reference ...") cases.
        if (!p)
            p = std::make_unique<ProgressPrinter>(
                phase, phase.rfind("reference", 0) == 0 ? "cases" : "variants");
        (*p)(done, total);
    };
    auto report = run_report(*ev, *cases, opt, print_diagnostic, progress);
    if (!report) return kRuntime;
    report->case_files = a.cases;
    report->device = ev->device_name();
    const std::string stem = sweep ? "sweep" : "report";
    std::vector<std::pair<std::string, std::string>> files = {
        {stem + ".json", report_json(*report)}, {stem + ".md", report_markdown(*report)}};
    for (auto& pic : report_pictures(*report)) files.push_back(std::move(pic));
    std::error_code ec;
    std::filesystem::create_directories(a.out_dir, ec);
    for (const auto& [name, text] : files) {
        if (!write_file_atomic(a.out_dir + "/" + name, text, print_diagnostic)) return kRuntime;
    }
    fmt::print(stderr, "{}: {} rows in {:.0f} s; wrote", stem, report->rows.size(),
               report->seconds);
    for (const auto& f : files) fmt::print(stderr, " {}/{}", a.out_dir, f.first);
    fmt::print(stderr, "\n");
    return kOk;
}

}  // namespace arealight::cli
