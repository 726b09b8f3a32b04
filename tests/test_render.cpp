// arealight render: the scene extras reader, the ray cast, PNG and PFM files, the false
// colour map and error image, and a rendering through the CPU mirror against the oracle.
#include <png.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "arealight/error_image.hpp"
#include "arealight/pfm_image.hpp"
#include "arealight/png_image.hpp"
#include "arealight/raycast.hpp"
#include "arealight/render.hpp"
#include "arealight/render_scene.hpp"
#include "arealight/scene_select.hpp"
#include "arealight/tone_map.hpp"

using namespace arealight;

namespace {

struct Collect {
    std::vector<std::string> messages;
    DiagnosticConsumer consumer() {
        return [this](const Diagnostic& d) { messages.push_back(d.message); };
    }
    bool has(const std::string& text) const {
        for (const auto& m : messages)
            if (m == text) return true;
        return false;
    }
    std::string all() const {
        std::string s;
        for (const auto& m : messages) s += m + "\n";
        return s;
    }
};

// A two-light scene (one one-sided, one two-sided polygon), GGX floor, Phong sphere.
const char* kScene = R"({
  "format": "arealight-scene/1",
  "lights": [
    {"type": "polygon", "vertices": [[-1, -0.5, 2], [-1, 0.5, 2], [1, 0.5, 2], [1, -0.5, 2]]},
    {"type": "polygon", "two_sided": true, "intensity": 0.5,
     "vertices": [[1.5, 1, 0.2], [1.5, 2, 0.2], [1.5, 2, 1.2]]}
  ],
  "materials": [{"distribution": "ggx", "alpha": 0.3}, {"distribution": "phong", "exponent": 20}],
  "camera": {"eye": [0, -4, 2], "target": [0, 0, 0.4], "up": [0, 0, 1], "fov_deg": 45},
  "objects": [
    {"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "material": 0, "albedo": [0.5, 0.5, 0.5]},
    {"type": "sphere", "center": [0, 0, 0.5], "radius": 0.5, "material": 1, "albedo": [0.8, 0.2, 0.1]},
    {"type": "box", "min": [-1.5, 0.5, 0], "max": [-0.8, 1.2, 0.6], "material": 0, "albedo": [0.1, 0.6, 0.2]}
  ]
})";

RenderScene scene_or_fail(const std::string& text) {
    Collect c;
    auto s = parse_render_scene(text, "scene.json", c.consumer());
    INFO(c.all());
    REQUIRE(s);
    return *s;
}

// The messages a scene with one substitution of kScene gives.
Collect errors_of(const std::string& from, const std::string& to) {
    std::string text = kScene;
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
    Collect c;
    CHECK_FALSE(parse_render_scene(text, "scene.json", c.consumer()));
    return c;
}

}  // namespace

TEST_CASE("render scene: camera, objects, lights and materials are read", "[render]") {
    const RenderScene s = scene_or_fail(kScene);
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[1].two_sided);
    CHECK(s.intensities == std::vector<double>{1.0, 0.5});
    REQUIRE(s.materials.size() == 2);
    CHECK(s.materials[0].distribution == Distribution::Ggx);
    CHECK(s.materials[0].alpha == 0.3);
    CHECK(s.camera.fov_deg == 45);
    REQUIRE(s.objects.size() == 3);
    CHECK(s.objects[1].type == ObjectType::Sphere);
    CHECK(s.objects[1].radius == 0.5);
    CHECK(s.objects[2].type == ObjectType::Box);
    CHECK(s.objects[2].material == 0);
}

