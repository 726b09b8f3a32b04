// The variant space as two tables, and the functions that loop over them: a key
// table (one row per key: its values, default, field, #define and doc) and a family
// table (one row per implemented (dist, method, light): the keys it uses, the values
// of each, and its templates). Adding a key or a family is a row here (and, for a
// key, its typed field in Variant); parsing, validity, canonical names, enumeration,
// defines, pattern matching and every error message follow from the rows.
#include "ascii_upper.hpp"
#include "arealight/variant.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <iterator>
#include <map>
#include <type_traits>

namespace arealight {
namespace {

const Distribution kDists[] = {Distribution::Phong, Distribution::Blinn, Distribution::Beckmann,
                               Distribution::Ggx};
const Method kMethods[] = {Method::Exact,     Method::Arvo, Method::Lorentz, Method::Pearson,
                           Method::Ellipsoid, Method::Ltc,  Method::Mrp,    Method::Point};
const LightType kLights[] = {LightType::Polygon, LightType::Disk, LightType::Sphere,
                             LightType::Ellipsoid};
const Sided kSided[] = {Sided::Any, Sided::One, Sided::Two};
const Precision kPrecisions[] = {Precision::Fp64, Precision::Fp32, Precision::Fp16};
const Fit kFits[] = {Fit::Tuned, Fit::Paper};
const SpecularForm kSpecularForms[] = {SpecularForm::TwoAxis, SpecularForm::Sg};
const Split kSplits[] = {Split::None, Split::Single, Split::Halved};
const Factor kFactors[] = {Factor::Closest, Factor::Blend};
const Horizon kHorizons[] = {Horizon::Clip, Horizon::Proxy};
const Edge kEdges[] = {Edge::Acos, Edge::Poly};
const Table kTables[] = {Table::Texture, Table::Fit};
const Orient kOrients[] = {Orient::Rim, Orient::Paper};

// How a key's effective value becomes a preprocessor switch.
struct DefineRule {
    enum class Form {
        None,    // no define
        OneHot,  // NAME<VALUE> 1, the value upper-cased (AL_METHOD_EXACT 1)
        Number,  // NAME <value> (AL_NODES 16)
        Mapped,  // NAME <map[value]>; a value the map does not list defines nothing
    };
    Form form = Form::None;
    std::string name;
    std::vector<std::pair<std::string, std::string>> map;
};
DefineRule one_hot(const char* prefix) {
    return {DefineRule::Form::OneHot, prefix, {}};
}
DefineRule number(const char* name) {
    return {DefineRule::Form::Number, name, {}};
}
DefineRule mapped(const char* name, std::vector<std::pair<std::string, std::string>> map) {
    return {DefineRule::Form::Mapped, name, std::move(map)};
}
// A boolean feature: defined (as 1) only when on.
DefineRule flag(const char* name, const char* on_value) {
    return mapped(name, {{on_value, "1"}});
}


std::optional<std::pair<std::string, std::string>> define_of(const DefineRule& rule,
                                                             const std::string& value) {
    switch (rule.form) {
        case DefineRule::Form::None:
            return std::nullopt;
        case DefineRule::Form::OneHot:
            return std::make_pair(rule.name + ascii_upper(value), std::string("1"));
        case DefineRule::Form::Number:
            return std::make_pair(rule.name, value);
        case DefineRule::Form::Mapped:
            for (const auto& [from, to] : rule.map)
                if (from == value) return std::make_pair(rule.name, to);
            return std::nullopt;
    }
    return std::nullopt;
}

std::string value_string(int x) {
    return std::to_string(x);
}
template <class T>
std::string value_string(T x) {
    return to_string(x);
}

// One row of the key table.
struct KeyRow {
    std::string name;
    std::vector<std::string> values;  // every accepted value, in enumeration and message order
    bool numeric = false;             // an integer: "08" reads as 8; "value 'x' is not one of"
    bool required = false;            // dist, method, light: no default, always named
    std::function<std::string(const Variant&)> get;
    std::function<void(Variant&, const std::string&)> set;  // a value from `values`
    DefineRule define;
    // The effective value of a variant whose family does not use the key, where it
    // has one (precision: fp32); without it such a variant has no value for the key.
    std::optional<std::string> unused_value;
    std::string doc;
    std::string default_value;  // get(Variant{}): the field's initialiser is the default
    // Where the key applies, declared, as (required key, values): for a key every
    // family uses today but that belongs to some of them only (verts: polygons), so
    // that a name without a family (light=disk) is told so. Without it, where it
    // applies is derived from the families that name it.
    std::vector<std::pair<std::string, std::vector<std::string>>> where;

