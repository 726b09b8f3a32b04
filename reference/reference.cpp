// The oracle: each quantity is integrated over its exact direction-space domain
// in geodesic polar coordinates about a point of the domain (the integrand's
// peak when it lies inside), with globally adaptive Gauss-Kronrod rules nested
// in azimuth (split at the domain's corners) and polar angle.
#include "arealight/reference.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "integrands.hpp"
#include "quadrature.hpp"
#include "sphere_domain.hpp"

namespace arealight {
namespace ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Azimuth nodes per quantity; each runs an inner rule of at most max_eval / this.
constexpr std::size_t kOuterEvals = 6000;

struct Frame {
    Vec3 n, v, r;
};

Frame shading_frame(const Case& c) {
    Frame f;
    f.n = normalize(c.n);
    f.v = normalize(c.v);
    f.r = normalize(2.0 * dot(f.n, f.v) * f.n - f.v);
    return f;
}

// The light's directions seen from p, or nullopt when p sees none of its
// emitting side (behind a one-sided light, on its plane, inside a volume).
std::optional<SphereDomain> light_domain(const Case& c) {
    const Light& L = c.light;
    SphereDomain dom;
    switch (L.type) {
        case LightType::Polygon: {
            const auto& V = L.vertices;
            const Vec3 N = cross(V[1] - V[0], V[2] - V[0]);
            const double side = dot(N, c.p - V[0]);
            if (side == 0.0 || (side < 0.0 && !L.two_sided)) return std::nullopt;
            Vec3 centroid{};
            for (const auto& x : V) centroid = centroid + x;
            centroid = (1.0 / V.size()) * centroid;
            const Vec3 g = centroid - c.p;
            std::vector<Vec3> outline;
            for (std::size_t i = 0; i < V.size(); ++i) {
                const Vec3 xi = V[i] - c.p;
                // x_i x (v_{i+1} - v_i) avoids the cancellation of x_i x x_{i+1}
                // for small, distant polygons.
                Vec3 m = cross(xi, V[(i + 1) % V.size()] - V[i]);
                if (dot(m, g) < 0.0) m = -m;
                dom.add_halfspace(m);
                outline.push_back(normalize(xi));
            }
            if (side < 0.0) std::reverse(outline.begin(), outline.end());
            dom.set_outline(std::move(outline));
            return dom;
        }
        case LightType::Disk: {
            const Vec3 d = L.center - c.p;
            const double side = -dot(cross(L.u, L.v), d);
            if (side == 0.0 || (side < 0.0 && !L.two_sided)) return std::nullopt;
            const EllipticCone cone = EllipticCone::disk(d, L.u, L.v);
            dom.add_cone(cone);
            return dom;
        }
        case LightType::Sphere: {
            const Vec3 d = L.center - c.p;
            const double dist = norm(d);
            if (!(dist > L.radius)) return std::nullopt;
            const double s = 1.0 / L.radius;
            const Mat3 Ainv{{s, 0, 0}, {0, s, 0}, {0, 0, s}};
            const Mat3 A{{L.radius, 0, 0}, {0, L.radius, 0}, {0, 0, L.radius}};
            dom.add_cone(EllipticCone::ball(Ainv, A, (-s) * d));
            return dom;
        }
        case LightType::Ellipsoid: {
            const auto& A = L.axes;
            // Orthogonal columns: the inverse's rows are a_i / |a_i|^2.
            const Mat3 Ainv{(1.0 / norm2(A[0])) * A[0], (1.0 / norm2(A[1])) * A[1],
                            (1.0 / norm2(A[2])) * A[2]};
            const Vec3 q = Ainv * (c.p - L.center);
            const double ql = norm(q);
            if (!(ql > 1.0)) return std::nullopt;
            // In the unit-ball frame the visible directions form the cone from q
            // towards the origin with sin(alpha) = 1 / |q|.
            dom.add_cone(EllipticCone::ball(Ainv, from_columns(A[0], A[1], A[2]), q));
            return dom;
        }
    }
    return std::nullopt;
}

struct Integral {
    double value = 0.0, error = 0.0;
    bool converged = true;
};

// Integrates g over the domain; `peak` is where g concentrates (or a singular point).
// Appends x0 +- width * 4^k (k = 0, 1, ...) inside (lo, hi): a grading that lets
// the first Gauss-Kronrod nodes see a feature of the given width at x0.
void graded_breaks(std::vector<double>& out, double x0, double width, double lo, double hi) {
    if (!(width > 0.0)) return;
    for (double d = width; d < hi - lo; d *= 4.0) {
        if (x0 + d < hi) out.push_back(x0 + d);
        if (x0 - d > lo) out.push_back(x0 - d);
    }
}

// Integrates g over the domain. `peak` is where g concentrates (or is singular)
// and `width` the narrowest angular size of that concentration; `ridges` are
// directions along which the lobe stretches into a thin ridge through the peak
// (grazing microfacet lobes).
template <class G>
Integral integrate(const SphereDomain& dom, const G& g, const Vec3* peak, double width,
                   const std::vector<Vec3>& ridges, const ReferenceOptions& opt) {
    Integral out;
    const auto poly = dom.inner_polygon();
    if (poly.empty()) return out;
    Vec3 a;
    if (peak && dom.slack(*peak) > 1e-12) {
        a = *peak;
    } else {
        Vec3 s{};
        for (const auto& x : poly) s = s + x;
        if (norm2(s) == 0.0) return out;
        a = normalize(s);
        if (!dom.contains(a)) a = poly.front();
    }
    Vec3 t1, t2;
    orthonormal_basis(a, t1, t2);
    auto azimuth = [&](const Vec3& w) { return std::atan2(dot(w, t2), dot(w, t1)); };

    std::vector<double> breaks;
    for (const auto& w : dom.corners()) {
        if (norm2(cross(w, a)) > 1e-24) breaks.push_back(azimuth(w));
    }
    if (peak && norm2(cross(*peak, a)) > 1e-24) {
        const double phi = azimuth(*peak);
        breaks.push_back(phi);
        // Seen from a, the lobe spans about width / angle(a, peak) in azimuth.
        const double gap = std::atan2(norm(cross(*peak, a)), dot(*peak, a));
        graded_breaks(breaks, phi, width / gap, phi - kPi / 16, phi + kPi / 16);
    }
    for (const auto& w : ridges) {
        if (norm2(cross(w, a)) > 1e-24) breaks.push_back(azimuth(w));
    }
    if (breaks.empty()) breaks.push_back(0.0);
    for (double& b : breaks) b = std::fmod(std::fmod(b, 2 * kPi) + 2 * kPi, 2 * kPi);
    std::sort(breaks.begin(), breaks.end());
    breaks.push_back(breaks.front() + 2 * kPi);
    // A first pass that samples every azimuth finely enough that a lobe narrower
    // than a corner interval is still seen before the adaptive refinement.
    std::vector<double> fine;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        const int pieces =
            std::max(4, static_cast<int>(std::ceil((breaks[i + 1] - breaks[i]) / (kPi / 16))));
        for (int k = 0; k < pieces; ++k)
            fine.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * k / pieces);
    }
    fine.push_back(breaks.back());
    breaks.swap(fine);

    std::atomic<bool> inner_ok{true};
    const double inner_rel = 0.1 * opt.rel_tol;
    const double inner_abs = 0.1 * opt.abs_tol / (2 * kPi);
    auto inner = [&](double phi) -> QuadValue {
        const Vec3 e = std::cos(phi) * t1 + std::sin(phi) * t2;
        const double tmax = dom.exit_angle(a, e);
        if (!(tmax > 0.0)) return {};
        std::vector<double> tb{0.0, tmax};
        if (peak) {
            // Closest approach of this great circle to the peak.
            const double ts = std::atan2(dot(*peak, e), dot(*peak, a));
            if (ts > 0.0 && ts < tmax) tb.push_back(ts);
            graded_breaks(tb, std::clamp(ts, 0.0, tmax), width, 0.0, tmax);
            std::sort(tb.begin(), tb.end());
        }
        auto f = [&](double t) -> QuadValue {
            const Vec3 w = std::cos(t) * a + std::sin(t) * e;
            return {g(w) * std::sin(t), 0.0};
        };
        const auto r = integrate_adaptive(f, tb, inner_rel, inner_abs,
                                          std::max<std::size_t>(opt.max_eval / kOuterEvals, 1000));
        if (!r.converged) inner_ok = false;
        return {r.value, r.error};
    };
    const auto r = integrate_adaptive(inner, breaks, 0.5 * opt.rel_tol, opt.abs_tol, kOuterEvals);
    out.value = r.value;
    // Quadrature estimate, inner errors carried through, and a floor for the
    // rounding of integrand evaluations (powers up to 1e5, sums of 1e5 terms).
    out.error = r.error + r.aux + 1e-12 * std::abs(r.value);
    out.converged = r.converged && inner_ok;
    return out;
}

}  // namespace
}  // namespace ref

