#include "arealight/variant.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <iterator>
#include <map>

namespace arealight {
namespace {

const Distribution kDists[] = {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                               Distribution::Ggx};
const Method kMethods[] = {Method::Exact,   Method::Arvo,      Method::Lorentz,
                           Method::Pearson, Method::Ellipsoid, Method::Point};
const LightType kLights[] = {LightType::Polygon, LightType::Disk, LightType::Sphere,
                             LightType::Ellipsoid};
const Sided kSided[] = {Sided::Any, Sided::One, Sided::Two};
const int kNodes[] = {8, 12, 16, 24};
const Precision kPrecisions[] = {Precision::Fp64, Precision::Fp32};
const Fit kFits[] = {Fit::Tuned, Fit::Paper};
const SpecularForm kSpecularForms[] = {SpecularForm::TwoAxis, SpecularForm::Sg};
// Largest polygon compiled in (the templates size their per-vertex arrays by
// AL_MAX_VERTS): triangles, quads, and the contract's maximum. Cost falls with it
// (fewer edges to clip and integrate); the sizes between bought little and each
// doubled the variants to build and check.
const int kVerts[] = {3, 4, 8};

// The (dist, method, light) families with an implementation. Adding a method is
// a template plus a row here.
struct Family {
    Distribution dist;
    Method method;
    LightType light;
};
const Family kFamilies[] = {
    {Distribution::Phong, Method::Exact, LightType::Polygon},
    {Distribution::Phong, Method::Arvo, LightType::Polygon},
    {Distribution::Phong, Method::Lorentz, LightType::Polygon},
    {Distribution::Phong, Method::Pearson, LightType::Polygon},
    {Distribution::Phong, Method::Ellipsoid, LightType::Polygon},
    {Distribution::Phong, Method::Point, LightType::Polygon},
};

bool has_family(const Variant& v) {
    return std::any_of(std::begin(kFamilies), std::end(kFamilies), [&](const Family& f) {
        return f.dist == v.dist && f.method == v.method && f.light == v.light;
    });
}
bool uses_verts(const Variant& v) {
    return v.light == LightType::Polygon;
}
bool uses_nodes(const Variant& v) {
    return v.method == Method::Exact;
}
bool uses_precision(const Variant& v) {
    return v.method == Method::Exact;
}
bool uses_peak_keys(const Variant& v) {
    return is_peak_method(v.method);
}
template <class T, std::size_t N>
bool contains(const T (&values)[N], const T& x) {
    return std::find(std::begin(values), std::end(values), x) != std::end(values);
}

template <class T, std::size_t N>
std::string choices(const T (&values)[N]) {
    std::string s;
    for (const auto& x : values) s += (s.empty() ? "" : ", ") + std::string(to_string(x));
    return s;
}

template <class T, std::size_t N>
std::optional<T> lookup(const T (&values)[N], const std::string& name) {
    for (const auto& x : values)
        if (name == to_string(x)) return x;
    return std::nullopt;
}

bool is_digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool is_space(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// The length cap keeps std::stoi clear of overflow; no valid value has more digits.
std::optional<int> parse_int(const std::string& s) {
    if (s.empty() || s.size() > 3 || !std::all_of(s.begin(), s.end(), is_digit))
        return std::nullopt;
    return std::stoi(s);
}

// Splits "a=b,c=d" into ordered pairs; nullopt (with a message) on bad syntax.
std::optional<std::vector<std::pair<std::string, std::string>>> split(const std::string& name,
                                                                      std::string& why) {
    std::vector<std::pair<std::string, std::string>> out;
    if (name.empty()) return out;
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t comma = std::min(name.find(',', start), name.size());
        const std::string item = name.substr(start, comma - start);
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == item.size() ||
            item.find('=', eq + 1) != std::string::npos ||
            std::any_of(item.begin(), item.end(), is_space)) {
            why = fmt::format("'{}' is not key=value", item);
            return std::nullopt;
        }
        out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
        start = comma + 1;
    }
    return out;
}

}  // namespace