    KeyRow unused_as(const char* value) && {
        unused_value = value;
        return std::move(*this);
    }
    KeyRow only_where(const char* key, std::vector<std::string> values) && {
        where.emplace_back(key, std::move(values));
        return std::move(*this);
    }
};

// A row for `field` of Variant over `values` (enumerators or integers, in order).
template <class T, std::size_t N>
KeyRow key(const char* name, T Variant::*field, const T (&values)[N], DefineRule define,
           const char* doc) {
    KeyRow r;
    r.name = name;
    for (const T& x : values) r.values.push_back(value_string(x));
    r.numeric = std::is_same_v<T, int>;
    r.get = [field](const Variant& v) { return value_string(v.*field); };
    r.set = [field, list = std::vector<T>(std::begin(values), std::end(values))](
                Variant& v, const std::string& s) {
        for (const T& x : list)
            if (value_string(x) == s) v.*field = x;
    };
    r.define = std::move(define);
    r.doc = doc;
    r.default_value = r.get(Variant{});
    return r;
}
template <class T, std::size_t N>
KeyRow required_key(const char* name, T Variant::*field, const T (&values)[N], DefineRule define,
                    const char* doc) {
    KeyRow r = key(name, field, values, std::move(define), doc);
    r.required = true;
    r.default_value.clear();
    return r;
}

// The key table, in canonical-name order (which is also the enumeration order: the
// first further key varies slowest). A new key: a field in Variant, initialised to
// its default, and a row here; the family rows then name it where it applies.
// verts: the templates size their per-vertex arrays by AL_MAX_VERTS: quads (triangles
// too) and the contract's maximum. A quad's arrays save VGPRs (phong lorentz 144 -> 128,
// 6 -> 8 waves per SIMD, navi21); the sizes between bought little and each doubled the
// variants, and a triangle size saved at most 3% of a wave's cycles and no wave per SIMD
// but Arvo's (12 -> 14) against verts=4 (arealight gpu-cost, 2026-12-06).
// nodes: 24 was dominated by 16 at both precisions (phong exact: the same error, 1.15e-6
// fp64 and 3.84e-6 fp32, at 39% and 33% more cycles a wave). Phong exact: 12 gave way to 6
// (12: 3.9e-6 fp32, 8: 5.3e-6, at 24% more cycles): nodes=6 fp32 keeps specular relL2 within
// 1e-4 on the typical, horizon, glossy and degenerate sets but 5.6e-3 on stress (8: 5.9e-4)
// and one large glossy quad 5.8% off (8: 0.09%), at 6 454 cycles a wave against 7 348.
std::vector<KeyRow> key_rows() {
    // clang-format off
    return {
        //           name         Variant field          values          #define
        required_key("dist",      &Variant::dist,        kDists,         one_hot("AL_DIST_"),
                     "microfacet distribution (contract-fixed)"),
        required_key("method",    &Variant::method,      kMethods,       one_hot("AL_METHOD_"),
                     "how the integral is computed: exact quadrature reference, arvo's "
                     "recurrence, lorentz/pearson/ellipsoid peak functions, ltc (linearly "
                     "transformed cosines, fitted tables), mrp (representative point), point "
                     "baseline"),
        required_key("light",     &Variant::light,       kLights,        one_hot("AL_LIGHT_"),
                     "light shape"),
        key("sided",              &Variant::sided,       kSided,
            mapped("AL_SIDED", {{"any", "0"}, {"one", "1"}, {"two", "2"}}),
            "any: each case's two_sided flag at run time; one, two: compiled in"),
        key("verts",              &Variant::verts,       {4, 8},         number("AL_MAX_VERTS"),
            "largest polygon compiled in (sizes the per-vertex arrays)")
            .only_where("light", {"polygon"}),
        key("nodes",              &Variant::nodes,       {2, 3, 6, 8, 16}, number("AL_NODES"),
            "Gauss-Legendre quadrature nodes per edge (per piece of an arc, microfacets)"),
        key("precision",          &Variant::precision,   kPrecisions,
            mapped("AL_PRECISION_FP64", {{"fp64", "1"}, {"fp32", "0"}, {"fp16", "0"}}),
            "arithmetic precision of the shader math (fp32 where the family has no choice; "
            "fp16: half-precision edge integrals and horizon, method=ltc)")
            .unused_as("fp32"),
        key("fit",                &Variant::fit,         kFits,          flag("AL_FIT_PAPER", "paper"),
            "peak-function fitting recipe: tuned (ours) or paper (Lecocq et al. 2016 as printed)"),
        key("specular",           &Variant::specular,    kSpecularForms, flag("AL_SPECULAR_SG", "sg"),
            "double-axis moment: twoaxis (Arvo's relation) or sg (spherical Gaussians)"),
        key("radial",             &Variant::radial,      {2, 4, 16},     number("AL_RADIAL"),
            "radial Gauss-Legendre nodes of the exact microfacet specular rule"),
        key("split",              &Variant::split,       kSplits,        one_hot("AL_SPLIT_"),
            "microfacet peak methods: edge splits before the half-vector map: none, single "
            "(Lecocq et al. 2016, Algorithm 1) or halved (its point, then each piece halved)"),
        key("factor",             &Variant::factor,      kFactors,       one_hot("AL_FACTOR_"),
            "microfacet peak methods: half vector of the specular factor: closest (to n) or "
            "blend (with the vector irradiance's, by solid angle against the lobe's)"),
        key("horizon",            &Variant::horizon,     kHorizons,      one_hot("AL_HORIZON_"),
            "method=ltc: clip the transformed polygon to the horizon, or proxy (Hill 2016: "
            "a sphere with the same vector form factor, clipped by table)"),
        key("edge",               &Variant::edge,        kEdges,         one_hot("AL_EDGE_"),
            "method=ltc: edge integral theta / sin(theta) by acos, or poly (a polynomial "
            "in cos(theta), from the mobile LTC article)"),
        key("table",              &Variant::table,       kTables,        flag("AL_TABLE_FIT", "fit"),
            "method=ltc: coefficients from the fitted tables (texture, sampled bilinearly) or "
            "closed-form polynomials fitted to them (fit: no table, no sampler)"),
        key("proxy",              &Variant::proxy,       {4, 16},         number("AL_MAX_VERTS"),
            "curved lights through a polygon method: sides of the spinning proxy polygon "
            "(Lecocq et al. 2016 section 9)"),
        key("orient",             &Variant::orient,      kOrients,       one_hot("AL_ORIENT_"),
            "curved lights through a polygon method: the proxy's turn per shading point: rim "
            "(area-matched, an edge crossing the rim under the mirror ray) or paper (Lecocq et al. 2016 "
            "Algorithm 3, typos corrected)"),
    };
    // clang-format on
}

// The family table: one row per implemented (dist, method, light). keys: the further
// keys the family uses, each with the values enumerated for it, which are exactly
// the values valid for it ({} = every value of the key); a key it does not name
// stays at its default. templates: what it stitches, in order, between
// templates/common/common.glsl and (GLSL only) templates/entry.glsl. Boundary-integral
// methods share the per-arc geometry (<dist>_edge), then integrate each edge their
// own way; all but arvo (its own recurrence and accumulator) share the accumulator
// (<dist>_boundary); the polygon's clipping streams arcs into it, so it comes after.
std::vector<VariantFamily> family_rows() {
    using D = Distribution;
    using M = Method;
    using L = LightType;
    // clang-format off
    return {
        // dist     method        light       keys ({} = all values)
        //   templates
        {D::Phong, M::Exact,     L::Polygon, {{"sided"}, {"verts"}, {"nodes", {"6", "8", "16"}}, {"precision", {"fp64", "fp32"}}},
            {"dist/phong.glsl", "method/phong_edge.glsl", "method/phong_edge_rule.glsl", "method/exact_phong.glsl", "method/phong_boundary.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Phong, M::Arvo,      L::Polygon, {{"sided"}, {"verts"}},
            {"dist/phong.glsl", "method/phong_edge.glsl", "method/arvo_phong.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Phong, M::Lorentz,   L::Polygon, {{"sided"}, {"verts"}, {"fit"}, {"specular"}},
            {"dist/phong.glsl", "method/phong_edge.glsl", "common/gauss_legendre6.glsl", "method/phong_edge_rule.glsl", "common/erfcx.glsl", "method/phong_lobe_z.glsl", "method/peak_phong.glsl",
             "method/peak_lobe_edge.glsl", "method/phong_boundary.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Phong, M::Pearson,   L::Polygon, {{"sided"}, {"verts"}, {"fit"}, {"specular"}},
            {"dist/phong.glsl", "method/phong_edge.glsl", "common/gauss_legendre6.glsl", "method/phong_edge_rule.glsl", "common/erfcx.glsl", "method/phong_lobe_z.glsl", "method/peak_phong.glsl",
             "method/peak_lobe_edge.glsl", "method/phong_boundary.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Phong, M::Ellipsoid, L::Polygon, {{"sided"}, {"verts"}, {"fit"}, {"specular"}},
            {"dist/phong.glsl", "method/phong_edge.glsl", "common/gauss_legendre6.glsl", "method/phong_edge_rule.glsl", "common/erfcx.glsl", "method/phong_lobe_z.glsl", "method/peak_phong.glsl",
             "method/peak_lobe_edge.glsl", "method/phong_boundary.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Phong, M::Point,     L::Polygon, {{"sided"}, {"verts"}},
            {"dist/phong.glsl", "light/point_light.glsl", "light/polygon.glsl", "light/polygon_methods.glsl"}, {}, false},
        {D::Blinn, M::Exact, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"nodes", {"2", "3", "16"}}, {"precision", {"fp64", "fp32"}}, {"radial", {"2", "16"}}},
            {"dist/blinn.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/blinn_radial.glsl", "method/peak_rule.glsl", "method/exact_microfacet.glsl",
             "light/polygon.glsl",
             "light/polygon_methods.glsl"}},
        {D::Blinn, M::Point, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}},
            {"dist/blinn.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/microfacet_brdf.glsl", "light/point_light.glsl", "light/polygon.glsl", "light/polygon_methods.glsl"}, {}, false},
        {D::Beckmann, M::Exact, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"nodes", {"2", "3", "16"}}, {"precision", {"fp64", "fp32"}}, {"radial", {"2", "16"}}},
            {"dist/beckmann.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/beckmann_radial.glsl", "method/peak_rule.glsl", "method/exact_microfacet.glsl",
             "light/polygon.glsl",
             "light/polygon_methods.glsl"}},
        {D::Beckmann, M::Point, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}},
            {"dist/beckmann.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/microfacet_brdf.glsl", "light/point_light.glsl", "light/polygon.glsl", "light/polygon_methods.glsl"}, {}, false},
        {D::Ggx, M::Exact, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"nodes", {"2", "3", "16"}}, {"precision", {"fp64", "fp32"}}, {"radial", {"2", "16"}}},
            {"dist/ggx.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/ggx_radial.glsl", "method/peak_rule.glsl", "method/exact_microfacet.glsl",
             "light/polygon.glsl",
             "light/polygon_methods.glsl"}},
        {D::Ggx, M::Point, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}},
            {"dist/ggx.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "dist/microfacet_brdf.glsl", "light/point_light.glsl", "light/polygon.glsl", "light/polygon_methods.glsl"}, {}, false},
        {D::Blinn, M::Lorentz, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/blinn.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Blinn, M::Pearson, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/blinn.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Blinn, M::Ellipsoid, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/blinn.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Beckmann, M::Lorentz, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/beckmann.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Beckmann, M::Pearson, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/beckmann.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Beckmann, M::Ellipsoid, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/beckmann.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Ggx, M::Lorentz, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/ggx.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Ggx, M::Pearson, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/ggx.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        {D::Ggx, M::Ellipsoid, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"fit", {"tuned"}}, {"split", {"single", "halved"}}, {"factor"}},
            {"dist/ggx.glsl", "common/erfcx.glsl", "dist/microfacet.glsl", "method/phong_edge.glsl", "method/peak_phong.glsl", "method/peak_microfacet.glsl",
             "light/polygon.glsl", "light/polygon_methods.glsl"}},
        // LTC (Heitz et al. 2016): fitted tables sampled as textures (data/ltc/, arealight fit-ltc).
        {D::Phong, M::Ltc, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"precision", {"fp32", "fp16"}, "fp32"}, {"horizon"}, {"edge"}},
            {"light/polygon.glsl", "method/ltc.glsl"}, {"al_ltc_matrix", "al_ltc_amplitude"}, false},
        {D::Blinn, M::Ltc, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"precision", {"fp32", "fp16"}, "fp32"}, {"horizon"}, {"edge"}},
            {"light/polygon.glsl", "method/ltc.glsl"}, {"al_ltc_matrix", "al_ltc_amplitude"}, false},
        {D::Beckmann, M::Ltc, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"precision", {"fp32", "fp16"}, "fp32"}, {"horizon"}, {"edge"}},
            {"light/polygon.glsl", "method/ltc.glsl"}, {"al_ltc_matrix", "al_ltc_amplitude"}, false},
        // GGX also without tables: table=fit (templates/method/ltc_ggx_fit.glsl, scripts/fit_ltc_ggx_closed.py).
        {D::Ggx, M::Ltc, L::Polygon, {{"sided", {"any"}}, {"verts", {"8"}}, {"precision", {"fp32", "fp16"}, "fp32"}, {"horizon"}, {"edge"}, {"table"}},
            {"light/polygon.glsl", "method/ltc.glsl"}, {"al_ltc_matrix", "al_ltc_amplitude"}, false,
            {{"table", "fit", {"method/ltc_ggx_fit.glsl"}, true}}},
    };
    // clang-format on
}

