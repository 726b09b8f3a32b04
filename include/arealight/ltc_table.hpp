// Linearly transformed cosines (Heitz et al. 2016; seed 001): the fitted tables,
// their file format, the fitter (`arealight fit-ltc`) and the textures the
// shaders sample (templates/method/ltc.glsl).
//
// Conventions shared with the shader (change both together):
// - Local frame: z = n, x = normalize(v - n (n.v)), y = z cross x; so the view is
//   (sin theta_v, 0, cos theta_v).
// - The LTC maps the clamped cosine D_o(w_o) = max(w_o.z, 0) / pi to
//   D(w) = D_o(w_o) |dw_o / dw|, w_o = Minv w / |Minv w|, with
//   Minv = [[a, 0, b], [0, c, 0], [d, 0, 1]] (rows), i.e.
//   w_o = (a w.x + b w.z, c w.y, d w.x + w.z) before normalisation.
// - Grid: texel (i, j) of a size x size table sits at
//   u = i / (size - 1) (roughness: rho = rho_min + u (rho_max - rho_min), rho = alpha^(1/p),
//                       p = ltc_axis_power: 3 for beckmann, 2 otherwise; phong and blinn
//                       use alpha = sqrt(2 / (N + 2))),
//   w = j / (size - 1) (view: cos theta_v = 1 - w^2).
//   The shader samples at ((u, w) (size - 1) + 0.5) / size with linear filtering,
//   so texel centres are exactly the fitted cells.
// - Texture 0 (matrix): (a, b, c, d) per cell; for GGX (ltc_alpha_scaled) (alpha a,
//   alpha b, alpha c, d), alpha = rho^p the cell's, and the shader divides the filtered
//   (a, b, c) by the case's alpha (clamped to the grid's range): entries that grow as
//   1 / alpha then interpolate as the lobe's width does (fit/ltc_fit.cpp: why GGX only).
// - Texture 1 (amplitude): (A, B, K, S) per cell. Specular of a light region P is
//   (f0 A + B) times the lobe's integral over P (phong: A, B = 0). The lobe is one
//   LTC (GGX, K = 0) or, for the Gaussian-tailed lobes (phong, blinn, beckmann), the
//   LTC of the kernel D_o + K D_s, D_s the clamped cosine widened by s =
//   kLtcSecondLobeWidth in x and y: its integral over P is the LTC's plus K times that of
//   Minv2 = diag(1 / s, 1 / s, 1) Minv (fit/ltc_fit.cpp: why). A and B are the
//   f0 and 1 - f0 parts of the integral of f (n.w) over the hemisphere (Schlick F =
//   f0 (1 - x) + x with x = (1 - h.v)^5), each divided by the LTC's own integral over
//   the hemisphere (h1 + K h2 for two lobes), so that a light filling the hemisphere is
//   exact. S is the
//   sphere-proxy horizon table (seed 001): texel (i, j) holds I(cos omega, sigma) /
//   sin^2 sigma for cos omega = 2 u - 1 and sin^2 sigma = w, the horizon-clipped
//   form factor of a sphere of angular radius sigma at angle omega from n over its
//   unclipped one (Snyder's closed form).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "arealight/case.hpp"
#include "arealight/diagnostics.hpp"
#include "arealight/texture.hpp"

namespace arealight {

// The second lobe's widening s (see above); the shader's AL_LTC_SECOND is diag(1 / s, 1 / s, 1).
constexpr double kLtcSecondLobeWidth = 1.2;

// Whether a distribution's table fits the two-lobe kernel (K free) or one LTC (K = 0).
bool ltc_two_lobes(Distribution d);

// Whether a distribution's matrix texture holds (a, b, c) times the cell's alpha (above).
bool ltc_alpha_scaled(Distribution d);

// One fitted cell.
struct LtcCell {
    double a = 1, b = 0, c = 1, d = 0;  // Minv, as above
    double amp_f0 = 1, amp_one = 0;     // A, B
    double kappa = 0;                   // K
    double error = 0;                   // the fit metric at the optimum (for reports)
};

// The cell whose LTC is c's second lobe: Minv's first two rows (a, b, c) over s.
LtcCell ltc_second_lobe(const LtcCell& c);

struct LtcTable {
    Distribution dist = Distribution::Ggx;
    int size = 64;
    double rho_min = 0, rho_max = 1;  // range of rho = alpha^(1/p) over u in [0, 1]
    std::vector<LtcCell> cells;       // size * size, cell (i, j) at j * size + i
    std::string command;              // the command that produced it (the file's header)

