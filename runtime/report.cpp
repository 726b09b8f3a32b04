#include "arealight/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "arealight/compiler.hpp"
#include "arealight/gpu_cost_json.hpp"
#include "arealight/machine_code.hpp"
#include "arealight/reference.hpp"
#include "arealight/scene_select.hpp"
#include "arealight/svg_plot.hpp"

namespace arealight {

const char* to_string(SweepAxis a) {
    switch (a) {
        case SweepAxis::Param:
            return "param";
        case SweepAxis::View:
            return "view";
        case SweepAxis::None:
            break;
    }
    return "none";
}

std::optional<SweepAxis> parse_sweep_axis(const std::string& s) {
    if (s == "param") return SweepAxis::Param;
    if (s == "view") return SweepAxis::View;
    return std::nullopt;
}

const std::vector<SweepParameter>& sweep_parameters() {
    // 10^0, 10^0.5, ..., 10^5: the exponent range of CONTRACT.md section 2.
    static const std::vector<double> exponents = [] {
        std::vector<double> e;
        for (int k = 0; k <= 10; ++k) e.push_back(std::pow(10.0, 0.5 * k));
        return e;
    }();
    // 1-2-5 per decade over the alpha range of CONTRACT.md section 2.
    static const std::vector<double> alphas = {0.001, 0.002, 0.005, 0.01, 0.02,
                                               0.05,  0.1,   0.2,   0.5,  1.0};
    static const std::vector<SweepParameter> table = {
        {Distribution::Phong, "exponent", "N", exponents, 1.0, 100000.0},
        {Distribution::Blinn, "exponent", "N", exponents, 1.0, 100000.0},
        {Distribution::Beckmann, "alpha", "α", alphas, 0.001, 1.0},
        {Distribution::Ggx, "alpha", "α", alphas, 0.001, 1.0},
    };
    return table;
}

const SweepParameter& sweep_parameter(Distribution d) {
    for (const auto& p : sweep_parameters())
        if (p.dist == d) return p;
    return sweep_parameters().front();  // unreachable: one row per distribution
}

const std::vector<double>& view_sweep_cosines() {
    static const std::vector<double> c = {1, 0.9, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05, 0.02, 0.01};
    return c;
}

Case sweep_case(const Case& c, SweepAxis axis, double value) {
    Case o = c;
    if (axis == SweepAxis::Param) {
        if (sweep_parameter(c.material.distribution).field == "alpha")
            o.material.alpha = value;
        else
            o.material.exponent = value;
    } else if (axis == SweepAxis::View) {
        auto dot = [](const Vec3& a, const Vec3& b) {
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        };
        auto unit = [&](const Vec3& a) {
            const double l = std::sqrt(dot(a, a));
            return l > 0 ? Vec3{a[0] / l, a[1] / l, a[2] / l} : a;
        };
        const Vec3 n = unit(c.n), v = unit(c.v);
        auto tangent = [&](const Vec3& w) {
            const double d = dot(w, n);
            return Vec3{w[0] - d * n[0], w[1] - d * n[1], w[2] - d * n[2]};
        };
        Vec3 t = tangent(v);
        if (dot(t, t) < 1e-24) {
            // v along n: the plane of n and v is any; take the axis least aligned with n.
            int k = 0;
            for (int i = 1; i < 3; ++i)
                if (std::abs(n[i]) < std::abs(n[k])) k = i;
            Vec3 e{0, 0, 0};
            e[k] = 1;
            t = tangent(e);
        }
        t = unit(t);
        const double cv = std::clamp(value, -1.0, 1.0), sv = std::sqrt(1 - cv * cv);
        for (int i = 0; i < 3; ++i) o.v[i] = cv * n[i] + sv * t[i];
    }
    return o;
}

const char* second_quantity(const Variant& v) {
    return is_microfacet(v.dist) ? "ndf" : "moment";
}

Variant baseline_of(const Variant& v) {
    Variant b;
    b.dist = v.dist;
    b.light = v.light;
    b.method = Method::Point;
    b.sided = v.sided;
    b.verts = v.verts;
    if (is_valid(b)) return b;
    b.sided = Variant{}.sided;
    b.verts = Variant{}.verts;
    return b;
}

namespace {

// Cases per timed dispatch at most: 2^18 cases are 54 MB of packed input.
constexpr std::size_t kMaxDispatchCases = 1 << 18;

double elapsed_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
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

bool has_gpu_ratio(const ReportRow& r) {
    return r.gpu && r.gpu->ratio_to_point > 0;
}

}  // namespace

void mark_pareto(std::vector<ReportRow>& rows) {
    const bool gpu = std::all_of(rows.begin(), rows.end(), has_gpu_ratio);
    auto cost = [gpu](const ReportRow& r) { return gpu ? r.gpu->ratio_to_point : r.ratio; };
    for (auto& a : rows) {
        a.pareto = std::isfinite(a.error()) && std::isfinite(cost(a));
        if (!a.pareto) continue;
        for (const auto& b : rows) {
            if (&a == &b || b.value != a.value || b.variant.dist != a.variant.dist ||
                b.variant.sided != a.variant.sided || b.variant.verts != a.variant.verts)
                continue;
            if (!std::isfinite(b.error()) || !std::isfinite(cost(b))) continue;
            if (cost(b) <= cost(a) && b.error() <= a.error() &&
                (cost(b) < cost(a) || b.error() < a.error())) {
                a.pareto = false;
                break;
            }
        }
    }
}

namespace {

// A sweep's parameter (its JSON key), symbol and axis label, from its axis and the
// distribution of its variants.
void set_sweep_labels(Report& report, Distribution dist) {
    if (report.axis == SweepAxis::Param) {
        const SweepParameter& p = sweep_parameter(dist);
        report.parameter = p.field;
        report.symbol = p.symbol;
        report.axis_label = p.field == "alpha" ? "roughness α" : "exponent N";
    } else if (report.axis == SweepAxis::View) {
        report.parameter = "cos_theta_v";
        report.symbol = "cos θ_v";
        report.axis_label = "cos θ_v (1: view along the normal, 0.01: grazing)";
    }
}

}  // namespace

void mark_recommended(std::vector<ReportRow>& rows) {
    const bool gpu = std::all_of(rows.begin(), rows.end(), has_gpu_ratio);
    auto cost = [gpu](const ReportRow& r) { return gpu ? r.gpu->ratio_to_point : r.ratio; };
    const Variant shape;
    auto allowed = [&](const ReportRow& r) {
        return r.variant.sided == shape.sided && r.variant.verts == shape.verts &&
               effective_precision(r.variant) != Precision::Fp64 && std::isfinite(r.error()) &&
               std::isfinite(cost(r));
    };
    for (auto& r : rows) r.recommended = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        ReportRow* best = nullptr;
        bool best_meets = false;
        for (auto& r : rows) {
            if (!allowed(r) || r.value != rows[i].value || r.variant.dist != rows[i].variant.dist ||
                r.variant.light != rows[i].variant.light)
                continue;
            const bool meets = r.error() <= kDefaultMaxError;
            const bool better = !best || (meets && !best_meets) ||
                                (meets == best_meets &&
                                 (meets ? cost(r) < cost(*best) : r.error() < best->error()));
            if (better) {
                best = &r;
                best_meets = meets;
            }
        }
        if (best) best->recommended = true;
    }
}