// Curved lights (disk, sphere, ellipsoid; Lecocq et al. 2016 section 9). Each light's library
// entry reduces it to an ellipse (templates/light/ellipse_record.glsl); a polygon method
// then shades the spinning proxy polygon of that ellipse, so its family is the
// polygon family's row with the polygon keys (sided, verts) replaced by the proxy's
// (proxy, orient) and every other key held at its default. Phong offers the
// paper's form (proxy=4, orient=paper) beside ours; the microfacet methods only
// the default, which is what their error is measured for. The point baseline has
// its own template: the ellipse's centre and solid angle. LTC shades the ellipse
// itself (Heitz & Hill 2017: a linear map keeps it an ellipse; templates/method/ltc_ellipse.glsl)
// with the polygon LTC's tables, so it takes no proxy keys and no edge key. The exact
// methods shade the ellipse itself too (light/ellipse_clip.glsl, light/ellipse.glsl).
std::vector<VariantFamily> curved_rows(const std::vector<VariantFamily>& polygon_rows,
                                       const std::vector<KeyRow>& keys) {
    using L = LightType;
    auto default_of = [&](const FamilyKey& k) {
        if (!k.default_value.empty()) return k.default_value;
        for (const auto& row : keys)
            if (row.name == k.key) return row.default_value;
        return std::string();
    };
    std::vector<VariantFamily> out;
    for (L light : {L::Disk, L::Sphere, L::Ellipsoid}) {
        for (const auto& row : polygon_rows) {
            if (!is_peak_method(row.method) && row.method != Method::Ltc &&
                row.method != Method::Point && row.method != Method::Exact)
                continue;
            VariantFamily f = row;
            f.light = light;
            f.keys.clear();
            if (row.method == Method::Exact) {
                // The light's true boundary, clipped in closed form (light/ellipse_clip.glsl), at
                // the polygon family's default keys but precision (CI compiles every
                // variant).
                f.templates.clear();
                for (const auto& t : row.templates) {
                    if (t == "light/polygon_methods.glsl" || t == "method/peak_rule.glsl") continue;
                    if (t.rfind("method/exact_", 0) == 0) {
                        f.templates.push_back("light/conic.glsl");
                        f.templates.push_back("method/peak_rule.glsl");
                    }
                    f.templates.push_back(t);
                }
                f.templates.push_back("light/ellipse_clip.glsl");
                f.templates.push_back("light/ellipse.glsl");
                // fp32 beside the fp64 reference: what a GPU runs (fp64 is 1/16 rate or
                // less there) and what a scene's default quality may choose.
                for (const auto& k : row.keys) {
                    if (k.key == "sided" || k.key == "verts") continue;
                    const std::string d = default_of(k);
                    f.keys.emplace_back(k.key,
                                        k.key == "precision" ? std::vector<std::string>{"fp64", "fp32"}
                                                             : std::vector<std::string>{d},
                                        d);
                }
                out.push_back(std::move(f));
                continue;
            }
            if (row.method == Method::Point) {
                f.templates.clear();
                for (const auto& t : row.templates)
                    if (t != "light/polygon.glsl" && t != "light/polygon_methods.glsl") f.templates.push_back(t);
                f.templates.push_back("light/point_curved.glsl");
                out.push_back(std::move(f));
                continue;
            }
            if (row.method == Method::Ltc) {
                f.templates = {"method/ltc.glsl", "light/ellipse_cone.glsl", "method/ltc_ellipse.glsl"};
                f.keys = {FamilyKey("precision", {"fp32"}, "fp32"), FamilyKey("horizon")};
                // table=fit replaces the lookup and the proxy's table, which the
                // ellipse shares (its parts come with the row).
                if (row.dist == Distribution::Ggx) f.keys.emplace_back("table");
                out.push_back(std::move(f));
                continue;
            }
            const bool phong = row.dist == Distribution::Phong;
            f.keys.push_back(phong ? FamilyKey("proxy") : FamilyKey("proxy", {"16"}));
            f.keys.push_back(phong ? FamilyKey("orient") : FamilyKey("orient", {"rim"}));
            for (const auto& k : row.keys) {
                if (k.key == "sided" || k.key == "verts") continue;
                const std::string d = default_of(k);
                f.keys.emplace_back(k.key, std::vector<std::string>{d}, d);
            }
            out.push_back(std::move(f));
        }
    }
    return out;
}