const char* to_string(Method m) {
    switch (m) {
        case Method::Exact:
            return "exact";
        case Method::Arvo:
            return "arvo";
        case Method::Lorentz:
            return "lorentz";
        case Method::Pearson:
            return "pearson";
        case Method::Ellipsoid:
            return "ellipsoid";
        case Method::Point:
            return "point";
    }
    return "exact";
}
const char* to_string(Fit f) {
    return f == Fit::Tuned ? "tuned" : "paper";
}
const char* to_string(SpecularForm s) {
    return s == SpecularForm::TwoAxis ? "twoaxis" : "sg";
}
bool is_peak_method(Method m) {
    return m == Method::Lorentz || m == Method::Pearson || m == Method::Ellipsoid;
}
const char* to_string(Precision p) {
    return p == Precision::Fp64 ? "fp64" : "fp32";
}
Precision effective_precision(const Variant& v) {
    return uses_precision(v) ? v.precision : Precision::Fp32;
}
const char* to_string(Sided s) {
    switch (s) {
        case Sided::Any:
            return "any";
        case Sided::One:
            return "one";
        case Sided::Two:
            return "two";
    }
    return "any";
}

std::optional<Variant> parse_variant(const std::string& name, const DiagnosticConsumer& diag) {
    auto fail = [&](const std::string& what) -> std::optional<Variant> {
        if (diag) diag({Severity::Error, "", 0, fmt::format("variant '{}': {}", name, what)});
        return std::nullopt;
    };
    std::string why;
    auto pairs = split(name, why);
    if (!pairs) return fail(why);
    Variant v;
    std::map<std::string, std::string> seen;
    for (const auto& [key, value] : *pairs) {
        if (!seen.emplace(key, value).second) return fail(fmt::format("key '{}' given twice", key));
        // Each sets its field from the value, or returns the message saying why not.
        auto pick = [&](const auto& values, auto& field) -> std::optional<std::string> {
            auto x = lookup(values, value);
            if (!x)
                return fmt::format("key '{}': unknown value '{}' (expected {})", key, value,
                                   choices(values));
            field = *x;
            return std::nullopt;
        };
        auto pick_int = [&](const auto& values, int& field) -> std::optional<std::string> {
            auto n = parse_int(value);
            if (!n || !contains(values, *n))
                return fmt::format("key '{}': value '{}' is not one of {}", key, value,
                                   fmt::join(values, ", "));
            field = *n;
            return std::nullopt;
        };
        std::optional<std::string> error;
        if (key == "dist") {
            error = pick(kDists, v.dist);
        } else if (key == "method") {
            error = pick(kMethods, v.method);
        } else if (key == "light") {
            error = pick(kLights, v.light);
        } else if (key == "sided") {
            error = pick(kSided, v.sided);
        } else if (key == "verts") {
            error = pick_int(kVerts, v.verts);
        } else if (key == "nodes") {
            error = pick_int(kNodes, v.nodes);
        } else if (key == "precision") {
            error = pick(kPrecisions, v.precision);
        } else if (key == "fit") {
            error = pick(kFits, v.fit);
        } else if (key == "specular") {
            error = pick(kSpecularForms, v.specular);
        } else {
            return fail(
                fmt::format("unknown key '{}' (keys: dist, method, light, sided, verts, "
                            "nodes, precision, fit, specular)",
                            key));
        }
        if (error) return fail(*error);
    }
    for (const char* required : {"dist", "method", "light"}) {
        if (!seen.count(required)) return fail(fmt::format("key '{}' is required", required));
    }
    if (seen.count("verts") && !uses_verts(v))
        return fail("key 'verts' applies to light=polygon only");
    if (seen.count("nodes") && !uses_nodes(v))
        return fail("key 'nodes' applies to method=exact only");
    if (seen.count("precision") && !uses_precision(v))
        return fail("key 'precision' applies to method=exact only");
    for (const char* k : {"fit", "specular"}) {
        if (seen.count(k) && !uses_peak_keys(v))
            return fail(
                fmt::format("key '{}' applies to method=lorentz, pearson, ellipsoid only", k));
    }
    if (!has_family(v)) {
        return fail(fmt::format("no variant for dist={},method={},light={} yet", to_string(v.dist),
                                to_string(v.method), to_string(v.light)));
    }
    return v;
}

bool is_valid(const Variant& v) {
    const Variant d;
    const bool sided_ok = contains(kSided, v.sided);
    const bool verts_ok = uses_verts(v) ? contains(kVerts, v.verts) : v.verts == d.verts;
    const bool nodes_ok = uses_nodes(v) ? contains(kNodes, v.nodes) : v.nodes == d.nodes;
    const bool precision_ok = uses_precision(v) || v.precision == d.precision;
    const bool peak_ok = uses_peak_keys(v) || (v.fit == d.fit && v.specular == d.specular);
    return has_family(v) && sided_ok && verts_ok && nodes_ok && precision_ok && peak_ok;
}

