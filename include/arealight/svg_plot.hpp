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
    // Marker shape (plot_marker); -1: by the series' place, so that series whose
    // palette colours repeat (plot_color cycles every 10) still differ in shape.
    int marker = -1;
};

struct Plot {
    std::string title, x_label, y_label;
    std::vector<PlotSeries> series;
    std::vector<PlotPoint> front;  // drawn as a dashed polyline over the series
    std::string front_name;        // its legend entry
    std::vector<PlotPoint> highlight;  // drawn as a ring around the series' points
    std::string highlight_name;        // its legend entry
    int width = 760, height = 480;
};

// Non-positive or non-finite values are left out (log axes); axes span whole
// decades around the rest.
std::string svg_plot(const Plot& p);

// A fixed palette, one colour per index (cycles every 10).
std::string plot_color(std::size_t index);
// The marker shape that goes with plot_color(index): circle for the first 10 indices,
// then square, triangle, diamond and cross, so that (colour, shape) differs for 50.
int plot_marker(std::size_t index);

}  // namespace arealight