namespace {

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

// The method and the keys that set its cost class: peak fits, precision, and the
// radial rule of the microfacet quadrature (with the quadrature size too when
// `nodes`, where not the default); with the distribution first when a run spans
// several.
std::string method_label(const Variant& v, bool with_dist = false, bool nodes = false) {
    std::string s = with_dist ? std::string(to_string(v.dist)) + "," : std::string();
    s += to_string(v.method);
    if (is_peak_method(v.method)) {
        if (v.fit == Fit::Paper) s += ",paper";
        if (v.specular == SpecularForm::Sg) s += ",sg";
    }
    if (v.method == Method::Ltc) {
        if (v.horizon == Horizon::Proxy) s += ",proxy";
        if (v.edge == Edge::Poly) s += ",poly";
        if (v.precision == Precision::Fp16) s += ",fp16";
    }
    if (v.method == Method::Exact) {
        const Variant d;
        if (v.precision == Precision::Fp32) s += ",fp32";
        if (nodes && v.nodes != d.nodes) s += fmt::format(",nodes={}", v.nodes);
        if (is_microfacet(v.dist) && v.radial != d.radial) s += fmt::format(",radial={}", v.radial);
    }
    return s;
}

// The label of one variant's line in a sweep.
std::string series_label(const Variant& v, bool with_dist) {
    return method_label(v, with_dist, true);
}

bool several_distributions(const Report& r) {
    for (const auto& row : r.rows)
        if (row.variant.dist != r.rows.front().variant.dist) return true;
    return false;
}

// "moment", "ndf", or "moment or ndf" when the rows have both.
std::string second_quantity_name(const std::vector<const ReportRow*>& rows) {
    std::set<std::string> q;
    for (const ReportRow* r : rows) q.insert(second_quantity(r->variant));
    if (q.size() == 1) return *q.begin();
    return "moment or ndf";
}

}  // namespace

