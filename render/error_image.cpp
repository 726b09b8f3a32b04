#include "arealight/error_image.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace arealight {
namespace {

double luminance(const LinearImage& img, std::size_t px) {
    const float* c = &img.rgb[px * 3];
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

double pixel_error(const LinearImage& img, const LinearImage& ref, std::size_t px, double floor) {
    const double y = luminance(img, px), yr = luminance(ref, px);
    return std::abs(y - yr) / std::max(std::abs(yr), floor);
}

// A 3x5 bitmap font for the legend's labels: each glyph five rows of three bits, the
// high bit leftmost.
struct Glyph {
    char c;
    std::uint8_t rows[5];
};
constexpr Glyph kFont[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}},
    {'3', {7, 1, 7, 1, 7}}, {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}},
    {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}}, {'8', {7, 5, 7, 5, 7}},
    {'9', {7, 5, 7, 1, 7}}, {'e', {2, 5, 7, 4, 3}}, {'-', {0, 0, 7, 0, 0}},
};
constexpr int kFontScale = 2;  // each font bit a 2x2 block
constexpr int kGlyphAdvance = 4 * kFontScale;

void put(Image8& img, int x, int y, const std::array<std::uint8_t, 3>& c) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
    std::uint8_t* p = &img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
    p[0] = c[0], p[1] = c[1], p[2] = c[2];
}

void draw_text(Image8& img, int x, int y, const std::string& text) {
    const std::array<std::uint8_t, 3> white = {255, 255, 255};
    for (char ch : text) {
        for (const Glyph& g : kFont) {
            if (g.c != ch) continue;
            for (int r = 0; r < 5; ++r)
                for (int b = 0; b < 3; ++b)
                    if (g.rows[r] >> (2 - b) & 1)
                        for (int s = 0; s < kFontScale * kFontScale; ++s)
                            put(img, x + b * kFontScale + s % kFontScale,
                                y + r * kFontScale + s / kFontScale, white);
        }
        x += kGlyphAdvance;
    }
}

std::string decade_label(int k) {
    return k == 0 ? "1" : fmt::format("1e{}", k);
}

// Position of e on the bar, 0 at scale.lo, 1 at scale.hi.
double bar_position(double e, const ErrorScale& s) {
    const double lo = std::log10(s.lo), hi = std::log10(s.hi);
    return (std::log10(std::max(e, 1e-300)) - lo) / (hi - lo);
}

}  // namespace

std::optional<ImageError> compare_images(const LinearImage& image, const LinearImage& ref,
                                         const ErrorScale& scale, const DiagnosticConsumer& diag) {
    if (image.width != ref.width || image.height != ref.height) {
        if (diag)
            diag({Severity::Error, "", 0,
                  fmt::format("the image is {}x{} and the reference {}x{}: nothing to compare",
                              image.width, image.height, ref.width, ref.height)});
        return std::nullopt;
    }
    ImageError out;
    out.pixels = static_cast<std::size_t>(image.width) * image.height;
    std::vector<double> errors;
    double se = 0, sr = 0;
    for (std::size_t px = 0; px < out.pixels; ++px) {
        const double y = luminance(image, px), yr = luminance(ref, px);
        if (!std::isfinite(y)) {
            ++out.bad;
            continue;
        }
        se += (y - yr) * (y - yr);
        sr += yr * yr;
        errors.push_back(pixel_error(image, ref, px, scale.floor));
    }
    out.rel_l2 = sr > 0 ? std::sqrt(se / sr) : NAN;
    std::sort(errors.begin(), errors.end());
    if (!errors.empty()) {
        // Quantiles as shared/tools/score takes them: element ceil(q n) - 1.
        auto q = [&](double f) {
            const auto i = static_cast<std::size_t>(std::ceil(f * errors.size()));
            return errors[std::min(errors.size() - 1, i > 0 ? i - 1 : 0)];
        };
        out.median = q(0.5);
        out.p95 = q(0.95);
        out.max = errors.back();
    }
    return out;
}

std::array<std::uint8_t, 3> false_colour(double t) {
    static constexpr std::uint8_t kViridis[9][3] = {
        {68, 1, 84},    {71, 44, 122},  {59, 81, 139},  {44, 113, 142}, {33, 144, 141},
        {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
    const double x = (std::isnan(t) ? 1.0 : std::clamp(t, 0.0, 1.0)) * 8.0;
    const int i = std::min(7, static_cast<int>(x));
    const double f = x - i;
    std::array<std::uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = static_cast<std::uint8_t>(
            std::lround(kViridis[i][k] + f * (kViridis[i + 1][k] - kViridis[i][k])));
    return c;
}

namespace {

// The colour bar's span: room at both ends for half a label.
constexpr int kBarMargin = 2 * kGlyphAdvance;

int decade_x(int k, int width, const ErrorScale& scale) {
    const int x0 = kBarMargin, x1 = width - kBarMargin;
    return x0 + static_cast<int>(std::lround(bar_position(std::pow(10.0, k), scale) * (x1 - x0)));
}

}  // namespace

std::vector<LegendLabel> error_legend_labels(int width, const ErrorScale& scale) {
    const int klo = static_cast<int>(std::lround(std::log10(scale.lo)));
    const int khi = static_cast<int>(std::lround(std::log10(scale.hi)));
    // The smallest stride in decades at which the widest label clears its neighbour by
    // a glyph's advance; the top decade is always labelled, counting down from it.
    int widest = 0;
    for (int k = klo; k <= khi; ++k)
        widest = std::max(widest, static_cast<int>(decade_label(k).size()) * kGlyphAdvance);
    int stride = 1;
    while (klo + stride <= khi &&
           decade_x(klo + stride, width, scale) - decade_x(klo, width, scale) <
               widest + kGlyphAdvance)
        ++stride;
    std::vector<LegendLabel> out;
    for (int k = khi; k >= klo; k -= stride) {
        const int w = static_cast<int>(decade_label(k).size()) * kGlyphAdvance - kFontScale;
        const int x = decade_x(k, width, scale);
        out.push_back({k, x - w / 2, x - w / 2 + w - 1});
    }
    std::reverse(out.begin(), out.end());
    return out;
}

Image8 error_image(const LinearImage& image, const LinearImage& ref, const ErrorScale& scale) {
    Image8 out;
    out.width = image.width;
    out.height = image.height + kLegendHeight;
    out.rgb.assign(static_cast<std::size_t>(out.width) * out.height * 3, 0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t px = static_cast<std::size_t>(y) * image.width + x;
            put(out, x, y, false_colour(bar_position(pixel_error(image, ref, px, scale.floor), scale)));
        }
    // The colour bar, with room at both ends for half a label.
    const int x0 = kBarMargin, x1 = out.width - kBarMargin;
    const int bar_top = image.height + 3, bar_bottom = bar_top + 8;
    for (int x = x0; x <= x1; ++x) {
        const auto c = false_colour(static_cast<double>(x - x0) / std::max(1, x1 - x0));
        for (int y = bar_top; y < bar_bottom; ++y) put(out, x, y, c);
    }
    const int klo = static_cast<int>(std::lround(std::log10(scale.lo)));
    const int khi = static_cast<int>(std::lround(std::log10(scale.hi)));
    for (int k = klo; k <= khi; ++k) {
        const int x = decade_x(k, out.width, scale);
        for (int y = bar_bottom; y < bar_bottom + 3; ++y) put(out, x, y, {255, 255, 255});
    }
    for (const LegendLabel& l : error_legend_labels(out.width, scale))
        draw_text(out, l.left, bar_bottom + 5, decade_label(l.decade));
    return out;
}

}  // namespace arealight