// Representative-point shading (templates/method/mrp.glsl): every distribution and light,
// at one shape (sided=any, verts=8 for polygons; no key for curved lights), without the
// second quantity (ndf, moment), as the point baselines and ltc. Polygons stream the
// clipped boundary into the vector form factor (common/vector_form_factor.glsl, light/polygon.glsl);
// curved lights take their ellipse record's cone (light/ellipse_cone.glsl).
std::vector<VariantFamily> mrp_rows() {
    using D = Distribution;
    using L = LightType;
    std::vector<VariantFamily> out;
    for (L light : {L::Polygon, L::Disk, L::Sphere, L::Ellipsoid}) {
        for (D dist : kDists) {
            VariantFamily f{dist, Method::Mrp, light, {}, {}, {}, false};
            if (dist == D::Phong) {
                f.templates = {"dist/phong.glsl"};
            } else {
                f.templates = {std::string("dist/") + to_string(dist) + ".glsl", "common/erfcx.glsl", "dist/microfacet.glsl",
                               "dist/microfacet_brdf.glsl"};
            }
            f.templates.push_back("light/point_light.glsl");
            if (light == L::Polygon) {
                f.keys = {FamilyKey("sided", {"any"}), FamilyKey("verts", {"8"})};
                f.templates.push_back("common/vector_form_factor.glsl");
                f.templates.push_back("light/polygon.glsl");
            } else {
                f.templates.push_back("light/ellipse_cone.glsl");
            }
            f.templates.push_back("method/mrp.glsl");
            out.push_back(std::move(f));
        }
    }
    return out;
}