bool Report::by_gpu_cost() const {
    return !rows.empty() && std::all_of(rows.begin(), rows.end(), has_gpu_ratio);
}

double ReportRow::error() const {
    double e = -1;
    for (const char* q : {"specular", second_quantity(variant)}) {
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
    report.axis = opt.axis;
    std::vector<double> values = opt.values;
    if (opt.axis == SweepAxis::Param) {
        std::set<Distribution> dists;
        for (const auto& v : variants) dists.insert(v.dist);
        if (dists.size() > 1)
            return fail(fmt::format(
                "a parameter sweep needs the variants of one distribution; '{}' matches several",
                opt.pattern));
        set_sweep_labels(report, variants.front().dist);
        if (values.empty()) values = sweep_parameter(variants.front().dist).values;
    } else if (opt.axis == SweepAxis::View) {
        set_sweep_labels(report, variants.front().dist);
        if (values.empty()) values = view_sweep_cosines();
    } else {
        values = {0.0};  // a report: every case as given
    }

    // Deterministic counts, once per variant.
    std::vector<std::size_t> spirv(variants.size(), 0), x86(variants.size(), 0);
    std::vector<std::size_t> fetches(variants.size(), 0), table_bytes(variants.size(), 0);
    // Variants that compile to the same module (beckmann's and ggx's ltc differ only in
    // their tables) find it in lavapipe's cache already: count it once.
    std::map<std::vector<uint32_t>, std::size_t> x86_of;
    for (std::size_t k = 0; k < variants.size(); ++k) {
        auto words = build_spirv(variants[k], true, diag);
        if (!words) return std::nullopt;
        spirv[k] = spirv_instruction_count(*words);
        fetches[k] = spirv_texture_sample_count(*words);
        for (const Texture2D* t : variant_textures(variants[k])) table_bytes[k] += t->bytes();
        if (!opt.shader_cache_dir.empty()) {
            auto known = x86_of.find(*words);
            if (known != x86_of.end()) {
                x86[k] = known->second;
            } else {
                auto code = lavapipe_machine_code(variants[k], opt.shader_cache_dir, diag);
                if (!code) return std::nullopt;
                x86[k] = code->instructions;
                x86_of.emplace(*words, x86[k]);
            }
        }
        if (progress) progress("compile", k + 1, variants.size());
    }

    // GPU cost, once per variant; a variant RADV fails on goes without (warned).
    std::vector<std::optional<GpuCost>> gpu(variants.size());
    auto as_warning = [&](const Diagnostic& d) {
        if (!diag) return;
        Diagnostic w = d;
        if (w.severity == Severity::Error) w.severity = Severity::Warning;
        diag(w);
    };
    if (opt.gpu) {
        if (auto meter = GpuCostMeter::create(*opt.gpu, diag)) {
            report.gpu_device =
                fmt::format("RADV {} (null device), Mesa {}", meter->family(), meter->mesa());
            for (std::size_t k = 0; k < variants.size(); ++k) {
                gpu[k] = meter->measure(variants[k], as_warning);
                if (!gpu[k] && diag)
                    diag({Severity::Warning, "", 0,
                          "report: " + canonical_name(variants[k]) + " has no gpu cost"});
                if (progress) progress("gpu cost", k + 1, variants.size());
            }
        }
    }

    std::size_t step = 0;
    const std::size_t steps = values.size() * variants.size();
    for (double value : values) {
        CaseSet set;
        for (const auto& c : cases.cases) {
            bool used = false;
            for (const auto& v : variants) used = used || case_applies(v, c);
            if (!used) continue;
            set.cases.push_back(sweep_case(c, opt.axis, value));
        }
        if (set.cases.empty()) return fail("no case applies to any matching variant");
        ResultSet ref;
        if (opt.axis == SweepAxis::None && opt.reference) {
            ref = *opt.reference;
        } else {
            ReferenceOptions ro;
            ro.threads = std::max(1u, opt.threads);
            const std::string phase = opt.axis == SweepAxis::None
                                          ? std::string("reference")
                                          : fmt::format("reference {}={:g}", report.symbol, value);
            ref = reference_all(set, ro, [&](std::size_t d, std::size_t t) {
                if (progress) progress(phase, d, t);
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
            row.value = opt.axis == SweepAxis::None ? 0.0 : value;
            row.cases = todo.size();
            row.spirv_instructions = spirv[k];
            row.x86_instructions = x86[k];
            row.table_bytes = table_bytes[k];
            row.texture_fetches = fetches[k];
            row.gpu = gpu[k];
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
            // The baseline runs the variant's cases: one pack per baseline and case count
            // (a variant of a shape its point family lacks runs a subset of the baseline's).
            const std::string bkey = fmt::format("{} {}", row.baseline, todo.size());
            if (!is_base && !baseline_packs.count(bkey)) {
                auto bcopies = copies_for(base);
                if (!bcopies) return std::nullopt;
                baseline_packs[bkey] = pack_repeated(todo, *bcopies);
            }
            std::vector<double> tv, tb;
            std::vector<float> res;
            for (int rep = 0; rep < std::max(1, opt.repeats); ++rep) {
                double s = 0;
                if (!ev.run_packed(v, pack.data, pack.count, res, diag, &s)) return std::nullopt;
                tv.push_back(s / pack.count * 1e9);
                if (!is_base) {
                    const Packed& bp = baseline_packs[bkey];
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
    mark_recommended(report.rows);
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
    if (!r.gpu_device.empty()) j["gpu_device"] = r.gpu_device;
    j["seconds"] = r.seconds;
    if (r.sweep()) {
        j["axis"] = to_string(r.axis);
        j["parameter"] = r.parameter;
    }
    ordered_json rows = ordered_json::array();
    auto num = [](double x) { return std::isfinite(x) ? ordered_json(x) : ordered_json(); };
    for (const auto& row : r.rows) {
        ordered_json o;
        o["variant"] = row.name;
        o["baseline"] = row.baseline;
        if (r.sweep()) o[r.parameter] = row.value;
        o["cases"] = row.cases;
        o["spirv_instructions"] = row.spirv_instructions;
        o["x86_instructions"] = row.x86_instructions;
        if (row.gpu) o["gpu"] = gpu_cost_json(*row.gpu);
        o["table_bytes"] = row.table_bytes;
        o["texture_fetches"] = row.texture_fetches;
        o["ns_per_case"] = row.ns_per_case;
        o["ratio_to_point"] = row.ratio;
        o["pareto"] = row.pareto;
        o["recommended"] = row.recommended;
        // The error of the plots and the front: the larger relL2 of these two.
        o["error_quantities"] = {"specular", second_quantity(row.variant)};
        o["error_rel_l2"] = num(row.error());
        ordered_json e;
        for (const auto& s : row.scores) {
            ordered_json q;
            q["n"] = s.n;
            q["missing"] = s.missing;
            q["bad"] = s.bad;
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

std::optional<Report> read_report_json(const std::string& text, const std::string& file,
                                       const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& where, const std::string& what) -> std::optional<Report> {
        if (diag) diag({Severity::Error, file, 0, fmt::format("{}: {}: {}", file, where, what)});
        return std::nullopt;
    };
    // Ordered: the quantities' scores keep the order the file lists them in.
    const auto doc = nlohmann::ordered_json::parse(text, nullptr, false);
    if (!doc.is_object()) return fail("document", "not JSON");
    if (doc.value("format", "") != "arealight-report/1")
        return fail("field 'format'", "not \"arealight-report/1\"");
    if (!doc.contains("rows") || !doc["rows"].is_array() || doc["rows"].empty())
        return fail("field 'rows'", "missing, not an array, or empty");
    Report r;
    try {
        r.pattern = doc.at("pattern").get<std::string>();
        r.case_files = doc.at("case_files").get<std::vector<std::string>>();
        r.device = doc.at("device").get<std::string>();
        r.gpu_device = doc.value("gpu_device", "");
        r.seconds = doc.at("seconds").get<double>();
    } catch (const nlohmann::json::exception& e) {
        return fail("header", e.what());
    }
    if (doc.contains("axis")) {
        const auto axis = doc["axis"].is_string() ? parse_sweep_axis(doc["axis"]) : std::nullopt;
        if (!axis) return fail("field 'axis'", "neither \"param\" nor \"view\"");
        r.axis = *axis;
    }
    for (std::size_t i = 0; i < doc["rows"].size(); ++i) {
        const auto& o = doc["rows"][i];
        const std::string where = fmt::format("row {}", i);
        ReportRow row;
        std::string why;
        try {
            row.name = o.at("variant").get<std::string>();
            const auto v = parse_variant(row.name, [&](const Diagnostic& d) { why = d.message; });
            if (!v) return fail(where + ": field 'variant'", why);
            row.variant = *v;
            row.baseline = o.at("baseline").get<std::string>();
            row.cases = o.at("cases").get<std::size_t>();
            row.spirv_instructions = o.at("spirv_instructions").get<std::size_t>();
            row.x86_instructions = o.at("x86_instructions").get<std::size_t>();
            row.table_bytes = o.at("table_bytes").get<std::size_t>();
            row.texture_fetches = o.at("texture_fetches").get<std::size_t>();
            row.ns_per_case = o.at("ns_per_case").get<double>();
            row.ratio = o.at("ratio_to_point").get<double>();
            if (o.contains("gpu")) {
                auto g = parse_gpu_cost(nlohmann::json::parse(o["gpu"].dump()), why);
                if (!g) return fail(where + ": field 'gpu'", why);
                row.gpu = *g;
            }
            auto num = [](const nlohmann::ordered_json& x) {
                return x.is_number() ? x.get<double>() : NAN;
            };
            for (auto it = o.at("error").begin(); it != o.at("error").end(); ++it) {
                QuantityScore s;
                s.quantity = it.key();
                const auto& q = it.value();
                s.n = q.at("n").get<std::size_t>();
                s.missing = q.at("missing").get<std::size_t>();
                s.bad = q.at("bad").get<std::size_t>();
                s.median = num(q.at("median"));
                s.p95 = num(q.at("p95"));
                s.max = num(q.at("max"));
                s.rel_l2 = num(q.at("rel_l2"));
                s.worst = q.at("worst").get<std::string>();
                row.scores.push_back(std::move(s));
            }
        } catch (const nlohmann::json::exception& e) {
            return fail(where, e.what());
        }
        if (r.sweep()) {
            if (i == 0) set_sweep_labels(r, row.variant.dist);
            if (!o.contains(r.parameter) || !o[r.parameter].is_number())
                return fail(where, fmt::format("field '{}' missing or not a number", r.parameter));
            row.value = o[r.parameter].get<double>();
        }
        r.rows.push_back(std::move(row));
    }
    mark_pareto(r.rows);
    mark_recommended(r.rows);
    return r;
}

namespace {

// Table bytes as the reader wants them: – for none, KiB above 1 KiB.
std::string bytes_text(std::size_t b) {
    if (b == 0) return "–";
    if (b < 1024) return fmt::format("{} B", b);
    return fmt::format("{:g} KiB", b / 1024.0);
}

std::string score_cell(const ReportRow& row, const std::string& q) {
    const QuantityScore* s = find_score(row, q);
    if (!s) return "–";
    std::string cell =
        fmt::format("{} / {} / {} / {}", g3(s->median), g3(s->p95), g3(s->max), g3(s->rel_l2));
    if (s->missing || s->bad) cell += fmt::format(" ({} missing, {} bad)", s->missing, s->bad);
    return cell;
}

// GPU cost | × point | VGPRs | waves, "–" each without one.
std::string gpu_cells(const ReportRow& row) {
    if (!row.gpu) return "– | – | – | –";
    const GpuCost& g = *row.gpu;
    return fmt::format("{} | {} | {} | {}", g.cost,
                       g.ratio_to_point > 0 ? fmt::format("{:.2f}", g.ratio_to_point) : "–",
                       g.spilled_vgprs ? fmt::format("{} ({} spilled)", g.vgprs, g.spilled_vgprs)
                                       : fmt::format("{}", g.vgprs),
                       g.waves_per_simd);
}

std::string table(const std::vector<const ReportRow*>& rows, const Report& r) {
    const std::string second = second_quantity_name(rows);
    std::string t;
    if (r.sweep()) {
        t += fmt::format(
            "| variant | {} | cases | GPU cost | × point | VGPRs | waves | ns/case | time × point "
            "| specular median / p95 / max / relL2 | {} median / p95 / max / relL2 |\n",
            r.symbol, second);
        t += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
    } else {
        t += fmt::format(
            "| variant | cases | GPU cost | × point | VGPRs | waves | SPIR-V | x86-64 | tables | "
            "fetches | ns/case | time × point | diffuse relL2 | specular median / p95 / max / "
            "relL2 | {} median / p95 / max / relL2 | front |\n",
            second);
        t += "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|:---:|\n";
    }
    for (const ReportRow* row : rows) {
        const std::string q = second_quantity(row->variant);
        if (r.sweep()) {
            t += fmt::format("| `{}` | {:g} | {} | {} | {:.1f} | {:.2f} | {} | {} |\n", row->name,
                             row->value, row->cases, gpu_cells(*row), row->ns_per_case, row->ratio,
                             score_cell(*row, "specular"), score_cell(*row, q));
        } else {
            const QuantityScore* d = find_score(*row, "diffuse");
            t += fmt::format(
                "| `{}` | {} | {} | {} | {} | {} | {} | {:.1f} | {:.2f} | {} | {} | {} | {} |\n",
                row->name, row->cases, gpu_cells(*row), row->spirv_instructions,
                row->x86_instructions, bytes_text(row->table_bytes), row->texture_fetches,
                row->ns_per_case, row->ratio, d ? g3(d->rel_l2) : "–", score_cell(*row, "specular"),
                score_cell(*row, q),
                std::string(row->pareto ? "●" : "") + (row->recommended ? " ★" : ""));
        }
    }
    return t;
}

std::string ratio_text(double x) {
    if (!std::isfinite(x)) return "–";
    return x < 10 ? fmt::format("{:.1f}×", x) : fmt::format("{:.0f}×", x);
}

std::string error_text(double x) {
    return std::isfinite(x) ? fmt::format("{:.1e}", x) : "–";
}

// A sweep at a glance: one row per variant, one column per value, each cell the
// time ratio to the point light / the error.
std::string sweep_summary(const Report& r) {
    std::vector<double> values;
    std::vector<std::string> names;
    for (const auto& row : r.rows) {
        if (std::find(values.begin(), values.end(), row.value) == values.end())
            values.push_back(row.value);
        if (std::find(names.begin(), names.end(), row.name) == names.end())
            names.push_back(row.name);
    }
    std::string t = "| variant |";
    std::string rule = "|---|";
    for (double x : values) {
        t += fmt::format(" {} = {:g} |", r.symbol, x);
        rule += "---:|";
    }
    t += "\n" + rule + "\n";
    for (const auto& name : names) {
        t += fmt::format("| `{}` |", name);
        for (double x : values) {
            std::string cell = " – |";
            for (const auto& row : r.rows)
                if (row.name == name && row.value == x)
                    cell =
                        fmt::format(" {} / {} |", ratio_text(row.ratio), error_text(row.error()));
            t += cell;
        }
        t += "\n";
    }
    return t;
}

}  // namespace

std::string report_markdown(const Report& r) {
    const bool sweep = r.sweep();
    std::string files;
    for (const auto& f : r.case_files) files += (files.empty() ? "" : ", ") + ("`" + f + "`");
    std::string over;
    if (r.axis == SweepAxis::Param)
        over = fmt::format(
            "Every case's {} ({}) set to each value in turn, the oracle recomputed per value.\n\n",
            r.parameter, r.symbol);
    else if (r.axis == SweepAxis::View)
        over =
            "Every case's view direction v rotated, in the plane of n and v, to the angle θ_v "
            "from n with each cos θ_v in turn (1: along the normal; small: grazing), the oracle "
            "recomputed per value.\n\n";
    std::string t = fmt::format(
        "<!-- generated by arealight {}; do not edit -->\n"
        "# arealight {}: `{}`\n\n"
        "Cases: {}. Device: {}. {} rows in {:.0f} s.\n\n{}"
        "{}"
        "Time: median of repeated dispatches on the device, per case; time × point is the "
        "ratio to the point-light variant of the same distribution and shape (sided, verts), "
        "timed interleaved with it. Error: |x − ref| / max(ref, 1e-3) against `arealight "
        "reference` (median, p95, max) and relative L2, the metric of `shared/tools/score`; "
        "the second quantity is moment for phong and ndf for the microfacet distributions. "
        "front: on the error–cost Pareto front of its distribution and shape (error = the "
        "larger relL2 of specular and moment or ndf; cost = {}){}.\n\n",
        sweep ? "sweep" : "report", sweep ? "sweep" : "report", r.pattern, files, r.device,
        r.rows.size(), r.seconds, over,
        r.gpu_device.empty()
            ? std::string("GPU cost: not measured (no RADV).\n\n")
            : fmt::format(
                  "GPU cost: ACO's inverse throughput (cycles per wave) of the kernel of "
                  "`arealight generate --spv`, compiled by {}, the larger of the module as "
                  "written and with its constant-trip-count loops unrolled (CONTRACT.md 4); "
                  "× point against the point light's, measured the same way; VGPRs (spilled) "
                  "and waves per SIMD of the module as written.\n\n",
                  r.gpu_device),
        r.by_gpu_cost() ? "GPU cost × point" : "time × point",
        sweep ? ""
              : "; ★: recommended, what `generate --scene` would pick by these rows at the "
                "default quality (per distribution and light, default shape, not fp64: the "
                "cheapest with error <= 2e-2, else the most accurate), ringed in report.svg");
    std::vector<const ReportRow*> all, shape;
    const Variant d;
    for (const auto& row : r.rows) {
        all.push_back(&row);
        if (row.variant.sided == d.sided && row.variant.verts == d.verts) shape.push_back(&row);
    }
    if (sweep) {
        t += "## Summary\n\nTime ratio to the point light / error (the larger relL2 of specular "
             "and " +
             second_quantity_name(all) + ").\n\n" + sweep_summary(r) + "\n## All rows\n\n";
    } else if (shape.size() != all.size() && !shape.empty()) {
        t += "## Default shape (sided=any, verts=8)\n\n" + table(shape, r) + "\n## All rows\n\n";
    }
    t += table(all, r);
    return t;
}

std::vector<std::pair<std::string, std::string>> report_pictures(const Report& r) {
    std::vector<std::pair<std::string, std::string>> out;
    const bool with_dist = several_distributions(r);
    std::vector<const ReportRow*> all;
    for (const auto& row : r.rows) all.push_back(&row);
    const std::string error_label =
        "relative L2 error (max of specular, " + second_quantity_name(all) + ")";
    // One colour per method label, in order of first appearance.
    std::vector<std::string> labels;
    for (const auto& row : r.rows) {
        const std::string l = method_label(row.variant, with_dist);
        if (std::find(labels.begin(), labels.end(), l) == labels.end()) labels.push_back(l);
    }
    auto color = [&](const std::string& l) {
        return plot_color(std::find(labels.begin(), labels.end(), l) - labels.begin());
    };
    if (!r.sweep()) {
        // One shape, so that every point is measured on the same cases: the default
        // one when the run has it.
        const Variant d;
        std::vector<const ReportRow*> rows;
        for (const auto& row : r.rows)
            if (row.variant.sided == d.sided && row.variant.verts == d.verts) rows.push_back(&row);
        std::string shape = " (sided=any, verts=8)";
        if (rows.empty()) {
            rows = all;
            shape.clear();
        }
        const bool gpu = r.by_gpu_cost();
        // Error against one cost per row, the front drawn when it was marked on that cost.
        auto cost_plot = [&](const std::string& x_label, auto cost, bool front) {
            Plot p;
            p.title = "Error against cost: " + r.pattern + shape;
            p.x_label = x_label;
            p.y_label = error_label;
            for (const auto& l : labels) {
                PlotSeries s;
                s.name = l;
                s.color = color(l);
                s.marker = plot_marker(std::find(labels.begin(), labels.end(), l) - labels.begin());
                for (const ReportRow* row : rows)
                    if (method_label(row->variant, with_dist) == l)
                        s.points.push_back({cost(*row), row->error(), row->name});
                if (!s.points.empty()) p.series.push_back(s);
            }
            for (const ReportRow* row : rows)
                if (row->recommended) p.highlight.push_back({cost(*row), row->error(), row->name});
            if (!p.highlight.empty())
                p.highlight_name = "recommended (error <= 2e-2, fp32)";
            // One front per distribution is one polyline only when there is one.
            if (front && !with_dist) {
                for (const ReportRow* row : rows)
                    if (row->pareto) p.front.push_back({cost(*row), row->error(), row->name});
                std::sort(p.front.begin(), p.front.end(),
                          [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
                p.front_name = "Pareto front";
            }
            return p;
        };
        auto time_ratio = [](const ReportRow& row) { return row.ratio; };
        const std::string time_label = "time per case / point light (lavapipe, median)";
        const Plot p = gpu ? cost_plot(
                                 "GPU cost / point light (" + r.gpu_device +
                                     ": ACO inverse throughput, loops unrolled where constant)",
                                 [](const ReportRow& row) { return row.gpu->ratio_to_point; }, true)
                           : cost_plot(time_label, time_ratio, true);
        out.emplace_back("report.svg", svg_plot(p));
        if (gpu)
            out.emplace_back("report_time.svg", svg_plot(cost_plot(time_label, time_ratio, false)));
        // The same against the deterministic cost: lavapipe's x86-64 instruction count.
        Plot q = p;
        q.title = "Error against code size: " + r.pattern + shape;
        q.x_label = "x86-64 instructions of the lavapipe shader";
        q.front.clear();
        q.front_name.clear();
        for (auto& s : q.series) {
            s.points.clear();
            for (const ReportRow* row : rows)
                if (method_label(row->variant, with_dist) == s.name && row->x86_instructions > 0)
                    s.points.push_back({double(row->x86_instructions), row->error(), row->name});
        }
        out.emplace_back("report_x86.svg", svg_plot(q));
        return out;
    }
    const std::string what = r.axis == SweepAxis::View ? "view angle" : r.symbol;
    for (int which = 0; which < 2; ++which) {
        Plot p;
        p.title = (which == 0 ? "Cost against " : "Error against ") + what + ": " + r.pattern;
        p.x_label = r.axis_label;
        p.y_label = which == 0 ? "time per case / point light" : error_label;
        std::vector<std::string> names;
        for (const auto& row : r.rows)
            if (std::find(names.begin(), names.end(), row.name) == names.end())
                names.push_back(row.name);
        for (std::size_t k = 0; k < names.size(); ++k) {
            PlotSeries s;
            for (const auto& row : r.rows)
                if (row.name == names[k]) s.name = series_label(row.variant, with_dist);
            s.color = plot_color(k);
            s.marker = plot_marker(k);
            s.line = true;
            for (const auto& row : r.rows)
                if (row.name == names[k])
                    s.points.push_back({row.value, which == 0 ? row.ratio : row.error(), ""});
            p.series.push_back(s);
        }
        out.emplace_back(which == 0 ? "sweep_time.svg" : "sweep_error.svg", svg_plot(p));
    }
    return out;
}

}  // namespace arealight