TEST_CASE("render scene: errors name the file, the item and the field", "[render]") {
    // Each row: a substitution into kScene and the message it must produce. Lights,
    // materials and quality are read_scene's, the rest the renderer's.
    struct Row {
        const char *from, *to, *expected;
    };
    const Row rows[] = {
        {R"("camera": {"eye": [0, -4, 2], )", R"("cam": {"eye": [0, -4, 2], )",
         "scene.json: field 'camera': missing"},
        {R"("fov_deg": 45)", R"("fov_deg": 180)",
         "scene.json: camera: field 'fov_deg': 180 is outside (0, 180)"},
        {R"("up": [0, 0, 1])", R"("up": [0, 1, -0.4])",
         "scene.json: camera: field 'up': is parallel to the viewing direction (target - eye)"},
        {R"("radius": 0.5, "material": 1)", R"("radius": -1, "material": 1)",
         "scene.json: object 1: field 'radius': -1 is not positive"},
        {R"("material": 1, "albedo")", R"("material": 2, "albedo")",
         "scene.json: object 1: field 'material': 2 is not an index into materials (0 to 1)"},
        {R"("max": [-0.8, 1.2, 0.6])", R"("max": [-0.8, 0.5, 0.6])",
         "scene.json: object 2: field 'max': component 1 is 0.5, not above min's 0.5"},
        {R"("albedo": [0.8, 0.2, 0.1])", R"("albedo": [0.8, 1.2, 0.1])",
         "scene.json: object 1: field 'albedo': component 1 is 1.2, outside [0, 1]"},
        {R"({"type": "box")", R"({"type": "cone")",
         "scene.json: object 2: field 'type': is \"cone\", expected \"plane\", \"sphere\" or "
         "\"box\""},
        {R"("intensity": 0.5)", R"("intensity": -2)",
         "scene.json: light 1: field 'intensity': -2 is negative"},
        {"[1.5, 2, 1.2]", "[1.5, 2, 1.2], [1.5, 1.9, 0.6]",
         "scene.json: light 1: field 'vertices[3]': is a reflex corner: the polygon is not "
         "convex"},
        {R"("alpha": 0.3)", R"("alpha": 3)",
         "scene.json: material 0: field 'alpha': 3 is outside [0.001, 1]"},
        {R"("format": "arealight-scene/1",)",
         R"("format": "arealight-scene/1", "quality": {"max_error": -1},)",
         "scene.json: field 'quality.max_error': -1 is not a positive number"},
        {R"("format": "arealight-scene/1")", R"("format": "arealight-cases/1")",
         "scene.json: field 'format': is \"arealight-cases/1\", expected \"arealight-scene/1\""},
        // Unknown fields of the renderer's own objects, and of a light's renderer-only field.
        {R"("fov_deg": 45)", R"("fov_deg": 45, "fov_degs": 50)",
         "scene.json: camera: field 'fov_degs': unknown field (did you mean 'fov_deg'?)"},
        {R"("albedo": [0.1, 0.6, 0.2])", R"("albedo": [0.1, 0.6, 0.2], "albdo": 1)",
         "scene.json: object 2: field 'albdo': unknown field (did you mean 'albedo'?)"},
        {R"("intensity": 0.5)", R"("intensity": 0.5, "intensty": 1)",
         "scene.json: light 1: field 'intensty': unknown field (did you mean 'intensity'?)"},
    };
    for (const Row& r : rows) {
        const Collect c = errors_of(r.from, r.to);
        INFO("substituted " << r.to << "; got:\n" << c.all());
        CHECK(c.has(r.expected));
    }
}

TEST_CASE("render: the centre ray meets a sphere at its near pole", "[render]") {
    RenderScene s = scene_or_fail(kScene);
    s.camera = {{0, -4, 0.5}, {0, 0, 0.5}, {0, 0, 1}, 30};
    // 3x3: the centre pixel's ray is the camera's axis, through the sphere's centre.
    const auto hits = cast_camera_rays(s, 3, 3);
    const PixelHit& h = hits[4];
    REQUIRE(h.kind == PixelHit::Kind::Surface);
    CHECK(h.object == 1);
    constexpr double kHitTol = 1e-12;  // a few ulps of the ray's arithmetic
    CHECK(h.p[1] == Approx(-0.5).margin(kHitTol));
    CHECK(h.n[1] == Approx(-1).margin(kHitTol));
    CHECK(h.v[1] == Approx(-1).margin(kHitTol));
}

