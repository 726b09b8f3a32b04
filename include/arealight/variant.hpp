// The variant key as a value type: named fields with defaults, a canonical
// printed form, validity rules, and enumeration of every valid combination
// (ROADMAP.md "The variant space").
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"

namespace arealight {

// exact: in-shader accuracy reference (quadrature); arvo: Arvo's O(N) recurrence
// for integer exponents (the paper's reference cost); lorentz, pearson, ellipsoid:
// seed 000's O(1) peak functions; ltc: linearly transformed cosines (Heitz et al.
// 2016, seed 001) with arealight's own fitted tables; mrp: representative-point
// shading as engines ship it (Karis 2013, Drobot 2014) with exact closed-form diffuse;
// point: the point-light baseline of every speed ratio.
enum class Method { Exact, Arvo, Lorentz, Pearson, Ellipsoid, Ltc, Mrp, Point };
// Peak-function fitting recipe: tuned (default: fit points, shape parameters and
// near/far forms of our own, templates/method/peak_phong.glsl) or paper (seed 000
// eq. 7, 13-14, 17-18 as printed, parity labels corrected).
enum class Fit { Tuned, Paper };
// How a peak method forms the double-axis (specular) moment: twoaxis (Arvo's exact
// two-axis relation over the same edge integrals) or sg (seed 000 section 7.1: the
// product of the two cosine lobes as one lobe through spherical Gaussians).
enum class SpecularForm { TwoAxis, Sg };
// Any honours each case's two_sided flag at run time; One and Two compile it in.
enum class Sided { Any, One, Two };
// Arithmetic precision of the shader math. method=exact, the in-shader accuracy
// reference, defaults to fp64 (fp32 input rounding then dominates its error) and
// offers fp32; method=ltc defaults to fp32 and offers fp16 (seed 001: the edge
// integrals and the horizon in half precision); every other method is fp32 only.
enum class Precision { Fp32, Fp64, Fp16 };
// Microfacet peak methods (templates/method/peak_microfacet.glsl): how each edge of the
// lit region is split before its points are mapped to half vectors: none, single
// (seed 000 Algorithm 1: at the foot of r, where it lies inside the edge) or halved
// (that point, then each piece halved: at most 3 splits).
enum class Split { None, Single, Halved };
// Microfacet peak methods: the representative half vector at which G2, the Jacobian
// and Fresnel turn ndf into specular: closest (the h-polygon's point closest to n) or
// blend (that point blended with the half vector of the lit region's vector
// irradiance by the light's solid angle against the lobe's).
enum class Factor { Closest, Blend };
// method=ltc: how the transformed polygon meets the horizon: clip (exactly, before
// the edge integrals) or proxy (seed 001: no clipping; the unclipped vector form
// factor's length and direction give a sphere whose clipped form factor is read
// from a table).
enum class Horizon { Clip, Proxy };
// method=ltc: the edge integral's theta / sin(theta) by acos (exact) or by a
// polynomial in cos(theta) (seed 001, fp16-friendly).
enum class Edge { Acos, Poly };
// method=ltc (GGX): where the fitted coefficients come from: texture (the two 64 x 64
// tables, sampled bilinearly) or fit (closed-form polynomials of the same grid
// coordinates, templates/method/ltc_ggx_fit.glsl from scripts/fit_ltc_ggx_closed.py, and the
// horizon proxy's closed form: no table, no sampler).
enum class Table { Texture, Fit };
// Curved lights through a polygon method (seed 000 section 9, the spinning polygon):
// how the proxy regular polygon is turned at each shading point. rim: area-matched,
// one edge crossing the light's rim where the mirror ray meets the light's plane;
// paper: Algorithm 3 with its typos corrected (templates/light/spin_polygon.glsl).
enum class Orient { Rim, Paper };

// One shader variant. Each key of the key table (variant_keys()) is a typed field
// here, initialised to the key's default; which keys a variant uses, and which of
// their values, is its family's row (variant_families()).
struct Variant {
    Distribution dist = Distribution::Phong;
    Method method = Method::Exact;
    LightType light = LightType::Polygon;
    Sided sided = Sided::Any;
    int verts = 8;   // polygon: largest polygon compiled in: 4 or 8
    int nodes = 16;  // method=exact: Gauss-Legendre nodes per edge (per arc piece, microfacets)
    Precision precision = Precision::Fp64;          // method=exact: fp64 or fp32
    Fit fit = Fit::Tuned;                           // peak methods
    SpecularForm specular = SpecularForm::TwoAxis;  // peak methods
    int radial = 16;  // exact microfacets: radial Gauss-Legendre nodes of the specular rule
    Split split = Split::Halved;     // microfacet peak methods
    Factor factor = Factor::Blend;   // microfacet peak methods
    Horizon horizon = Horizon::Clip;  // method=ltc
    Edge edge = Edge::Acos;           // method=ltc
    Table table = Table::Texture;     // method=ltc, GGX
    int proxy = 16;                   // curved lights, polygon methods: proxy polygon's size
    Orient orient = Orient::Rim;      // curved lights, polygon methods: its orientation rule