CaseResult reference_case(const Case& c, const ReferenceOptions& opt) {
    using namespace ref;
    CaseResult res;
    res.id = c.id;
    const Frame fr = shading_frame(c);
    const Material& mat = c.material;
    const bool phong = mat.distribution == Distribution::Phong;
    auto zero = [&] {
        res.diffuse = res.specular = 0.0;
        res.error = res.error_diffuse = 0.0;
        if (phong) {
            res.moment = 0.0;
            res.error_moment = 0.0;
        } else {
            res.ndf = 0.0;
            res.error_ndf = 0.0;
        }
        res.converged = true;
        return res;
    };
    auto base = light_domain(c);
    if (!base) return zero();
    SphereDomain lit = *base;  // Omega intersect H
    lit.add_halfspace(fr.n);
    bool converged = true;
    auto finish = [&](const Integral& I, std::optional<double>& value,
                      std::optional<double>& error) {
        value = std::max(I.value, 0.0);
        error = I.error;
        converged = converged && I.converged;
    };

    finish(integrate(
               lit, [&](const Vec3& w) { return dot(fr.n, w) / kPi; }, nullptr, 0.0, {}, opt),
           res.diffuse, res.error_diffuse);

    if (phong) {
        SphereDomain mirror = lit;  // (r.w)_+ vanishes outside r's hemisphere
        mirror.add_halfspace(fr.r);
        const double N = mat.exponent;
        const double width = 0.5 / std::sqrt(N);  // cos^N t ~ exp(-N t^2 / 2)
        finish(
            integrate(
                mirror, [&](const Vec3& w) { return (N + 1) / (2 * kPi) * cos_power(fr.r, w, N); },
                &fr.r, width, {}, opt),
            res.moment, res.error_moment);
        finish(integrate(
                   mirror,
                   [&](const Vec3& w) {
                       return (N + 2) / (2 * kPi) * cos_power(fr.r, w, N) * dot(fr.n, w);
                   },
                   &fr.r, width, {}, opt),
               res.specular, res.error);
    } else {
        const double nv = dot(fr.n, fr.v);
        auto half = [&](const Vec3& w) { return normalize(w + fr.v); };
        // D(h) / (4 h.v), with h.v = |w + v| / 2 for unit w and v.
        auto ndf = [&](const Vec3& w) {
            const Vec3 s = w + fr.v;
            const double len = norm(s);
            if (!(len > 0.0)) return 0.0;
            return ndf_value(mat, fr.n, (1.0 / len) * s) / (2.0 * len);
        };
        if (nv > 0.0) {
            // At grazing views the lobe about r is squeezed by n.v across the
            // plane of incidence: a ridge along the direction from r towards n.
            // The lobe's half-width in h is about alpha; n.v squeezes it in w.
            const double alpha_h = mat.distribution == Distribution::Blinn
                                       ? std::sqrt(2.0 / (mat.exponent + 2.0))
                                       : mat.alpha;
            const double width = 0.5 * alpha_h * nv;
            std::vector<Vec3> ridges;
            const Vec3 up = fr.n - dot(fr.n, fr.r) * fr.r;
            if (norm2(up) > 1e-20) ridges = {normalize(up), -normalize(up)};
            finish(integrate(lit, ndf, &fr.r, width, ridges, opt), res.ndf, res.error_ndf);
            const double lambda_v = smith_lambda(mat, fr.n, fr.v);
            finish(integrate(
                       lit,
                       [&](const Vec3& w) {
                           const double g2 = 1.0 / (1.0 + smith_lambda(mat, fr.n, w) + lambda_v);
                           const double f = ndf_value(mat, fr.n, half(w)) * g2 / (4.0 * nv);
                           // Without f0 the integrand is left untouched, so results stay
                           // bit-identical to those computed before f0 existed.
                           return mat.has_f0 ? f * schlick_fresnel(mat.f0, w, fr.v) : f;
                       },
                       &fr.r, width, ridges, opt),
                   res.specular, res.error);
        } else {
            // Seen from below: D(h) needs n.h > 0, i.e. n.w > -n.v (a cap), and
            // the Jacobian is singular at -v, which becomes the polar axis.
            SphereDomain capped = lit;
            if (nv < 0.0) {
                const double c0 = -nv;
                // The cap n.w >= c0 is the view of a ball of radius sqrt(1 - c0^2)
                // centred at distance 1 along n.
                const double R = std::sqrt((1 - c0) * (1 + c0));
                const Mat3 Ainv{{1 / R, 0, 0}, {0, 1 / R, 0}, {0, 0, 1 / R}};
                const Mat3 A{{R, 0, 0}, {0, R, 0}, {0, 0, R}};
                capped.add_cone(EllipticCone::ball(Ainv, A, (-1 / R) * fr.n));
            }
            const Vec3 mv = -fr.v;
            finish(integrate(capped, ndf, &mv, 1e-3, {}, opt), res.ndf, res.error_ndf);
            res.specular = 0.0;
            res.error = 0.0;
        }
    }
    res.converged = converged;
    return res;
}

ResultSet reference_all(const CaseSet& cases, const ReferenceOptions& opt,
                        const ProgressConsumer& progress) {
    ResultSet out;
    out.variant = "oracle";
    out.backend = "cpu";
    out.results.resize(cases.cases.size());
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex progress_mutex;
    auto worker = [&] {
        for (std::size_t i; (i = next++) < cases.cases.size();) {
            out.results[i] = reference_case(cases.cases[i], opt);
            const std::size_t d = ++done;
            if (progress) {
                std::lock_guard<std::mutex> lock(progress_mutex);
                progress(d, cases.cases.size());
            }
        }
    };
    const unsigned n = std::max(1u, opt.threads);
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
    return out;
}

}  // namespace arealight