TEST_CASE("render: camera rays see disk, sphere and ellipsoid lights", "[render]") {
    // Three curved lights centred on the line y = 2, z = 0, the disk facing the camera
    // at the origin, which looks along +y; each pixel ray is aimed at a known point, and the ray's hit is
    // checked against the light's own equation.
    const RenderScene base = scene_or_fail(R"({
      "format": "arealight-scene/1",
      "lights": [
        {"type": "disk", "center": [-1, 2, 0], "u": [0, 0, 0.4], "v": [-0.2, 0, 0]},
        {"type": "sphere", "center": [0, 2, 0], "radius": 0.3},
        {"type": "ellipsoid", "center": [1, 2, 0],
         "axes": [[0.3, 0.3, 0], [-0.1, 0.1, 0], [0, 0, 0.2]]}
      ],
      "materials": [{"distribution": "ggx", "alpha": 0.3}],
      "camera": {"eye": [0, 0, 0], "target": [0, 1, 0], "up": [0, 0, 1], "fov_deg": 90},
      "objects": []
    })");
    // One pixel's ray through the point (x, 1, z) of the image plane at distance 1:
    // a 1x1 image with the camera turned towards that point.
    auto seen = [&](Vec3 target) {
        RenderScene s = base;
        s.camera.target = target;
        return cast_camera_rays(s, 1, 1)[0];
    };
    struct Probe {
        const char* what;
        Vec3 target;
        int light;  // -1: nothing
    };
    const Probe probes[] = {
        {"disk centre", {-1, 2, 0}, 0},
        {"inside the disk along u", {-1, 2, 0.39}, 0},
        {"outside the disk along u", {-1, 2, 0.41}, -1},
        {"outside the disk along v", {-1.21, 2, 0}, -1},
        {"sphere centre", {0, 2, 0}, 1},
        {"inside the sphere's silhouette", {0, 2, 0.29}, 1},
        {"outside the sphere's silhouette", {0, 2, 0.32}, -1},
        // Its long axis points nearly at the eye: seen from there its silhouette spans
        // x in (0.8, 1.2) at z = 0 and |z| < 0.2 about the axis (found by the quadratic
        // for the ray, worked separately).
        {"ellipsoid centre", {1, 2, 0}, 2},
        {"inside the ellipsoid's silhouette, off centre", {1.1, 2, 0}, 2},
        {"beside it, right", {1.3, 2, 0}, -1},
        {"beside it, left", {0.7, 2, 0}, -1},
        {"inside, along the third axis", {1, 2, 0.19}, 2},
        {"above it", {1, 2, 0.23}, -1},
    };
    for (const Probe& pr : probes) {
        INFO(pr.what);
        const PixelHit h = seen(pr.target);
        if (pr.light < 0) {
            CHECK(h.kind == PixelHit::Kind::Background);
            continue;
        }
        REQUIRE(h.kind == PixelHit::Kind::Light);
        CHECK(h.light == pr.light);
    }
    // A one-sided disk is not seen from behind; two-sided it is.
    RenderScene behind = base;
    behind.lights[0].u = {0, 0, 0.2};
    behind.lights[0].v = {0.4, 0, 0};  // u x v = (0, 0.08, 0): emits away from the camera
    behind.camera.target = {-1, 2, 0};
    CHECK(cast_camera_rays(behind, 1, 1)[0].kind == PixelHit::Kind::Background);
    behind.lights[0].two_sided = true;
    CHECK(cast_camera_rays(behind, 1, 1)[0].kind == PixelHit::Kind::Light);
}

TEST_CASE("render: PNG round trip through libpng", "[render]") {
    Image8 img;
    img.width = 5;
    img.height = 3;
    for (int i = 0; i < 45; ++i) img.rgb.push_back(static_cast<std::uint8_t>(i * 37 % 256));
    Collect c;
    auto bytes = encode_png(img, "t.png", c.consumer());
    INFO(c.all());
    REQUIRE(bytes);
    png_image back;
    std::memset(&back, 0, sizeof back);
    back.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_memory(&back, bytes->data(), bytes->size()));
    CHECK(back.width == 5);
    CHECK(back.height == 3);
    back.format = PNG_FORMAT_RGB;
    std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(back));
    REQUIRE(png_image_finish_read(&back, nullptr, pixels.data(), 0, nullptr));
    CHECK(pixels == img.rgb);

    Image8 wrong = img;
    wrong.rgb.pop_back();
    CHECK_FALSE(encode_png(wrong, "t.png", c.consumer()));
    CHECK(c.has("t.png: cannot encode PNG: the image is empty or its pixels do not match its size"));
}