// Where a key applies, as the error messages name it: the row's declared `where`,
// else the smallest set of (dist, method, light) values, over as few of those keys
// as possible, whose families are exactly the ones that name the key (none: every
// family names it). It also decides, for a variant with no family (its name is
// rejected anyway), whether the key applies to it, so that such a name is told the
// nearer problem.
struct Scope {
    bool found = false;  // false: no such set (the text lists the families)
    std::vector<std::pair<std::size_t, std::vector<std::string>>> axes;  // key index, values
    std::string text;
};

struct Tables {
    std::vector<KeyRow> keys;
    std::vector<VariantFamily> families;  // key value lists resolved
    // uses[f][k]: family f's values of key k, or nullopt where it does not use it.
    std::vector<std::vector<std::optional<std::vector<std::string>>>> uses;
    // defaults[f][k]: family f's default of key k (its own where the row names one).
    std::vector<std::vector<std::string>> defaults;
    std::vector<Scope> scopes;  // per key
    std::vector<KeyInfo> info;
};

bool contains(const std::vector<std::string>& values, const std::string& x) {
    return std::find(values.begin(), values.end(), x) != values.end();
}

std::string join(const std::vector<std::string>& values, const char* sep = ", ") {
    std::string s;
    for (const auto& x : values) s += (s.empty() ? "" : sep) + x;
    return s;
}

