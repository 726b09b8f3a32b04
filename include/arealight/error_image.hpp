// How far a rendering is from a reference rendering, as numbers and as a picture.
//
// Per pixel the error is that of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B:
//   e = |Y - Y_ref| / max(Y_ref, floor)
// (shared/tools/score's metric on Y); the image's relL2 is sqrt(sum (Y - Y_ref)^2 /
// sum Y_ref^2) over all pixels.
#pragma once

#include <array>
#include <vector>
#include <cstdint>
#include <optional>
#include <string>

#include "arealight/diagnostics.hpp"
#include "arealight/image.hpp"

namespace arealight {

struct ImageError {
    double rel_l2 = 0, median = 0, p95 = 0, max = 0;
    std::size_t pixels = 0, bad = 0;  // bad: a non-finite pixel in the image
};

struct ErrorScale {
    double floor = 1e-3;        // luminance below which errors count as absolute
    double lo = 1e-4, hi = 1.0;  // colour bar ends; powers of ten, lo < hi
};

// nullopt with a diagnostic naming both sizes when they differ.
std::optional<ImageError> compare_images(const LinearImage& image, const LinearImage& ref,
                                         const ErrorScale& scale, const DiagnosticConsumer& diag);

// t in [0, 1] (clamped; NaN as 1) along an approximation of matplotlib's viridis (nine
// stops, linear between them): dark purple at 0, yellow at 1.
std::array<std::uint8_t, 3> false_colour(double t);

// Height in pixels of the legend error_image draws below the picture.
constexpr int kLegendHeight = 30;

// The colour bar's labels in an image `width` pixels wide: per labelled power of ten k,
// its label's left and right pixel columns. Every power of ten gets a tick; labels are
// spaced so that none overlaps the next (every second or third decade on a narrow bar).
struct LegendLabel {
    int decade, left, right;
};
std::vector<LegendLabel> error_legend_labels(int width, const ErrorScale& scale);

// The per-pixel error in false colour on a log scale from scale.lo (and below) to
// scale.hi (and above), with a colour bar below it: a tick at each power of ten and the
// labels of error_legend_labels ("1e-3", "1"). Sizes must match (compare_images checks
// them).
Image8 error_image(const LinearImage& image, const LinearImage& ref, const ErrorScale& scale);

}  // namespace arealight