TEST_CASE("render: PFM round trip and a truncated file", "[render]") {
    LinearImage img;
    img.width = 2;
    img.height = 3;
    img.rgb = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 1e-30f, 1e30f, -1};
    img.rgb.resize(18);
    const std::string bytes = format_pfm(img);
    CHECK(bytes.rfind("PF\n2 3\n-1.0\n", 0) == 0);
    Collect c;
    auto back = parse_pfm(bytes, "t.pfm", c.consumer());
    INFO(c.all());
    REQUIRE(back);
    CHECK(back->width == 2);
    CHECK(back->height == 3);
    CHECK(back->rgb == img.rgb);
    CHECK_FALSE(parse_pfm(bytes.substr(0, bytes.size() - 4), "t.pfm", c.consumer()));
    CHECK(c.has("t.pfm: not a colour PFM: 68 bytes of pixels, expected 72 for 2x3"));
}

TEST_CASE("render: sRGB encoding, tone map and false colour endpoints", "[render]") {
    CHECK(srgb8(0.0) == 0);
    CHECK(srgb8(-1.0) == 0);
    CHECK(srgb8(1.0) == 255);
    CHECK(srgb8(7.0) == 255);
    CHECK(srgb8(0.5) == 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
    LinearImage two;
    two.width = 2;
    two.height = 1;
    two.rgb = {0.25f, 2.0f, 0.0f, 0.5f, NAN, 0.5f};
    const Image8 shown = tone_map(two, 2.0);
    // Exposure 2: 0.25 shows as 0.5; a NaN channel makes the pixel magenta.
    CHECK(shown.rgb == std::vector<std::uint8_t>{188, 255, 0, 255, 0, 255});
    using C = std::array<std::uint8_t, 3>;
    CHECK(false_colour(0.0) == C{68, 1, 84});
    CHECK(false_colour(-3.0) == C{68, 1, 84});
    CHECK(false_colour(1.0) == C{253, 231, 37});
    CHECK(false_colour(9.0) == C{253, 231, 37});
    CHECK(false_colour(NAN) == C{253, 231, 37});
    CHECK(false_colour(0.5) == C{33, 144, 141});
}

TEST_CASE("render: image error numbers and the false-colour picture", "[render]") {
    LinearImage ref, img;
    ref.width = img.width = 4;
    ref.height = img.height = 2;
    ref.rgb.assign(24, 1.0f);
    img.rgb.assign(24, 1.0f);
    // Pixel 0 off by 1e-2 (the middle of the 1e-4 .. 1 bar), pixel 1 by 1 (its top).
    for (int k = 0; k < 3; ++k) img.rgb[k] = 1.01f, img.rgb[3 + k] = 2.0f;
    ErrorScale scale;
    Collect c;
    auto e = compare_images(img, ref, scale, c.consumer());
    REQUIRE(e);
    constexpr double kFloatTol = 1e-6;  // the images hold floats
    CHECK(e->max == Approx(1.0).epsilon(kFloatTol));
    CHECK(e->rel_l2 == Approx(std::sqrt((1e-4 + 1.0) / 8.0)).epsilon(kFloatTol));
    CHECK(e->median == 0.0);
    CHECK(e->pixels == 8);

    const Image8 pic = error_image(img, ref, scale);
    CHECK(pic.width == 4);
    CHECK(pic.height == 2 + kLegendHeight);
    using C = std::array<std::uint8_t, 3>;
    auto at = [&](int x, int y) {
        const std::uint8_t* p = &pic.rgb[(static_cast<std::size_t>(y) * pic.width + x) * 3];
        return C{p[0], p[1], p[2]};
    };
    // 1.01f is not exactly 1.01: its error lies within a colour step of the middle stop.
    const C mid = at(0, 0);
    CHECK(std::abs(mid[1] - 144) <= 1);
    CHECK(at(1, 0) == C{253, 231, 37});
    CHECK(at(2, 0) == C{68, 1, 84});

    LinearImage small = ref;
    small.width = 2;
    CHECK_FALSE(compare_images(small, ref, scale, c.consumer()));
    CHECK(c.has("the image is 2x2 and the reference 4x2: nothing to compare"));
}

TEST_CASE("render: the exact variants through the CPU mirror match the oracle", "[render]") {
    const RenderScene s = scene_or_fail(kScene);
    RenderOptions opt;
    opt.width = 16;
    opt.height = 12;
    Collect c;
    for (const char* name : {"dist=ggx,method=exact,light=polygon",
                             "dist=phong,method=exact,light=polygon"}) {
        auto v = parse_variant(name, c.consumer());
        REQUIRE(v);
        opt.variants.push_back(*v);
    }
    EvalOptions eo;
    eo.backend = Backend::Cpu;
    auto ev = Evaluator::create(eo, c.consumer());
    REQUIRE(ev);
    RenderStats stats;
    auto img = render(s, opt, ev.get(), c.consumer(), {}, &stats);
    INFO(c.all());
    REQUIRE(img);
    CHECK(stats.variants.size() == 2);

    RenderOptions ro = opt;
    ro.reference = true;
    ro.reference_options.rel_tol = 1e-8;
    ro.reference_options.threads = 2;
    RenderStats rstats;
    auto ref = render(s, ro, nullptr, c.consumer(), {}, &rstats);
    REQUIRE(ref);
    CHECK(rstats.cases == stats.cases);
    CHECK(rstats.unconverged == 0);
    // Most of the frame is lit surface: the comparison covers real shading.
    CHECK(stats.cases > static_cast<std::size_t>(opt.width * opt.height));

    // The exact variants are at the 1e-6 level against the oracle (README), fp32 inputs
    // included; the bound leaves a factor of ten.
    constexpr double kExactVsOracle = 1e-5;
    auto e = compare_images(*img, *ref, ErrorScale{}, c.consumer());
    REQUIRE(e);
    INFO("relL2 " << e->rel_l2 << ", max " << e->max);
    CHECK(e->bad == 0);
    CHECK(e->rel_l2 < kExactVsOracle);
    CHECK(e->max < kExactVsOracle);
}

TEST_CASE("render: a variant that does not fit a light is an error", "[render]") {
    const RenderScene s = scene_or_fail(kScene);
    RenderOptions opt;
    opt.width = 8;
    opt.height = 6;
    Collect c;
    // sided=two compiles in two-sided lights only; light 0 is one-sided.
    auto v = parse_variant("dist=phong,method=pearson,light=polygon,sided=two,verts=4", c.consumer());
    REQUIRE(v);
    opt.variants.push_back(*v);
    EvalOptions eo;
    eo.backend = Backend::Cpu;
    auto ev = Evaluator::create(eo, c.consumer());
    REQUIRE(ev);
    CHECK_FALSE(render(s, opt, ev.get(), c.consumer()));
    INFO(c.all());
    CHECK(c.has("variant dist=phong,method=pearson,light=polygon,sided=two,verts=4 does not apply to "
                "light 0 (a one-sided polygon of 4 vertices)"));
}

namespace {

MeasuredVariant measured(const std::string& name, double error, std::size_t x86) {
    MeasuredVariant m;
    m.variant = name;
    m.error_rel_l2 = error;
    m.x86_instructions = x86;
    return m;
}

// The test's own measured data for the Phong polygon pair: LTC cheap and coarse, pearson
// dearer and finer.
QualityData two_phong_methods() {
    QualityData q;
    q.variants.push_back(measured("dist=phong,method=ltc,light=polygon", 0.05, 100));
    q.variants.push_back(measured("dist=phong,method=pearson,light=polygon", 0.01, 500));
    return q;
}

}  // namespace

TEST_CASE("render: an uncovered pair takes the scene's selection", "[render]") {
    RenderScene s = scene_or_fail(kScene);
    const QualityData q = two_phong_methods();
    struct Want {
        std::optional<double> max_error;
        Method method;
    };
    // Without quality the bound is kDefaultMaxError (0.02): only pearson meets it.
    for (const Want& w : {Want{std::nullopt, Method::Pearson}, Want{0.1, Method::Ltc},
                          Want{0.001, Method::Pearson}}) {
        s.quality.max_error = w.max_error;
        Collect c;
        auto v = render_variant(s, LightType::Polygon, Distribution::Phong, q, c.consumer());
        INFO("max_error " << w.max_error.value_or(-1) << "\n" << c.all());
        REQUIRE(v);
        CHECK(v->variant.method == w.method);
        // One one-sided and one two-sided light: the variant must take both.
        CHECK(v->variant.sided == Sided::Any);
    }
    // quality.method alone: that method, whatever the data says.
    s.quality.max_error.reset();
    s.quality.method = "ltc";
    Collect c;
    auto v = render_variant(s, LightType::Polygon, Distribution::Phong, q, c.consumer());
    INFO(c.all());
    REQUIRE(v);
    CHECK(v->variant.method == Method::Ltc);
}

TEST_CASE("render: the selection is generate --scene's, pair by pair", "[render]") {
    for (const char* quality : {"", R"("quality": {"max_error": 0.005},)",
                                R"("quality": {"method": "pearson"},)"}) {
        std::string text = kScene;
        text.insert(text.find('{') + 1, quality);
        const RenderScene s = scene_or_fail(text);
        Collect c;
        auto all = select_variants(s, shipped_quality(), c.consumer());
        INFO(quality << "\n" << c.all());
        REQUIRE(all);
        REQUIRE(all->size() == 2);
        for (const auto& want : *all) {
            auto got = render_variant(s, want.variant.light, want.variant.dist,
                                      shipped_quality(), c.consumer());
            REQUIRE(got);
            CHECK(canonical_name(got->variant) == canonical_name(want.variant));
            CHECK(got->why == want.why);
        }
    }
}

TEST_CASE("render: the default variants are the selection, --variant overrides", "[render]") {
    RenderScene s = scene_or_fail(kScene);
    RenderOptions opt;
    opt.width = 8;
    opt.height = 6;
    EvalOptions eo;
    eo.backend = Backend::Cpu;
    Collect c;
    auto ev = Evaluator::create(eo, c.consumer());
    REQUIRE(ev);
    const QualityData q = two_phong_methods();
    opt.quality = &q;
    // The test data has no GGX row, so GGX must be given; Phong comes from the data.
    auto ggx = parse_variant("dist=ggx,method=exact,light=polygon", c.consumer());
    REQUIRE(ggx);
    opt.variants.push_back(*ggx);
    s.quality.max_error = 0.1;
    RenderStats stats;
    REQUIRE(render(s, opt, ev.get(), c.consumer(), {}, &stats));
    INFO(c.all());
    REQUIRE(stats.variants.size() == 2);
    CHECK(stats.variants[0].find("dist=phong,method=ltc,light=polygon") == 0);
    CHECK(stats.variants[1] == "dist=ggx,method=exact,light=polygon");

    // Without the GGX --variant the selection fails on the pair the data lacks.
    opt.variants.clear();
    Collect c2;
    CHECK_FALSE(render(s, opt, ev.get(), c2.consumer()));
    INFO(c2.all());
    CHECK(c2.has("light=polygon, dist=ggx: no measured variant that the scene's quality allows "
                 "in the quality data (arealight quality regenerates it from the reports)"));

    // A method no variant has fails the selection, but not pairs every --variant covers.
    s.quality.method = "magic";
    auto phong = parse_variant("dist=phong,method=exact,light=polygon", c.consumer());
    REQUIRE(phong);
    opt.variants = {*ggx, *phong};
    Collect c3;
    CHECK(render(s, opt, ev.get(), c3.consumer()));
    INFO(c3.all());
}

TEST_CASE("render: the error image's colour-bar labels never overlap, at any width", "[render]") {
    const ErrorScale scale;  // 1e-4 .. 1: five decades
    for (int width : {24, 60, 90, 120, 240, 640}) {
        const auto labels = error_legend_labels(width, scale);
        INFO("width " << width << ": " << labels.size() << " labels");
        REQUIRE_FALSE(labels.empty());
        CHECK(labels.back().decade == 0);  // the top, "1", is always labelled
        for (std::size_t i = 1; i < labels.size(); ++i) CHECK(labels[i - 1].right < labels[i].left);
        if (width >= 240) CHECK(labels.size() == 5);  // room for every decade
    }
    CHECK(error_legend_labels(60, scale).size() < 5);
}