std::string canonical_name(const Variant& v) {
    const Variant d;
    std::string s = fmt::format("dist={},method={},light={}", to_string(v.dist),
                                to_string(v.method), to_string(v.light));
    if (v.sided != d.sided) s += fmt::format(",sided={}", to_string(v.sided));
    if (uses_verts(v) && v.verts != d.verts) s += fmt::format(",verts={}", v.verts);
    if (uses_nodes(v) && v.nodes != d.nodes) s += fmt::format(",nodes={}", v.nodes);
    if (uses_precision(v) && v.precision != d.precision)
        s += fmt::format(",precision={}", to_string(v.precision));
    if (uses_peak_keys(v) && v.fit != d.fit) s += fmt::format(",fit={}", to_string(v.fit));
    if (uses_peak_keys(v) && v.specular != d.specular)
        s += fmt::format(",specular={}", to_string(v.specular));
    return s;
}

std::vector<Variant> enumerate_variants() {
    std::vector<Variant> out;
    for (const auto& f : kFamilies) {
        Variant base;
        base.dist = f.dist;
        base.method = f.method;
        base.light = f.light;
        for (Sided s : kSided) {
            for (int verts : kVerts) {
                if (!uses_verts(base) && verts != kVerts[0]) continue;
                for (int nodes : kNodes) {
                    if (!uses_nodes(base) && nodes != kNodes[0]) continue;
                    for (Precision p : kPrecisions) {
                        if (!uses_precision(base) && p != kPrecisions[0]) continue;
                        for (Fit fit : kFits) {
                            if (!uses_peak_keys(base) && fit != kFits[0]) continue;
                            for (SpecularForm sf : kSpecularForms) {
                                if (!uses_peak_keys(base) && sf != kSpecularForms[0]) continue;
                                Variant v = base;
                                v.sided = s;
                                if (uses_verts(v)) v.verts = verts;
                                if (uses_nodes(v)) v.nodes = nodes;
                                if (uses_precision(v)) v.precision = p;
                                if (uses_peak_keys(v)) {
                                    v.fit = fit;
                                    v.specular = sf;
                                }
                                out.push_back(v);
                            }
                        }
                    }
                }
            }
        }
    }
    return out;
}

std::vector<std::pair<std::string, std::string>> variant_defines(const Variant& v) {
    std::vector<std::pair<std::string, std::string>> d;
    auto upper = [](std::string s) {
        for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        return s;
    };
    d.emplace_back("AL_DIST_" + upper(to_string(v.dist)), "1");
    d.emplace_back("AL_METHOD_" + upper(to_string(v.method)), "1");
    d.emplace_back("AL_LIGHT_" + upper(to_string(v.light)), "1");
    d.emplace_back("AL_SIDED", v.sided == Sided::Any ? "0" : v.sided == Sided::One ? "1" : "2");
    if (uses_verts(v)) d.emplace_back("AL_MAX_VERTS", std::to_string(v.verts));
    if (uses_nodes(v)) d.emplace_back("AL_NODES", std::to_string(v.nodes));
    d.emplace_back("AL_PRECISION_FP64", effective_precision(v) == Precision::Fp64 ? "1" : "0");
    if (uses_peak_keys(v)) {
        if (v.fit == Fit::Paper) d.emplace_back("AL_FIT_PAPER", "1");
        if (v.specular == SpecularForm::Sg) d.emplace_back("AL_SPECULAR_SG", "1");
    }
    return d;
}

bool variant_matches(const Variant& v, const std::string& pattern) {
    std::string why;
    auto pairs = split(pattern, why);
    if (!pairs) return false;
    for (const auto& [key, value] : *pairs) {
        std::string actual;
        if (key == "dist")
            actual = to_string(v.dist);
        else if (key == "method")
            actual = to_string(v.method);
        else if (key == "light")
            actual = to_string(v.light);
        else if (key == "sided")
            actual = to_string(v.sided);
        else if (key == "verts" && uses_verts(v))
            actual = std::to_string(v.verts);
        else if (key == "nodes" && uses_nodes(v))
            actual = std::to_string(v.nodes);
        else if (key == "precision")
            actual = to_string(effective_precision(v));
        else if (key == "fit" && uses_peak_keys(v))
            actual = to_string(v.fit);
        else if (key == "specular" && uses_peak_keys(v))
            actual = to_string(v.specular);
        else
            return false;  // unknown, or a key this variant has no value for
        if (actual != value) return false;
    }
    return true;
}

}  // namespace arealight
