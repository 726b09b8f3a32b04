#include "arealight/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "arealight/compiler.hpp"
#include "arealight/machine_code.hpp"
#include "arealight/reference.hpp"
#include "arealight/svg_plot.hpp"

namespace arealight {
namespace {

// Cases per timed dispatch at most: 2^18 cases are 54 MB of packed input.
constexpr std::size_t kMaxDispatchCases = 1 << 18;

double elapsed_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The point-light variant of the same shape: same cases, the cheapest shader.
Variant baseline_of(const Variant& v) {
    Variant b;
    b.dist = v.dist;
    b.light = v.light;
    b.method = Method::Point;
    b.sided = v.sided;
    b.verts = v.verts;
    return b;
}

double median(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    return x.empty() ? NAN : x[x.size() / 2];
}

const QuantityScore* find_score(const ReportRow& r, const std::string& q) {
    for (const auto& s : r.scores)
        if (s.quantity == q) return &s;
    return nullptr;
}

// Rows on the error-cost front: no other row of the same exponent and shape (so
// the same cases) is at most as costly and at most as wrong, and better in one.
void mark_pareto(std::vector<ReportRow>& rows) {
    for (auto& a : rows) {
        a.pareto = std::isfinite(a.error()) && std::isfinite(a.ratio);
        if (!a.pareto) continue;
        for (const auto& b : rows) {
            if (&a == &b || b.exponent != a.exponent || b.variant.sided != a.variant.sided ||
                b.variant.verts != a.variant.verts)
                continue;
            if (!std::isfinite(b.error()) || !std::isfinite(b.ratio)) continue;
            if (b.ratio <= a.ratio && b.error() <= a.error() &&
                (b.ratio < a.ratio || b.error() < a.error())) {
                a.pareto = false;
                break;
            }
        }
    }
}

struct Packed {
    std::vector<float> data;
    std::size_t count = 0;
};

Packed pack_repeated(const std::vector<const Case*>& todo, std::size_t copies) {
    std::vector<const Case*> reps;
    reps.reserve(todo.size() * copies);
    for (std::size_t k = 0; k < copies; ++k) reps.insert(reps.end(), todo.begin(), todo.end());
    return {pack_cases(reps), reps.size()};
}

std::string g3(double x) {
    if (!std::isfinite(x)) return "–";
    return fmt::format("{:.2e}", x);
}

std::string method_label(const Variant& v) {
    std::string s = to_string(v.method);
    if (is_peak_method(v.method)) {
        if (v.fit == Fit::Paper) s += ",paper";
        if (v.specular == SpecularForm::Sg) s += ",sg";
    }
    if (v.method == Method::Exact && v.precision == Precision::Fp32) s += ",fp32";
    return s;
}

// The method label plus the quadrature size where it is not the default.
std::string series_label(const Variant& v) {
    std::string s = method_label(v);
    if (v.method == Method::Exact && v.nodes != Variant{}.nodes) s += fmt::format(",{}", v.nodes);
    return s;
}

}  // namespace

double ReportRow::error() const {
    double e = -1;
    for (const char* q : {"specular", "moment"}) {
        for (const auto& s : scores)
            if (s.quantity == q && std::isfinite(s.rel_l2)) e = std::max(e, s.rel_l2);
    }
    return e < 0 ? NAN : e;
}

std::optional<Report> run_report(Evaluator& ev, const CaseSet& cases, const ReportOptions& opt,
                                 const DiagnosticConsumer& diag, const PhaseProgress& progress) {
    const auto t_start = std::chrono::steady_clock::now();
    auto fail = [&](const std::string& m) -> std::optional<Report> {
        if (diag) diag({Severity::Error, "", 0, "report: " + m});
        return std::nullopt;
    };
    // Matching variants plus the baselines they need, in enumeration order.
    std::set<std::string> wanted;
    for (const auto& v : enumerate_variants()) {
        if (!variant_matches(v, opt.pattern)) continue;
        wanted.insert(canonical_name(v));
        wanted.insert(canonical_name(baseline_of(v)));
    }
    std::vector<Variant> variants;
    for (const auto& v : enumerate_variants())
        if (wanted.count(canonical_name(v))) variants.push_back(v);
    if (variants.empty()) return fail(fmt::format("no variant matches '{}'", opt.pattern));

    Report report;
    report.pattern = opt.pattern;

    // Deterministic counts, once per variant.
    std::vector<std::size_t> spirv(variants.size(), 0), x86(variants.size(), 0);
    for (std::size_t k = 0; k < variants.size(); ++k) {
        auto words = build_spirv(variants[k], true, diag);
        if (!words) return std::nullopt;
        spirv[k] = spirv_instruction_count(*words);
        if (!opt.shader_cache_dir.empty()) {
            auto code = lavapipe_machine_code(variants[k], opt.shader_cache_dir, diag);
            if (!code) return std::nullopt;
            x86[k] = code->instructions;
        }
        if (progress) progress("compile", k + 1, variants.size());
    }

    std::vector<double> exponents = opt.exponents;
    if (exponents.empty()) exponents.push_back(0.0);
    std::size_t step = 0;
    const std::size_t steps = exponents.size() * variants.size();
    for (double N : exponents) {
        CaseSet set;
        for (const auto& c : cases.cases) {
            bool used = false;
            for (const auto& v : variants) used = used || case_applies(v, c);
            if (!used) continue;
            set.cases.push_back(c);
            if (N > 0) set.cases.back().material.exponent = N;
        }
        if (set.cases.empty()) return fail("no case applies to any matching variant");
        ResultSet ref;
        if (N == 0 && opt.reference) {
            ref = *opt.reference;
        } else {
            ReferenceOptions ro;
            ro.threads = std::max(1u, opt.threads);
            ref = reference_all(set, ro, [&](std::size_t d, std::size_t t) {
                if (progress)
                    progress(N > 0 ? fmt::format("reference N={:g}", N) : "reference", d, t);
            });
        }

        // Each variant timed side by side with its baseline, interleaved, on the
        // same cases repeated until a dispatch lasts opt.dispatch_seconds.
        std::map<std::string, Packed> baseline_packs;
        for (std::size_t k = 0; k < variants.size(); ++k) {
            const Variant& v = variants[k];
            std::vector<const Case*> todo;
            for (const auto& c : set.cases)
                if (case_applies(v, c)) todo.push_back(&c);
            if (todo.empty()) return fail("no case applies to " + canonical_name(v));
            auto out = ev.run(v, set, diag);
            if (!out) return std::nullopt;
            ReportRow row;
            row.variant = v;
            row.name = canonical_name(v);
            row.exponent = N;
            row.cases = todo.size();
            row.spirv_instructions = spirv[k];
            row.x86_instructions = x86[k];
            row.scores = score_results(ref, *out, opt.floor);

            const Variant base = baseline_of(v);
            row.baseline = canonical_name(base);
            // Copies of the cases per dispatch for u, from a timed run of one copy.
            const Packed single = pack_repeated(todo, 1);
            auto copies_for = [&](const Variant& u) -> std::optional<std::size_t> {
                std::vector<float> res;
                double s = 0;
                // The first dispatch also compiles (or loads) the pipeline: time the second.
                for (int i = 0; i < 2; ++i)
                    if (!ev.run_packed(u, single.data, single.count, res, diag, &s))
                        return std::nullopt;
                const double want = opt.dispatch_seconds / std::max(s, 1e-9);
                return std::clamp<std::size_t>(
                    static_cast<std::size_t>(std::ceil(want)), 1,
                    std::max<std::size_t>(1, kMaxDispatchCases / todo.size()));
            };
            auto copies = copies_for(v);
            if (!copies) return std::nullopt;
            const Packed pack = pack_repeated(todo, *copies);
            const bool is_base = v == base;
            if (!is_base && !baseline_packs.count(row.baseline)) {
                auto bcopies = copies_for(base);
                if (!bcopies) return std::nullopt;
                baseline_packs[row.baseline] = pack_repeated(todo, *bcopies);
            }
            std::vector<double> tv, tb;
            std::vector<float> res;
            for (int rep = 0; rep < std::max(1, opt.repeats); ++rep) {
                double s = 0;
                if (!ev.run_packed(v, pack.data, pack.count, res, diag, &s)) return std::nullopt;
                tv.push_back(s / pack.count * 1e9);
                if (!is_base) {
                    const Packed& bp = baseline_packs[row.baseline];
                    if (!ev.run_packed(base, bp.data, bp.count, res, diag, &s)) return std::nullopt;
                    tb.push_back(s / bp.count * 1e9);
                }
            }
            row.ns_per_case = median(tv);
            // The median of each repeat's own ratio: a slow spell of the machine hits
            // both members of a pair alike.
            std::vector<double> ratios;
            for (std::size_t i = 0; i < tb.size(); ++i) ratios.push_back(tv[i] / tb[i]);
            row.ratio = is_base ? 1.0 : median(ratios);
            report.rows.push_back(std::move(row));
            if (progress) progress("time", ++step, steps);
        }
    }
    mark_pareto(report.rows);
    report.seconds = elapsed_since(t_start);
    return report;
}

std::string report_json(const Report& r) {
    using nlohmann::ordered_json;
    ordered_json j;
    j["format"] = "arealight-report/1";
    j["pattern"] = r.pattern;
    j["case_files"] = r.case_files;
    j["device"] = r.device;
    j["seconds"] = r.seconds;
    ordered_json rows = ordered_json::array();
    for (const auto& row : r.rows) {
        ordered_json o;
        o["variant"] = row.name;
        o["baseline"] = row.baseline;
        if (row.exponent > 0) o["exponent"] = row.exponent;
        o["cases"] = row.cases;
        o["spirv_instructions"] = row.spirv_instructions;
        o["x86_instructions"] = row.x86_instructions;
        o["ns_per_case"] = row.ns_per_case;
        o["ratio_to_point"] = row.ratio;
        o["pareto"] = row.pareto;
        ordered_json e;
        for (const auto& s : row.scores) {
            ordered_json q;
            q["n"] = s.n;
            q["missing"] = s.missing;
            q["bad"] = s.bad;
            auto num = [](double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(); };
            q["median"] = num(s.median);
            q["p95"] = num(s.p95);
            q["max"] = num(s.max);
            q["rel_l2"] = num(s.rel_l2);
            q["worst"] = s.worst;
            e[s.quantity] = q;
        }
        o["error"] = e;
        rows.push_back(o);
    }
    j["rows"] = rows;
    return j.dump(1) + "\n";
}

namespace {

std::string score_cell(const ReportRow& row, const std::string& q) {
    const QuantityScore* s = find_score(row, q);
    if (!s) return "–";
    std::string cell =
        fmt::format("{} / {} / {} / {}", g3(s->median), g3(s->p95), g3(s->max), g3(s->rel_l2));
    if (s->missing || s->bad) cell += fmt::format(" ({} missing, {} bad)", s->missing, s->bad);
    return cell;
}

std::string table(const std::vector<const ReportRow*>& rows, bool sweep) {
    std::string t;
    if (sweep) {
        t += "| variant | N | cases | ns/case | × point | specular median / p95 / max / relL2 "
             "| moment median / p95 / max / relL2 |\n";
        t += "|---|---:|---:|---:|---:|---|---|\n";
    } else {
        t += "| variant | cases | SPIR-V | x86-64 | ns/case | × point | diffuse relL2 | specular "
             "median / p95 / max / relL2 | moment median / p95 / max / relL2 | front |\n";
        t += "|---|---:|---:|---:|---:|---:|---:|---|---|:---:|\n";
    }
    for (const ReportRow* r : rows) {
        if (sweep) {
            t += fmt::format("| `{}` | {:g} | {} | {:.1f} | {:.2f} | {} | {} |\n", r->name,
                             r->exponent, r->cases, r->ns_per_case, r->ratio,
                             score_cell(*r, "specular"), score_cell(*r, "moment"));
        } else {
            const QuantityScore* d = find_score(*r, "diffuse");
            t += fmt::format("| `{}` | {} | {} | {} | {:.1f} | {:.2f} | {} | {} | {} | {} |\n",
                             r->name, r->cases, r->spirv_instructions, r->x86_instructions,
                             r->ns_per_case, r->ratio, d ? g3(d->rel_l2) : "–",
                             score_cell(*r, "specular"), score_cell(*r, "moment"),
                             r->pareto ? "●" : "");
        }
    }
    return t;
}

}  // namespace

std::string report_markdown(const Report& r) {
    const bool sweep = !r.rows.empty() && r.rows.front().exponent > 0;
    std::string files;
    for (const auto& f : r.case_files) files += (files.empty() ? "" : ", ") + ("`" + f + "`");
    std::string t = fmt::format(
        "<!-- generated by arealight {}; do not edit -->\n"
        "# arealight {}: `{}`\n\n"
        "Cases: {}. Device: {}. {} rows in {:.0f} s.\n\n"
        "Time: median of repeated dispatches on the device, per case; × point is the ratio "
        "to the point-light variant of the same shape (sided, verts), timed interleaved with "
        "it. Error: |x − ref| / max(ref, 1e-3) against `arealight reference` (median, p95, "
        "max) and "
        "relative L2, the metric of `shared/tools/score`. front: on the error–cost Pareto "
        "front (error = the larger relL2 of specular and moment).\n\n",
        sweep ? "sweep" : "report", sweep ? "sweep" : "report", r.pattern, files, r.device,
        r.rows.size(), r.seconds);
    std::vector<const ReportRow*> all, shape;
    const Variant d;
    for (const auto& row : r.rows) {
        all.push_back(&row);
        if (row.variant.sided == d.sided && row.variant.verts == d.verts) shape.push_back(&row);
    }
    if (!sweep && shape.size() != all.size() && !shape.empty()) {
        t +=
            "## Default shape (sided=any, verts=8)\n\n" + table(shape, false) + "\n## All rows\n\n";
    }
    t += table(all, sweep);
    return t;
}

std::vector<std::pair<std::string, std::string>> report_pictures(const Report& r) {
    std::vector<std::pair<std::string, std::string>> out;
    const bool sweep = !r.rows.empty() && r.rows.front().exponent > 0;
    // One colour per method label, in order of first appearance.
    std::vector<std::string> labels;
    for (const auto& row : r.rows) {
        const std::string l = method_label(row.variant);
        if (std::find(labels.begin(), labels.end(), l) == labels.end()) labels.push_back(l);
    }
    auto color = [&](const std::string& l) {
        return plot_color(std::find(labels.begin(), labels.end(), l) - labels.begin());
    };
    if (!sweep) {
        // One shape, so that every point is measured on the same cases: the default
        // one when the run has it.
        const Variant d;
        std::vector<const ReportRow*> rows;
        for (const auto& row : r.rows)
            if (row.variant.sided == d.sided && row.variant.verts == d.verts) rows.push_back(&row);
        std::string shape = " (sided=any, verts=8)";
        if (rows.empty()) {
            for (const auto& row : r.rows) rows.push_back(&row);
            shape.clear();
        }
        Plot p;
        p.title = "Error against cost: " + r.pattern + shape;
        p.x_label = "time per case / point light (lavapipe, median)";
        p.y_label = "relative L2 error (max of specular, moment)";
        for (const auto& l : labels) {
            PlotSeries s;
            s.name = l;
            s.color = color(l);
            for (const ReportRow* row : rows)
                if (method_label(row->variant) == l)
                    s.points.push_back({row->ratio, row->error(), row->name});
            if (!s.points.empty()) p.series.push_back(s);
        }
        for (const ReportRow* row : rows)
            if (row->pareto) p.front.push_back({row->ratio, row->error(), row->name});
        std::sort(p.front.begin(), p.front.end(),
                  [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
        p.front_name = "Pareto front";
        out.emplace_back("report.svg", svg_plot(p));
        // The same against the deterministic cost: lavapipe's x86-64 instruction count.
        Plot q = p;
        q.title = "Error against code size: " + r.pattern + shape;
        q.x_label = "x86-64 instructions of the lavapipe shader";
        q.front.clear();
        for (auto& s : q.series) {
            s.points.clear();
            for (const ReportRow* row : rows)
                if (method_label(row->variant) == s.name && row->x86_instructions > 0)
                    s.points.push_back({double(row->x86_instructions), row->error(), row->name});
        }
        out.emplace_back("report_x86.svg", svg_plot(q));
        return out;
    }
    for (int which = 0; which < 2; ++which) {
        Plot p;
        p.title = which == 0 ? "Cost against N: " + r.pattern : "Error against N: " + r.pattern;
        p.x_label = "exponent N";
        p.y_label = which == 0 ? "time per case / point light"
                               : "relative L2 error (max of specular, moment)";
        std::vector<std::string> names;
        for (const auto& row : r.rows)
            if (std::find(names.begin(), names.end(), row.name) == names.end())
                names.push_back(row.name);
        for (std::size_t k = 0; k < names.size(); ++k) {
            PlotSeries s;
            for (const auto& row : r.rows)
                if (row.name == names[k]) s.name = series_label(row.variant);
            s.color = plot_color(k);
            s.line = true;
            for (const auto& row : r.rows)
                if (row.name == names[k])
                    s.points.push_back({row.exponent, which == 0 ? row.ratio : row.error(), ""});
            p.series.push_back(s);
        }
        out.emplace_back(which == 0 ? "sweep_time.svg" : "sweep_error.svg", svg_plot(p));
    }
    return out;
}

}  // namespace arealight