Variant base_of(const VariantFamily& f) {
    Variant v;
    v.dist = f.dist;
    v.method = f.method;
    v.light = f.light;
    return v;
}

std::string family_name(const Variant& v) {
    return fmt::format("dist={},method={},light={}", to_string(v.dist), to_string(v.method),
                       to_string(v.light));
}

// "method=lorentz, pearson, ellipsoid", keys in table order joined by " and ".
std::string scope_text(const Tables& t, Scope& s) {
    std::sort(s.axes.begin(), s.axes.end());
    std::vector<std::string> parts;
    for (const auto& [axis, values] : s.axes)
        parts.push_back(t.keys[axis].name + "=" + join(values));
    return join(parts, " and ");
}

Scope scope_of(const Tables& t, std::size_t k) {
    std::vector<std::size_t> fixed;  // the required keys, most specific (latest) first
    for (std::size_t i = t.keys.size(); i-- > 0;)
        if (t.keys[i].required) fixed.push_back(i);
    std::vector<bool> in(t.families.size());
    for (std::size_t f = 0; f < t.families.size(); ++f) in[f] = t.uses[f][k].has_value();
    if (std::find(in.begin(), in.end(), true) == in.end()) return {false, {}, "no family"};
    Scope best;
    std::size_t best_axes = 0, best_cost = 0;
    // Fewest keys, then fewest values; on a tie the earlier mask (light, then method).
    for (unsigned mask = 0; mask < (1u << fixed.size()); ++mask) {
        Scope s;
        std::size_t cost = 0;
        for (std::size_t a = 0; a < fixed.size(); ++a) {
            if (!(mask & (1u << a))) continue;
            const KeyRow& axis = t.keys[fixed[a]];
            std::vector<std::string> values;
            for (const auto& x : axis.values) {
                for (std::size_t f = 0; f < t.families.size(); ++f)
                    if (in[f] && axis.get(base_of(t.families[f])) == x) {
                        values.push_back(x);
                        break;
                    }
            }
            cost += values.size();
            s.axes.emplace_back(fixed[a], std::move(values));
        }
        bool exact = true;
        for (std::size_t f = 0; f < t.families.size() && exact; ++f) {
            bool inside = true;
            for (const auto& [axis, values] : s.axes)
                inside = inside && contains(values, t.keys[axis].get(base_of(t.families[f])));
            exact = inside == in[f];
        }
        if (!exact) continue;
        if (best.found &&
            (s.axes.size() > best_axes || (s.axes.size() == best_axes && cost >= best_cost)))
            continue;
        s.found = true;
        best = std::move(s);
        best_axes = best.axes.size();
        best_cost = cost;
    }
    if (best.found) {
        best.text = scope_text(t, best);
    } else {
        std::vector<std::string> names;
        for (std::size_t f = 0; f < t.families.size(); ++f)
            if (in[f]) names.push_back(family_name(base_of(t.families[f])));
        best.text = join(names, "; ");
    }
    return best;
}

Scope declared_scope(const Tables& t, const KeyRow& row) {
    Scope s;
    s.found = true;
    for (const auto& [name, values] : row.where) {
        for (std::size_t i = 0; i < t.keys.size(); ++i)
            if (t.keys[i].name == name) s.axes.emplace_back(i, values);
    }
    s.text = scope_text(t, s);
    return s;
}

const Tables& tables() {
    static const Tables t = [] {
        Tables t;
        t.keys = key_rows();
        t.families = family_rows();
        for (auto& f : curved_rows(t.families, t.keys)) t.families.push_back(std::move(f));
        for (auto& f : mrp_rows()) t.families.push_back(std::move(f));
        for (auto& f : t.families) {
            for (auto& fk : f.keys) {
                for (const auto& row : t.keys)
                    if (row.name == fk.key && fk.values.empty()) fk.values = row.values;
            }
        }
        for (const auto& f : t.families) {
            std::vector<std::optional<std::vector<std::string>>> uses(t.keys.size());
            std::vector<std::string> defaults(t.keys.size());
            for (std::size_t k = 0; k < t.keys.size(); ++k) defaults[k] = t.keys[k].default_value;
            for (const auto& fk : f.keys) {
                for (std::size_t k = 0; k < t.keys.size(); ++k) {
                    if (t.keys[k].name != fk.key) continue;
                    uses[k] = fk.values;
                    if (!fk.default_value.empty()) defaults[k] = fk.default_value;
                }
            }
            t.uses.push_back(std::move(uses));
            t.defaults.push_back(std::move(defaults));
        }
        for (std::size_t k = 0; k < t.keys.size(); ++k) {
            const KeyRow& row = t.keys[k];
            t.scopes.push_back(row.required ? Scope{true, {}, ""} : scope_of(t, k));
            if (!row.where.empty()) t.scopes.back() = declared_scope(t, row);
            t.info.push_back({row.name, row.values, row.default_value, row.required, row.doc,
                              t.scopes.back().text});
        }
        return t;
    }();
    return t;
}

