// arealight-quality/1: built from arealight-report/1 files, written and read back.
#include "arealight/quality.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "arealight/gpu_cost_json.hpp"
#include "json_fields.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;
using io_detail::Reporter;

constexpr const char* kFormat = "arealight-quality/1";

void warn(const DiagnosticConsumer& diag, const std::string& file, const std::string& message) {
    if (diag) diag({Severity::Warning, file, 0, file + ": " + message});
}

// A finite number under `key`, or nullopt.
std::optional<double> finite(const json& obj, const char* key) {
    auto it = obj.find(key);
    if (it == obj.end() || !it->is_number()) return std::nullopt;
    const double x = it->get<double>();
    if (!std::isfinite(x)) return std::nullopt;
    return x;
}

// One report row, or nullopt with the reason why it is left out.
std::optional<MeasuredVariant> from_row(const json& row, const std::string& report,
                                        std::string& why, std::string& warning) {
    MeasuredVariant m;
    m.report = report;
    auto name = row.find("variant");
    if (name == row.end() || !name->is_string()) {
        why = "has no variant name";
        return std::nullopt;
    }
    m.variant = name->get<std::string>();
    const auto x86 = finite(row, "x86_instructions");
    if (!x86 || *x86 <= 0) {
        why = "has no x86 instruction count (report run without a shader cache)";
        return std::nullopt;
    }
    m.x86_instructions = static_cast<std::size_t>(*x86);
    m.ratio_to_point = finite(row, "ratio_to_point").value_or(0.0);
    m.cases = static_cast<std::size_t>(finite(row, "cases").value_or(0.0));
    if (auto g = row.find("gpu"); g != row.end()) {
        std::string bad;
        m.gpu = parse_gpu_cost(*g, bad);
        if (!m.gpu) warning = "its gpu object is left out: " + bad;
    }
    auto err = row.find("error");
    if (err == row.end() || !err->is_object()) {
        why = "has no error table";
        return std::nullopt;
    }
    for (auto it = err->begin(); it != err->end(); ++it) {
        if (!it->is_object()) continue;
        // null where the variant does not compute the quantity (point and ltc: no ndf or
        // moment), every case then "missing"; a quantity it computes is always a number.
        if (auto r = it->find("rel_l2"); r != it->end() && r->is_null()) continue;
        const auto r = finite(*it, "rel_l2");
        if (!r) {
            why = "has no finite rel_l2 for " + it.key();
            return std::nullopt;
        }
        m.rel_l2[it.key()] = *r;
    }
    if (m.rel_l2.count("specular") == 0) {
        why = "has no specular error";
        return std::nullopt;
    }
    if (const auto e = finite(row, "error_rel_l2")) {
        m.error_rel_l2 = *e;
    } else {
        bool any = false;
        for (const auto& [q, r] : m.rel_l2) {
            if (q == "diffuse") continue;
            m.error_rel_l2 = std::max(m.error_rel_l2, r);
            any = true;
        }
        if (!any) {
            why = "has no error beside diffuse";
            return std::nullopt;
        }
    }
    return m;
}

// Adds or replaces (same variant: the later report wins) in place.
void put(QualityData& data, MeasuredVariant m) {
    for (auto& old : data.variants) {
        if (old.variant == m.variant) {
            old = std::move(m);
            return;
        }
    }
    data.variants.push_back(std::move(m));
}

}  // namespace

double MeasuredVariant::error() const {
    auto d = rel_l2.find("diffuse");
    return d == rel_l2.end() ? error_rel_l2 : std::max(error_rel_l2, d->second);
}

const MeasuredVariant* QualityData::find(const std::string& variant) const {
    for (const auto& m : variants)
        if (m.variant == variant) return &m;
    return nullptr;
}

