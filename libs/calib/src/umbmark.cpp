/* hslam calib: UMBmark (thesis 4.1, eq. 21-28); conventions in umbmark.h. */
#include <hslam/calib/umbmark.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hslam::calib
{
TCentreOfGravity centreOfGravity(const std::vector<TUmbmarkEndpoint>& runs, bool clockwise)
{
	TCentreOfGravity cg;
	for (const auto& r : runs)
	{
		if (r.clockwise != clockwise) continue;
		cg.x_m += r.err_x_m;
		cg.y_m += r.err_y_m;
		++cg.runs;
	}
	if (cg.runs == 0) return cg;
	cg.x_m /= cg.runs;  // eq. 21
	cg.y_m /= cg.runs;  // eq. 22
	cg.r_m = std::hypot(cg.x_m, cg.y_m);
	return cg;
}

double squareEndpointX(double L, double alpha, double beta, bool clockwise)
{
	const double turn = (clockwise ? -1.0 : 1.0) * (0.5 * M_PI - alpha);
	const double chord = std::abs(beta) > 1e-12 ? 2.0 * L / beta * std::sin(0.5 * beta) : L;
	double x = 0, heading = 0;
	for (int leg = 0; leg < 4; ++leg)
	{
		x += chord * std::cos(heading + 0.5 * beta);
		heading += beta + (leg < 3 ? turn : 0.0);
	}
	return x;
}

void refineExact(double L, double x_cw, double x_ccw, double& alpha, double& beta)
{
	for (int it = 0; it < 20; ++it)
	{
		const double h = 1e-7;
		const double f1 = squareEndpointX(L, alpha, beta, true) - x_cw;
		const double f2 = squareEndpointX(L, alpha, beta, false) - x_ccw;
		const double a11 = (squareEndpointX(L, alpha + h, beta, true) - x_cw - f1) / h;
		const double a12 = (squareEndpointX(L, alpha, beta + h, true) - x_cw - f1) / h;
		const double a21 = (squareEndpointX(L, alpha + h, beta, false) - x_ccw - f2) / h;
		const double a22 = (squareEndpointX(L, alpha, beta + h, false) - x_ccw - f2) / h;
		const double det = a11 * a22 - a12 * a21;
		if (std::abs(det) < 1e-12) return;
		const double da = (f1 * a22 - f2 * a12) / det, db = (a11 * f2 - a21 * f1) / det;
		alpha -= da;
		beta -= db;
		if (std::abs(da) + std::abs(db) < 1e-12) return;
	}
}

double wheelDiameterRatioFromRadius(double radius_m, double wheelbase_m)
{
	if (!std::isfinite(radius_m)) return 1.0;
	return (radius_m + 0.5 * wheelbase_m) / (radius_m - 0.5 * wheelbase_m);  // eq. 27
}

TUmbmarkResult computeUmbmark(const std::vector<TUmbmarkEndpoint>& runs, const TUmbmarkOptions& o)
{
	TUmbmarkResult res;
	res.cw = centreOfGravity(runs, true);
	res.ccw = centreOfGravity(runs, false);
	if (res.cw.runs == 0 || res.ccw.runs == 0)
		throw std::invalid_argument("UMBmark needs at least one clockwise and one counter-clockwise run (got " +
									std::to_string(res.cw.runs) + " CW, " + std::to_string(res.ccw.runs) + " CCW)");
	const double L = o.side_length_m;
	res.alpha_first_order_rad = res.alpha_rad = (res.cw.x_m + res.ccw.x_m) / (-4.0 * L);  // eq. 23 (radians)
	res.beta_first_order_rad = res.beta_rad = (res.cw.x_m - res.ccw.x_m) / (-4.0 * L);  // eq. 24 (radians)
	if (o.exact_model) refineExact(L, res.cw.x_m, res.ccw.x_m, res.alpha_rad, res.beta_rad);
	res.radius_m = res.beta_rad == 0 ? std::numeric_limits<double>::infinity()
									 : (0.5 * L) / std::sin(0.5 * res.beta_rad);  // eq. 26
	const double alpha_deg = res.alpha_rad * 180.0 / M_PI;
	res.eb = 90.0 / (90.0 - alpha_deg);  // eq. 25
	res.corrected_wheelbase_m = res.eb * o.nominal_wheelbase_m;
	// Eq. 27 with the corrected (actual) wheelbase: the circle a straight
	// command drives on is set by the real wheels (the thesis used nominal b;
	// the difference is Eb - 1 of Ed - 1, below 1 % of it here).
	res.ed = wheelDiameterRatioFromRadius(res.radius_m, res.corrected_wheelbase_m);
	res.left_factor = 2.0 / (res.ed + 1.0);  // eq. 28
	res.right_factor = 2.0 / (1.0 / res.ed + 1.0);
	res.e_max_syst_m = std::max(res.cw.r_m, res.ccw.r_m);
	return res;
}

}  // namespace hslam::calib
