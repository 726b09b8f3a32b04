// arealight-cases/1 reader with full validation, arealight-results/1 writer and reader. A
// case's light and material go through the shared schema (shading_schema.hpp).
#include "arealight/case_io.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "arealight/atomic_file.hpp"
#include "json_fields.hpp"
#include "shading_schema.hpp"

namespace arealight {
namespace {

using json = nlohmann::json;
// Output keeps insertion order so that files read in the order CONTRACT.md shows.
using ordered_json = nlohmann::ordered_json;
using io_detail::parse_json;
using io_detail::read_text;
using io_detail::Reporter;

// A case's "light" or "material": present, an object, and valid as CONTRACT 3 says.
void read_case_light(Reporter& rep, const std::string& where, const json& c,
                     const ValidationTolerances& tol, Light& out) {
    auto it = c.find("light");
    if (it == c.end() || !it->is_object()) {
        rep.error(where, "light", it == c.end() ? "missing" : "must be an object");
        return;
    }
    io_detail::read_light_object(rep, where, "light.", *it, tol, out);
}

void read_case_material(Reporter& rep, const std::string& where, const json& c, Material& out) {
    auto it = c.find("material");
    if (it == c.end() || !it->is_object()) {
        rep.error(where, "material", it == c.end() ? "missing" : "must be an object");
        return;
    }
    io_detail::read_material_object(rep, where, "material.", *it, out);
}

void put(ordered_json& j, const char* key, const std::optional<double>& v) {
    if (!v) return;
    // JSON has no NaN or infinity: a non-finite value is written as null (read back as absent).
    if (std::isfinite(*v))
        j[key] = *v;
    else
        j[key] = nullptr;
}

}  // namespace

std::optional<CaseSet> parse_cases(const std::string& text, const std::string& name,
                                   const DiagnosticConsumer& diag,
                                   const ValidationTolerances& tol) {
    auto parsed = parse_json(text, name, diag);
    if (!parsed) return std::nullopt;
    const json& doc = *parsed;
    Reporter rep(name, diag);
    if (!io_detail::check_format(doc, "arealight-cases/1", rep)) return std::nullopt;
    io_detail::check_fields(rep, "", "", doc, {"format", "cases"});
    auto cs = doc.find("cases");
    if (cs == doc.end() || !cs->is_array()) {
        rep.error("", "cases", cs == doc.end() ? "missing" : "must be an array of cases");
        return std::nullopt;
    }
    CaseSet set;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < cs->size(); ++i) {
        const json& c = (*cs)[i];
        Case out;
        // A case is named by its id when it has a usable one, else by its index in "cases".
        std::string where = fmt::format("case #{}", i);
        if (!c.is_object()) {
            rep.error("", fmt::format("cases[{}]", i), "must be an object");
            continue;
        }
        auto id = c.find("id");
        if (id == c.end() || !id->is_string() || id->get<std::string>().empty()) {
            rep.error(where, "id", id == c.end() ? "missing" : "must be a non-empty string");
        } else {
            out.id = id->get<std::string>();
            where = "case '" + out.id + "'";
            if (!ids.insert(out.id).second)
                rep.error(where, "id", "duplicates an earlier case's id");
        }
        io_detail::check_fields(rep, where, "", c, {"id", "p", "n", "v", "light", "material"});
        io_detail::read_point(rep, where, c, "p", "p", out.p);
        io_detail::read_direction(rep, where, c, "n", "n", out.n);
        io_detail::read_direction(rep, where, c, "v", "v", out.v);
        read_case_light(rep, where, c, tol, out.light);
        read_case_material(rep, where, c, out.material);
        set.cases.push_back(std::move(out));
    }
    if (rep.errors() > 0) return std::nullopt;
    return set;
}

std::optional<CaseSet> read_cases(const std::string& path, const DiagnosticConsumer& diag,
                                  const ValidationTolerances& tol) {
    auto text = read_text(path, diag);
    if (!text) return std::nullopt;
    return parse_cases(*text, path, diag, tol);
}