    // Equal when every key of the key table has the same value (a field that no
    // key row reads would not count: each field is a row).
    bool operator==(const Variant& o) const;
    bool operator!=(const Variant& o) const { return !(*this == o); }
};

const char* to_string(Method m);
const char* to_string(Sided s);
const char* to_string(Precision p);
const char* to_string(Fit f);
const char* to_string(SpecularForm s);
const char* to_string(Split s);
const char* to_string(Factor f);
const char* to_string(Horizon h);
const char* to_string(Edge e);
const char* to_string(Table t);
const char* to_string(Orient o);

// Whether the method is one of seed 000's peak functions (keys fit, specular).
bool is_peak_method(Method m);

// The precision a variant's shader computes in: its key where it has one, else fp32.
Precision effective_precision(const Variant& v);

// Parses "key=value,..."; dist, method and light are required, every other key
// has a default. Errors name the key (unknown, bad value, duplicate, missing,
// not applicable, a value its family does not offer) and the combination when it
// has no implementation.
std::optional<Variant> parse_variant(const std::string& name, const DiagnosticConsumer& diag);

// An implemented family, every key in range, and every key that does not apply
// left at its default, so that equal shaders compare equal and parse_variant
// returns exactly the valid variants.
bool is_valid(const Variant& v);

// dist, method, light, then the keys that apply and differ from their default.
// parse_variant(canonical_name(v)) == v for every valid v.
std::string canonical_name(const Variant& v);

// Every valid variant, in a fixed order, without duplicates.
std::vector<Variant> enumerate_variants();

// Preprocessor switches the templates see; a boolean feature only when on.
std::vector<std::pair<std::string, std::string>> variant_defines(const Variant& v);

// True when every key=value of `pattern` (a partial name; empty matches all)
// equals the variant's effective value, defaults included. A key the variant
// does not use (nodes for method=point) has no value and so never matches, except
// precision, whose effective value (effective_precision) every variant has; and
// an invalid pattern matches nothing.
bool variant_matches(const Variant& v, const std::string& pattern);

// Introspection of the two tables the functions above loop over.
//
// A key: every value it accepts (in enumeration and message order), its default
// (empty for the required keys dist, method and light), one line of doc, and the
// families it applies to as the error messages name them ("method=exact"; empty
// when every family uses it).
struct KeyInfo {
    std::string name;
    std::vector<std::string> values;
    std::string default_value;
    bool required = false;
    std::string doc;
    std::string applies_to;
};

// dist, method, light, then the further keys, in canonical-name order.
const std::vector<KeyInfo>& variant_keys();

// A (dist, method, light) with an implementation: the further keys it uses, each
// with the values enumerated for it (exactly the values valid for it, in the key's
// order), and the templates it stitches, in order, between templates/common/common.glsl
// and (GLSL only) templates/entry.glsl, as names inside templates/.
struct FamilyKey {
    // In the table, {} stands for every value of the key; variant_families() lists them.
    // default_value: the family's own default where the key's (KeyInfo) is not one it
    // offers (method=ltc's precision is fp32, not fp64); empty: the key's.
    FamilyKey(std::string key, std::vector<std::string> values = {},
              std::string default_value = {})
        : key(std::move(key)), values(std::move(values)), default_value(std::move(default_value)) {}
    std::string key;
    std::vector<std::string> values;
    std::string default_value;
};
// A key value that changes what a family stitches and samples (method=ltc's
// table=fit: closed-form code in place of the tables): its templates are stitched
// first (after templates/common/common.glsl), and without_samplers drops the family's samplers.
struct FamilyKeyParts {
    std::string key;
    std::string value;
    std::vector<std::string> templates;
    bool without_samplers = false;
};
struct VariantFamily {
    Distribution dist;
    Method method;
    LightType light;
    std::vector<FamilyKey> keys;
    std::vector<std::string> templates;
    // Tables the shader samples, in binding order from binding 2: sampler names as
    // the templates spell them. The stitcher declares them (GLSL: sampler2D uniforms;
    // C++: the mirror's samplers), the evaluator binds variant_textures().
    std::vector<std::string> samplers = {};
    // Whether the shader returns the quantity beside specular (ndf for microfacets,
    // moment for phong; CONTRACT.md 2): the point baselines and ltc do not.
    bool second_quantity = true;
    std::vector<FamilyKeyParts> parts = {};
};

const std::vector<VariantFamily>& variant_families();

// The family row of the variant's (dist, method, light), or nullptr when none.
const VariantFamily* find_family(const Variant& v);

// What the variant stitches between templates/common/common.glsl and the light's entry, and
// the tables it samples: its family's, with the parts of the key values it has
// (VariantFamily::parts). Empty for a variant without a family.
std::vector<std::string> variant_family_templates(const Variant& v);
std::vector<std::string> variant_samplers(const Variant& v);
// Which table a sampler of v reads: two samplers with the same id read byte-identical
// data (runtime/variant_textures.cpp: the LTC tables depend on the distribution alone),
// so a library declares and binds such a table once. "al_ltc_matrix/ggx".
std::string sampler_table_id(const Variant& v, const std::string& sampler);

}  // namespace arealight