std::optional<std::size_t> key_index(const std::string& name) {
    const auto& keys = tables().keys;
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (keys[k].name == name) return k;
    return std::nullopt;
}

std::optional<std::size_t> family_index(const Variant& v) {
    const auto& families = tables().families;
    for (std::size_t f = 0; f < families.size(); ++f) {
        const auto& row = families[f];
        if (row.dist == v.dist && row.method == v.method && row.light == v.light) return f;
    }
    return std::nullopt;
}

// Whether key k is one the variant uses: its family names it; without a family,
// whether the variant lies in the key's scope.
bool applies(const Variant& v, std::size_t k) {
    const Tables& t = tables();
    if (t.keys[k].required) return true;
    if (auto f = family_index(v)) return t.uses[*f][k].has_value();
    const Scope& s = t.scopes[k];
    if (!s.found) return false;
    for (const auto& [axis, values] : s.axes)
        if (!contains(values, t.keys[axis].get(v))) return false;
    return true;
}

// The value the variant has for key k: its field where the key applies, else the
// key's unused value where it has one.
std::optional<std::string> effective_value(const Variant& v, std::size_t k) {
    const KeyRow& row = tables().keys[k];
    if (applies(v, k)) return row.get(v);
    return row.unused_value;
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

// The value as the key spells it ("08" is 8 for a number), or nullopt.
std::optional<std::string> accept(const KeyRow& row, const std::string& value) {
    std::string s = value;
    if (row.numeric) {
        auto n = parse_int(value);
        if (!n) return std::nullopt;
        s = std::to_string(*n);
    }
    if (!contains(row.values, s)) return std::nullopt;
    return s;
}

std::string bad_value(const KeyRow& row, const std::string& value) {
    if (row.numeric)
        return fmt::format("key '{}': value '{}' is not one of {}", row.name, value,
                           join(row.values));
    return fmt::format("key '{}': unknown value '{}' (expected {})", row.name, value,
                       join(row.values));
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

bool Variant::operator==(const Variant& o) const {
    for (const auto& row : tables().keys)
        if (row.get(*this) != row.get(o)) return false;
    return true;
}

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
        case Method::Ltc:
            return "ltc";
        case Method::Mrp:
            return "mrp";
        case Method::Point:
            return "point";
    }
    return "exact";
}
const char* to_string(Horizon h) {
    return h == Horizon::Clip ? "clip" : "proxy";
}
const char* to_string(Edge e) {
    return e == Edge::Acos ? "acos" : "poly";
}
const char* to_string(Table t) {
    return t == Table::Texture ? "texture" : "fit";
}
const char* to_string(Orient o) {
    return o == Orient::Rim ? "rim" : "paper";
}
const char* to_string(Fit f) {
    return f == Fit::Tuned ? "tuned" : "paper";
}
const char* to_string(SpecularForm s) {
    return s == SpecularForm::TwoAxis ? "twoaxis" : "sg";
}
const char* to_string(Split s) {
    switch (s) {
        case Split::None:
            return "none";
        case Split::Single:
            return "single";
        case Split::Halved:
            return "halved";
    }
    return "halved";
}
const char* to_string(Factor f) {
    return f == Factor::Closest ? "closest" : "blend";
}
bool is_peak_method(Method m) {
    return m == Method::Lorentz || m == Method::Pearson || m == Method::Ellipsoid;
}
const char* to_string(Precision p) {
    switch (p) {
        case Precision::Fp64:
            return "fp64";
        case Precision::Fp32:
            return "fp32";
        case Precision::Fp16:
            return "fp16";
    }
    return "fp32";
}
Precision effective_precision(const Variant& v) {
    static const std::size_t k = *key_index("precision");
    const auto value = effective_value(v, k);
    for (Precision p : kPrecisions)
        if (value && *value == to_string(p)) return p;
    return Precision::Fp32;
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

const std::vector<KeyInfo>& variant_keys() {
    return tables().info;
}

const std::vector<VariantFamily>& variant_families() {
    return tables().families;
}

const VariantFamily* find_family(const Variant& v) {
    const auto f = family_index(v);
    return f ? &tables().families[*f] : nullptr;
}

namespace {
// The parts of the key values the variant has (VariantFamily::parts).
std::vector<const FamilyKeyParts*> parts_of(const Variant& v, const VariantFamily& f) {
    std::vector<const FamilyKeyParts*> out;
    for (const auto& part : f.parts) {
        const auto k = key_index(part.key);
        if (!k) continue;
        const auto value = effective_value(v, *k);
        if (value && *value == part.value) out.push_back(&part);
    }
    return out;
}
}  // namespace

std::vector<std::string> variant_family_templates(const Variant& v) {
    const VariantFamily* f = find_family(v);
    if (!f) return {};
    std::vector<std::string> out;
    for (const auto* part : parts_of(v, *f))
        out.insert(out.end(), part->templates.begin(), part->templates.end());
    out.insert(out.end(), f->templates.begin(), f->templates.end());
    return out;
}

std::vector<std::string> variant_samplers(const Variant& v) {
    const VariantFamily* f = find_family(v);
    if (!f) return {};
    for (const auto* part : parts_of(v, *f))
        if (part->without_samplers) return {};
    return f->samplers;
}

std::string sampler_table_id(const Variant& v, const std::string& sampler) {
    return sampler + "/" + to_string(v.dist);
}

std::optional<Variant> parse_variant(const std::string& name, const DiagnosticConsumer& diag) {
    const Tables& t = tables();
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
        const auto k = key_index(key);
        if (!k) {
            std::vector<std::string> names;
            for (const auto& row : t.keys) names.push_back(row.name);
            return fail(fmt::format("unknown key '{}' (keys: {})", key, join(names)));
        }
        const auto spelled = accept(t.keys[*k], value);
        if (!spelled) return fail(bad_value(t.keys[*k], value));
        t.keys[*k].set(v, *spelled);
    }
    for (const auto& row : t.keys) {
        if (row.required && !seen.count(row.name))
            return fail(fmt::format("key '{}' is required", row.name));
    }
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        if (seen.count(t.keys[k].name) && !applies(v, k))
            return fail(
                fmt::format("key '{}' applies to {} only", t.keys[k].name, t.scopes[k].text));
    }
    const auto f = family_index(v);
    if (!f) return fail(fmt::format("no variant for {} yet", family_name(v)));
    // A key not named takes the family's default.
    for (std::size_t k = 0; k < t.keys.size(); ++k)
        if (!t.keys[k].required && !seen.count(t.keys[k].name) && t.uses[*f][k])
            t.keys[k].set(v, t.defaults[*f][k]);
    // A family may offer fewer values of a key than the key has.
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        const auto& values = t.uses[*f][k];
        const KeyRow& row = t.keys[k];
        if (!values || contains(*values, row.get(v))) continue;
        if (seen.count(row.name))
            return fail(fmt::format("key '{}': value '{}' is not offered for {} (expected {})",
                                    row.name, seen[row.name], family_name(v), join(*values)));
        return fail(
            fmt::format("key '{}' must be given for {}: its default {} is not offered "
                        "(expected {})",
                        row.name, family_name(v), t.defaults[*f][k], join(*values)));
    }
    return v;
}

