#include "arealight/svg_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace arealight {
namespace {

bool plottable(const PlotPoint& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && p.x > 0 && p.y > 0;
}

std::string escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

// Whole decades covering [lo, hi] (at least one).
void decades(double lo, double hi, int& d0, int& d1) {
    d0 = static_cast<int>(std::floor(std::log10(lo)));
    d1 = static_cast<int>(std::ceil(std::log10(hi)));
    if (d1 <= d0) d1 = d0 + 1;
}

std::string decade_label(int d) {
    if (d >= 0 && d <= 4) return fmt::format("{}", static_cast<long>(std::lround(std::pow(10, d))));
    return fmt::format("1e{}", d);
}

}  // namespace

std::string plot_color(std::size_t index) {
    static const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
    return palette[index % (sizeof palette / sizeof palette[0])];
}

int plot_marker(std::size_t index) {
    return static_cast<int>((index / 10) % 5);
}

namespace {

// One marker of shape `shape` (plot_marker) and radius r at (x, y), left open for a
// <title> child and closed by the caller with the returned tag name.
std::string marker_open(int shape, double x, double y, double r, const std::string& color,
                        std::string& tag) {
    switch (shape) {
        case 1:
            tag = "rect";
            return fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" "
                               "fill=\"{}\">",
                               x - r, y - r, 2 * r, 2 * r, color);
        case 2:
            tag = "polygon";
            return fmt::format("<polygon points=\"{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}\" fill=\"{}\">",
                               x, y - 1.2 * r, x + 1.1 * r, y + 0.8 * r, x - 1.1 * r, y + 0.8 * r,
                               color);
        case 3:
            tag = "polygon";
            return fmt::format(
                "<polygon points=\"{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}\" fill=\"{}\">",
                x, y - 1.3 * r, x + 1.3 * r, y, x, y + 1.3 * r, x - 1.3 * r, y, color);
        case 4:
            tag = "path";
            return fmt::format(
                "<path d=\"M{:.1f},{:.1f}L{:.1f},{:.1f}M{:.1f},{:.1f}L{:.1f},{:.1f}\" stroke=\"{}\" "
                "stroke-width=\"2\">",
                x - r, y - r, x + r, y + r, x - r, y + r, x + r, y - r, color);
        default:
            tag = "circle";
            return fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"{}\" fill=\"{}\">", x, y, r,
                               color);
    }
}

}  // namespace

