// A small, dependency-free SVG plot on log-log axes: point series (markers),
// line series, and an optional highlighted polyline (a Pareto front). Output is
// deterministic text (fixed number formatting), so reports diff cleanly.
#pragma once

#include <string>
#include <vector>

namespace arealight {

struct PlotPoint {
    double x = 0, y = 0;
    std::string label;  // shown on hover (<title>); empty for none
};

struct PlotSeries {
    std::string name;   // legend entry
    std::string color;  // any SVG colour
    bool line = false;  // join the points in order instead of drawing markers
    std::vector<PlotPoint> points;
};

struct Plot {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    std::vector<PlotPoint> front;  // drawn as a dashed polyline over the series
    std::string front_name;        // its legend entry
    int width = 760, height = 480;
};

// Non-positive or non-finite values are left out (log axes); axes span whole
// decades around the rest.
std::string svg_plot(const Plot& p);

// A fixed palette, one colour per index (cycles).
std::string plot_color(std::size_t index);

}  // namespace arealight