std::optional<QualityData> quality_from_reports(const std::vector<std::string>& paths,
                                                const DiagnosticConsumer& diag) {
    QualityData data;
    bool ok = true;
    for (const auto& path : paths) {
        auto text = io_detail::read_text(path, diag);
        auto doc = text ? io_detail::parse_json(*text, path, diag) : std::nullopt;
        if (!doc) {
            ok = false;
            continue;
        }
        Reporter rep(path, diag);
        if (!io_detail::check_format(*doc, "arealight-report/1", rep)) {
            ok = false;
            continue;
        }
        auto rows = doc->find("rows");
        if (rows == doc->end() || !rows->is_array()) {
            rep.error("", "rows", rows == doc->end() ? "missing" : "must be an array");
            ok = false;
            continue;
        }
        data.reports.push_back(path);
        for (std::size_t i = 0; i < rows->size(); ++i) {
            std::string why, warning;
            auto m =
                (*rows)[i].is_object() ? from_row((*rows)[i], path, why, warning) : std::nullopt;
            if (!warning.empty()) warn(diag, path, fmt::format("rows[{}]: {}", i, warning));
            if (m)
                put(data, std::move(*m));
            else
                warn(diag, path,
                     fmt::format("rows[{}] left out: {}", i, why.empty() ? "not an object" : why));
        }
    }
    if (!ok) return std::nullopt;
    return data;
}

std::string format_quality(const QualityData& data) {
    ordered_json doc = ordered_json::object();
    doc["format"] = kFormat;
    doc["reports"] = data.reports;
    ordered_json arr = ordered_json::array();
    for (const auto& m : data.variants) {
        ordered_json j = ordered_json::object();
        j["variant"] = m.variant;
        j["error_rel_l2"] = m.error_rel_l2;
        ordered_json rel = ordered_json::object();
        for (const auto& [q, r] : m.rel_l2) rel[q] = r;
        j["rel_l2"] = std::move(rel);
        j["x86_instructions"] = m.x86_instructions;
        j["ratio_to_point"] = m.ratio_to_point;
        if (m.gpu) j["gpu"] = gpu_cost_json(*m.gpu);
        j["cases"] = m.cases;
        j["report"] = m.report;
        arr.push_back(std::move(j));
    }
    doc["variants"] = std::move(arr);
    return doc.dump(1, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

std::optional<QualityData> parse_quality(const std::string& text, const std::string& name,
                                         const DiagnosticConsumer& diag) {
    auto doc = io_detail::parse_json(text, name, diag);
    if (!doc) return std::nullopt;
    Reporter rep(name, diag);
    if (!io_detail::check_format(*doc, kFormat, rep)) return std::nullopt;
    QualityData data;
    if (auto r = doc->find("reports"); r != doc->end() && r->is_array())
        for (const auto& x : *r)
            if (x.is_string()) data.reports.push_back(x.get<std::string>());
    auto vs = doc->find("variants");
    if (vs == doc->end() || !vs->is_array()) {
        rep.error("", "variants", vs == doc->end() ? "missing" : "must be an array");
        return std::nullopt;
    }
    for (std::size_t i = 0; i < vs->size(); ++i) {
        const json& j = (*vs)[i];
        const std::string where = fmt::format("variants[{}]", i);
        if (!j.is_object()) {
            rep.error(where, "", "must be an object");
            continue;
        }
        MeasuredVariant m;
        auto text_field = [&](const char* key, std::string& out) {
            auto it = j.find(key);
            if (it == j.end() || !it->is_string())
                rep.error(where, key, it == j.end() ? "missing" : "must be a string");
            else
                out = it->get<std::string>();
        };
        auto number = [&](const char* key) {
            const auto x = finite(j, key);
            if (!x || *x < 0) rep.error(where, key, "must be a finite number >= 0");
            return x.value_or(0.0);
        };
        text_field("variant", m.variant);
        text_field("report", m.report);
        m.error_rel_l2 = number("error_rel_l2");
        m.x86_instructions = static_cast<std::size_t>(number("x86_instructions"));
        m.ratio_to_point = number("ratio_to_point");
        m.cases = static_cast<std::size_t>(number("cases"));
        if (auto g = j.find("gpu"); g != j.end()) {
            std::string bad;
            m.gpu = parse_gpu_cost(*g, bad);
            if (!m.gpu) rep.error(where, "gpu", bad);
        }
        auto rel = j.find("rel_l2");
        if (rel == j.end() || !rel->is_object()) {
            rep.error(where, "rel_l2", "must be an object of numbers");
        } else {
            for (auto it = rel->begin(); it != rel->end(); ++it) {
                if (!it->is_number() || !std::isfinite(it->get<double>()))
                    rep.error(where, "rel_l2." + it.key(), "must be a finite number");
                else
                    m.rel_l2[it.key()] = it->get<double>();
            }
        }
        data.variants.push_back(std::move(m));
    }
    if (rep.errors() > 0) return std::nullopt;
    return data;
}

}  // namespace arealight