bool is_valid(const Variant& v) {
    const Tables& t = tables();
    const auto f = family_index(v);
    if (!f) return false;
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        const KeyRow& row = t.keys[k];
        if (row.required) continue;
        const auto& values = t.uses[*f][k];
        const std::string value = row.get(v);
        if (values ? !contains(*values, value) : value != row.default_value) return false;
    }
    return true;
}

std::string canonical_name(const Variant& v) {
    const Tables& t = tables();
    std::string s = family_name(v);
    const auto f = family_index(v);
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        const KeyRow& row = t.keys[k];
        if (row.required || !applies(v, k)) continue;
        const std::string value = row.get(v);
        const std::string& fallback = f ? t.defaults[*f][k] : row.default_value;
        if (value != fallback) s += fmt::format(",{}={}", row.name, value);
    }
    return s;
}

std::vector<Variant> enumerate_variants() {
    const Tables& t = tables();
    std::vector<Variant> out;
    for (std::size_t f = 0; f < t.families.size(); ++f) {
        // The family's keys in table order; the last varies fastest.
        std::vector<std::pair<const KeyRow*, const std::vector<std::string>*>> axes;
        for (std::size_t k = 0; k < t.keys.size(); ++k)
            if (t.uses[f][k]) axes.emplace_back(&t.keys[k], &*t.uses[f][k]);
        std::vector<std::size_t> at(axes.size(), 0);
        for (;;) {
            Variant v = base_of(t.families[f]);
            for (std::size_t a = 0; a < axes.size(); ++a)
                axes[a].first->set(v, (*axes[a].second)[at[a]]);
            out.push_back(v);
            std::size_t a = axes.size();
            while (a > 0 && ++at[a - 1] == axes[a - 1].second->size()) at[--a] = 0;
            if (a == 0) break;
        }
    }
    return out;
}

std::vector<std::pair<std::string, std::string>> variant_defines(const Variant& v) {
    const Tables& t = tables();
    std::vector<std::pair<std::string, std::string>> d;
    for (std::size_t k = 0; k < t.keys.size(); ++k) {
        const auto value = effective_value(v, k);
        if (!value) continue;
        if (auto define = define_of(t.keys[k].define, *value)) d.push_back(std::move(*define));
    }
    return d;
}

bool variant_matches(const Variant& v, const std::string& pattern) {
    std::string why;
    auto pairs = split(pattern, why);
    if (!pairs) return false;
    for (const auto& [key, value] : *pairs) {
        const auto k = key_index(key);
        if (!k) return false;
        // As parse_variant reads it: "nodes=08" is nodes=8.
        const auto spelled = accept(tables().keys[*k], value);
        const auto actual = effective_value(v, *k);
        if (!spelled || !actual || *actual != *spelled) return false;  // or a key it has no value for
    }
    return true;
}

}  // namespace arealight
