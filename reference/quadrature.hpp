// Globally adaptive Gauss-Kronrod (G7/K15) quadrature in one dimension, with the
// QUADPACK error heuristic (Piessens et al. 1983, qk15/qag). Nodes and weights
// come from Boost.Math so no constant is typed by hand.
#pragma once

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <vector>

namespace arealight::ref {

// An integrand value with an auxiliary quantity integrated by the same rule
// (used to carry the error bound of an inner integral through the outer one).
struct QuadValue {
    double value = 0.0;
    double aux = 0.0;
};

struct QuadResult {
    double value = 0.0;
    double error = 0.0;  // estimated absolute error (QUADPACK heuristic) + integrated aux
    double aux = 0.0;
    std::size_t evals = 0;
    bool converged = true;
};

namespace detail {

struct Segment {
    double a, b, value, error, aux;
    bool operator<(const Segment& o) const { return error < o.error; }
};

template <class F>
Segment gk15(const F& f, double a, double b) {
    using K = boost::math::quadrature::gauss_kronrod<double, 15>;
    using G = boost::math::quadrature::gauss<double, 7>;
    static const auto& xk = K::abscissa();  // 8 non-negative nodes, xk[0] = 0
    static const auto& wk = K::weights();
    static const auto& wg = G::weights();  // 4 weights, wg[0] for the centre node
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    const QuadValue f0 = f(c);
    double kron = wk[0] * f0.value, gauss = wg[0] * f0.value, aux = wk[0] * f0.aux;
    double fv[15];
    fv[0] = f0.value;
    for (std::size_t i = 1; i < xk.size(); ++i) {
        const QuadValue l = f(c - h * xk[i]), r = f(c + h * xk[i]);
        fv[2 * i - 1] = l.value;
        fv[2 * i] = r.value;
        kron += wk[i] * (l.value + r.value);
        aux += wk[i] * (l.aux + r.aux);
        if (i % 2 == 0) gauss += wg[i / 2] * (l.value + r.value);
    }
    // QUADPACK: resasc measures the spread of f about its mean, which turns the
    // raw Gauss-Kronrod difference into a realistic (still conservative) bound.
    const double mean = 0.5 * kron;
    double resabs = wk[0] * std::abs(fv[0]), resasc = wk[0] * std::abs(fv[0] - mean);
    for (std::size_t i = 1; i < xk.size(); ++i) {
        resabs += wk[i] * (std::abs(fv[2 * i - 1]) + std::abs(fv[2 * i]));
        resasc += wk[i] * (std::abs(fv[2 * i - 1] - mean) + std::abs(fv[2 * i] - mean));
    }
    const double ah = std::abs(h);
    double err = std::abs((kron - gauss) * h);
    resabs *= ah;
    resasc *= ah;
    if (resasc != 0.0 && err != 0.0)
        err = resasc * std::min(1.0, std::pow(200.0 * err / resasc, 1.5));
    const double eps = std::numeric_limits<double>::epsilon();
    if (resabs > std::numeric_limits<double>::min() / (50.0 * eps))
        err = std::max(50.0 * eps * resabs, err);
    return {a, b, kron * h, err, std::abs(aux * h)};
}

}  // namespace detail

// Integrates f over the union of [breaks[i], breaks[i+1]] until the estimated
// error is below max(rel_tol*|I|, abs_tol) or max_eval evaluations are spent.
template <class F>
QuadResult integrate_adaptive(const F& f, const std::vector<double>& breaks, double rel_tol,
                              double abs_tol, std::size_t max_eval) {
    QuadResult out;
    std::priority_queue<detail::Segment> heap;
    double total = 0.0, total_err = 0.0, total_aux = 0.0;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        if (!(breaks[i + 1] > breaks[i])) continue;
        const auto s = detail::gk15(f, breaks[i], breaks[i + 1]);
        out.evals += 15;
        total += s.value;
        total_err += s.error;
        total_aux += s.aux;
        heap.push(s);
    }
    while (!heap.empty() && total_err > std::max(rel_tol * std::abs(total), abs_tol)) {
        if (out.evals + 30 > max_eval) {
            out.converged = false;
            break;
        }
        const auto s = heap.top();
        const double mid = 0.5 * (s.a + s.b);
        if (!(mid > s.a && mid < s.b)) {  // interval can no longer be split
            out.converged = false;
            break;
        }
        heap.pop();
        const auto l = detail::gk15(f, s.a, mid), r = detail::gk15(f, mid, s.b);
        out.evals += 30;
        total += l.value + r.value - s.value;
        total_err += l.error + r.error - s.error;
        total_aux += l.aux + r.aux - s.aux;
        heap.push(l);
        heap.push(r);
    }
    // Re-sum from the segments to drop the drift of the running updates.
    total = total_err = total_aux = 0.0;
    while (!heap.empty()) {
        total += heap.top().value;
        total_err += heap.top().error;
        total_aux += heap.top().aux;
        heap.pop();
    }
    out.value = total;
    out.error = total_err;
    out.aux = total_aux;
    return out;
}

}  // namespace arealight::ref