std::string format_results(const ResultSet& results) {
    ordered_json doc = ordered_json::object();
    doc["format"] = "arealight-results/1";
    doc["variant"] = results.variant;
    doc["backend"] = results.backend;
    ordered_json arr = ordered_json::array();
    for (const auto& r : results.results) {
        ordered_json j = ordered_json::object();
        j["id"] = r.id;
        put(j, "diffuse", r.diffuse);
        put(j, "specular", r.specular);
        put(j, "ndf", r.ndf);
        put(j, "moment", r.moment);
        put(j, "error", r.error);
        put(j, "error_diffuse", r.error_diffuse);
        put(j, "error_ndf", r.error_ndf);
        put(j, "error_moment", r.error_moment);
        if (r.converged) j["converged"] = *r.converged;
        arr.push_back(std::move(j));
    }
    doc["results"] = std::move(arr);
    // nlohmann prints the shortest digits that read back as the same double, so values
    // round-trip bit for bit. Invalid UTF-8 in a name is replaced rather than thrown on.
    return doc.dump(1, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

bool write_results(const std::string& path, const ResultSet& results,
                   const DiagnosticConsumer& diag) {
    return write_file_atomic(path, format_results(results), diag);
}

std::optional<ResultSet> read_results(const std::string& path, const DiagnosticConsumer& diag) {
    auto text = read_text(path, diag);
    if (!text) return std::nullopt;
    return parse_results(*text, path, diag);
}

std::optional<ResultSet> parse_results(const std::string& text, const std::string& name,
                                       const DiagnosticConsumer& diag) {
    auto parsed = parse_json(text, name, diag);
    if (!parsed) return std::nullopt;
    const json& doc = *parsed;
    Reporter rep(name, diag);
    if (!io_detail::check_format(doc, "arealight-results/1", rep)) return std::nullopt;
    auto rs = doc.find("results");
    if (rs == doc.end() || !rs->is_array()) {
        rep.error("", "results", rs == doc.end() ? "missing" : "must be an array");
        return std::nullopt;
    }
    ResultSet out;
    auto text_field = [&](const char* key, std::string& s) {
        auto it = doc.find(key);
        if (it == doc.end()) return;
        if (it->is_string())
            s = it->get<std::string>();
        else
            rep.error("", key, "must be a string");
    };
    text_field("variant", out.variant);
    text_field("backend", out.backend);
    for (std::size_t i = 0; i < rs->size(); ++i) {
        const json& j = (*rs)[i];
        const std::string where = fmt::format("results[{}]", i);
        if (!j.is_object()) {
            rep.error("", where, "must be an object");
            continue;
        }
        CaseResult r;
        auto id = j.find("id");
        if (id == j.end() || !id->is_string())
            rep.error("", where + ".id", id == j.end() ? "missing" : "must be a string");
        else
            r.id = id->get<std::string>();
        // Absent and null both leave the value unset (null is how non-finite values are written).
        auto number = [&](const char* key, std::optional<double>& v) {
            auto it = j.find(key);
            if (it == j.end() || it->is_null()) return;
            if (it->is_number())
                v = it->get<double>();
            else
                rep.error("", where + "." + key, "must be a number or null");
        };
        number("diffuse", r.diffuse);
        number("specular", r.specular);
        number("ndf", r.ndf);
        number("moment", r.moment);
        number("error", r.error);
        number("error_diffuse", r.error_diffuse);
        number("error_ndf", r.error_ndf);
        number("error_moment", r.error_moment);
        if (auto it = j.find("converged"); it != j.end() && !it->is_null()) {
            if (it->is_boolean())
                r.converged = it->get<bool>();
            else
                rep.error("", where + ".converged", "must be true, false or null");
        }
        out.results.push_back(std::move(r));
    }
    if (rep.errors() > 0) return std::nullopt;
    return out;
}

}  // namespace arealight