std::string svg_plot(const Plot& p) {
    double xlo = INFINITY, xhi = -INFINITY, ylo = INFINITY, yhi = -INFINITY;
    for (const auto& s : p.series) {
        for (const auto& q : s.points) {
            if (!plottable(q)) continue;
            xlo = std::min(xlo, q.x);
            xhi = std::max(xhi, q.x);
            ylo = std::min(ylo, q.y);
            yhi = std::max(yhi, q.y);
        }
    }
    if (!(xlo <= xhi)) xlo = 1, xhi = 10, ylo = 1, yhi = 10;
    int x0, x1, y0, y1;
    decades(xlo, xhi, x0, x1);
    decades(ylo, yhi, y0, y1);
    // The legend sits right of the plot and must fit the canvas: its column is as wide as
    // the longest entry (about 7 px a character at 12 px), the canvas as tall as its
    // entries; the plot area keeps the size p asks for.
    std::size_t longest = 0, entries = p.series.size() + (p.front.empty() ? 0 : 1) +
                                       (p.highlight.empty() ? 0 : 1);
    for (const auto& s : p.series) longest = std::max(longest, s.name.size());
    if (!p.front.empty()) longest = std::max(longest, p.front_name.size());
    if (!p.highlight.empty()) longest = std::max(longest, p.highlight_name.size());
    const double left = 70, top = 40, bottom = 50;
    const double right = std::max(190.0, 40.0 + 7.0 * double(longest));
    const double pw = p.width - left - 190.0, ph = p.height - top - bottom;
    const int width = static_cast<int>(std::ceil(left + pw + right));
    const int height = std::max(p.height, static_cast<int>(std::ceil(top + 18.0 * entries + 10.0)));
    auto X = [&](double x) { return left + (std::log10(x) - x0) / (x1 - x0) * pw; };
    auto Y = [&](double y) { return top + ph - (std::log10(y) - y0) / (y1 - y0) * ph; };

    std::string o = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} "
        "{}\" font-family=\"sans-serif\" font-size=\"12\">\n",
        width, height, width, height);
    o += "<!-- generated by arealight; do not edit -->\n";
    o += fmt::format("<rect width=\"{}\" height=\"{}\" fill=\"white\"/>\n", width, height);
    o += fmt::format(
        "<text x=\"{:.1f}\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
        left + pw / 2, escape(p.title));
    // Grid and ticks at every decade.
    for (int d = x0; d <= x1; ++d) {
        const double x = X(std::pow(10, d));
        o += fmt::format(
            "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", x,
            top, x, top + ph);
        o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n", x,
                         top + ph + 16, decade_label(d));
    }
    for (int d = y0; d <= y1; ++d) {
        const double y = Y(std::pow(10, d));
        o += fmt::format(
            "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n",
            left, y, left + pw, y);
        o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n",
                         left - 6, y + 4, decade_label(d));
    }
    o += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
        "stroke=\"black\"/>\n",
        left, top, pw, ph);
    o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{}</text>\n",
                     left + pw / 2, top + ph + bottom - 10.0, escape(p.x_label));
    o += fmt::format(
        "<text x=\"16\" y=\"{:.1f}\" text-anchor=\"middle\" transform=\"rotate(-90 16 {:.1f})\">{}"
        "</text>\n",
        top + ph / 2, top + ph / 2, escape(p.y_label));

    auto polyline = [&](const std::vector<PlotPoint>& pts, const std::string& color,
                        const std::string& extra) {
        std::string d;
        for (const auto& q : pts)
            if (plottable(q))
                d += fmt::format("{}{:.1f},{:.1f}", d.empty() ? "" : " ", X(q.x), Y(q.y));
        if (!d.empty())
            o += fmt::format("<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" {}/>\n", d, color,
                             extra);
    };
    auto shape_of = [&](const PlotSeries& s) {
        return s.marker >= 0 ? s.marker : plot_marker(static_cast<std::size_t>(&s - p.series.data()));
    };
    for (const auto& s : p.series) {
        if (s.line) polyline(s.points, s.color, "stroke-width=\"1.5\"");
        for (const auto& q : s.points) {
            if (!plottable(q)) continue;
            std::string tag;
            o += marker_open(shape_of(s), X(q.x), Y(q.y), s.line ? 2.5 : 4, s.color, tag);
            if (!q.label.empty()) o += "<title>" + escape(q.label) + "</title>";
            o += "</" + tag + ">\n";
        }
    }
    if (!p.front.empty())
        polyline(p.front, "black", "stroke-width=\"1.2\" stroke-dasharray=\"5,3\"");
    auto ring = [&](double x, double y) {
        return fmt::format(
            "<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"8\" fill=\"none\" stroke=\"black\" "
            "stroke-width=\"1.6\"/>\n",
            x, y);
    };
    for (const auto& q : p.highlight)
        if (plottable(q)) o += ring(X(q.x), Y(q.y));

    // Legend, right of the plot.
    double ly = top + 8;
    auto legend = [&](const std::string& name, const std::string& color, int shape) {
        const double lx = left + pw + 14;
        if (shape < 0) {
            o += fmt::format(
                "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"{}\" "
                "stroke-dasharray=\"5,3\"/>\n",
                lx, ly, lx + 16, ly, color);
        } else {
            std::string tag;
            o += marker_open(shape, lx + 8, ly, 4, color, tag) + "</" + tag + ">\n";
        }
        o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", lx + 22, ly + 4,
                         escape(name));
        ly += 18;
    };
    for (const auto& s : p.series) legend(s.name, s.color, shape_of(s));
    if (!p.front.empty()) legend(p.front_name, "black", -1);
    if (!p.highlight.empty()) {
        o += ring(left + pw + 22, ly);
        o += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\">{}</text>\n", left + pw + 36, ly + 4,
                         escape(p.highlight_name));
        ly += 18;
    }
    o += "</svg>\n";
    return o;
}

}  // namespace arealight