    const LtcCell& at(int i, int j) const { return cells[static_cast<std::size_t>(j) * size + i]; }
};

// The roughness axis: rho = alpha^(1/p) with p = ltc_axis_power(d), 3 for beckmann (its
// alphas reach 0.001, where sqrt(alpha)'s columns step by 2.2x in alpha: fit/ltc_fit.cpp),
// 2 for the others (phong and blinn through alpha = sqrt(2 / (N + 2)) reach 0.0045 only).
int ltc_axis_power(Distribution d);
double ltc_rho_of_alpha(Distribution d, double alpha);
double ltc_alpha_of_rho(Distribution d, double rho);

// rho's range for a distribution: alpha in [0.001, 1] (ggx, beckmann), or N in [1, 100000]
// through alpha = sqrt(2 / (N + 2)) (phong, blinn): CONTRACT.md 2.
void ltc_rho_range(Distribution d, double& rho_min, double& rho_max);

// The (roughness, view) of cell (i, j) of a size x size table. ltc_cell_cos_theta is the
// grid's value (0 on the last row); the fit uses max(it, 1e-3) (fit/ltc_fit.cpp).
double ltc_cell_rho(const LtcTable& t, int i);
double ltc_cell_alpha(const LtcTable& t, int i);  // ltc_alpha_of_rho of ltc_cell_rho
// The factor the matrix texture applies to (a, b, c) of column i: its alpha where
// ltc_alpha_scaled, else 1; and the shader's divisor of the filtered (a, b, c) at a lobe's
// rho (its alpha, rho clamped to the table's range, or 1).
double ltc_matrix_scale(const LtcTable& t, int i);
double ltc_matrix_scale_at(const LtcTable& t, double rho);
double ltc_cell_cos_theta(int size, int j);

struct LtcFitOptions {
    int size = 64;
    int threads = 0;  // 0: hardware concurrency
    // Called after each finished cell (from the calling thread); may be empty.
    std::function<void(int done, int total)> progress;
};

// Fits every cell; nullopt with a diagnostic on failure.
std::optional<LtcTable> fit_ltc(Distribution d, const LtcFitOptions& opt,
                                const DiagnosticConsumer& diag);

// Fits one cell (i, j) of a size x size table, starting from `start` (a neighbour's
// solution; nullptr: the method's own starting point). Deterministic.
LtcCell fit_ltc_cell(Distribution d, int size, int i, int j, const LtcCell* start);
// The same as fit_ltc does it: the cells of the smallest roughnesses (i < 4) are also
// fitted for bilinear interpolation, halfway to their neighbours next_u = (i + 1, j) and
// prev_w = (i, j - 1) (nullptr where there is none); fit_ltc passes start = (i, j - 1), or
// (i + 1, 0) on the row j = 0. Elsewhere the neighbours are not used.
LtcCell fit_ltc_cell(Distribution d, int size, int i, int j, const LtcCell* start,
                     const LtcCell* next_u, const LtcCell* prev_w);

// The file format: text, bannered "generated by arealight fit-ltc; do not edit".
std::string format_ltc_table(const LtcTable& t);
std::optional<LtcTable> parse_ltc_table(const std::string& text, const std::string& file_name,
                                        const DiagnosticConsumer& diag);

// The committed table of a distribution, compiled into the binary (parsed once).
const LtcTable& builtin_ltc_table(Distribution d);

// The two textures of the shader (matrix, amplitude) built from a table; the
// builtin ones are built once and live for the program.
std::vector<Texture2D> ltc_textures(const LtcTable& t);
const std::vector<Texture2D>& builtin_ltc_textures(Distribution d);

// Horizon-clipped form factor of a sphere of angular radius sigma whose centre is at
// angle omega from the normal, over pi (in [0, 1]): seed 001's I_hemisphere.
double sphere_horizon_form_factor(double cos_omega, double sin_sigma);

}  // namespace arealight
