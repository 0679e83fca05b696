/* hslam calib: UMBmark odometry calibration (thesis 4.1, eq. 21-31;
 * Borenstein & Feng, IEEE Trans. Robotics and Automation 12(6), 1996).
 *
 * Conventions (tested on simulated robots with known Ed, Eb in tests/calib):
 *  - every run starts at its start pose with the first leg along the run's +x
 *    axis; a CW run turns right (first corner at (L, 0), then (L, -L)), a CCW
 *    run turns left ((L, 0), then (L, L));
 *  - an end-point error is TRUE minus ODOMETRY end position, in that frame;
 *  - alpha > 0: the robot turns less than commanded (actual wheelbase longer
 *    than nominal, Eb > 1); beta > 0: a straight leg curves to the LEFT
 *    (right wheel larger, Ed = D_R / D_L > 1).
 * With these, to first order x_cw = -2L(alpha + beta), x_ccw = -2L(alpha - beta),
 * hence alpha = (x_cw + x_ccw) / (-4L) and beta = (x_cw - x_ccw) / (-4L) (eq. 23-24
 * with 14.324 = 180 / (4 pi) turning radians into degrees). */
#pragma once

#include <string>
#include <vector>

namespace hslam::calib
{
/** One UMBmark run's end-point error (true - odometry), UMBmark frame. */
struct TUmbmarkEndpoint
{
	bool clockwise = true;
	double err_x_m = 0;
	double err_y_m = 0;
	std::string label;  //!< where it came from (run number, table row), for reports
};

struct TUmbmarkOptions
{
	double side_length_m = 4.0;  //!< L, side of the square (thesis: 4.4 m)
	double nominal_wheelbase_m = 0.335;  //!< b as configured in the odometry (thesis: 33.5 cm)
	/** Refine alpha, beta with the exact square model (see refineExact()); false = eq. 23-24 only. */
	bool exact_model = true;

	template <class V>
	void visit(V& v)
	{
		v.real("side_length_m", side_length_m, 0.1, 100.0);
		v.real("nominal_wheelbase_m", nominal_wheelbase_m, 0.05, 5.0);
		v.flag("exact_model", exact_model);
	}
};

/** Centre of gravity of one direction's cluster (eq. 21-22) and its distance r. */
struct TCentreOfGravity
{
	double x_m = 0, y_m = 0;
	double r_m = 0;  //!< sqrt(x^2 + y^2)
	int runs = 0;
};

struct TUmbmarkResult
{
	TCentreOfGravity cw, ccw;
	double alpha_rad = 0;  //!< type-A (turn) error: eq. 23, refined if exact_model
	double beta_rad = 0;  //!< type-B (straight-leg curvature) error: eq. 24, refined if exact_model
	double alpha_first_order_rad = 0, beta_first_order_rad = 0;  //!< eq. 23-24 as printed
	double radius_m = 0;  //!< eq. 26, signed like beta (infinite if beta = 0)
	double eb = 1;  //!< actual / nominal wheelbase = 90 / (90 - alpha_deg)  (eq. 25)
	double corrected_wheelbase_m = 0;  //!< Eb * nominal wheelbase
	double ed = 1;  //!< D_R / D_L, eq. 27 with the corrected wheelbase
	double left_factor = 1;  //!< c_L = 2 / (Ed + 1), eq. 28
	double right_factor = 1;  //!< c_R = 2 / (1/Ed + 1), eq. 28
	double e_max_syst_m = 0;  //!< max(r_cw, r_ccw): Borenstein's measure of odometric accuracy
};

/** Centre of gravity (eq. 21-22) of the runs of one direction. */
TCentreOfGravity centreOfGravity(const std::vector<TUmbmarkEndpoint>& runs, bool clockwise);

/** UMBmark from end-point errors. Throws std::invalid_argument unless there
 * is at least one CW and one CCW run. */
TUmbmarkResult computeUmbmark(const std::vector<TUmbmarkEndpoint>& runs, const TUmbmarkOptions& options);

/** x of the end point of an exact UMBmark square (legs of length L on arcs
 * turning beta each, turns of 90 deg - alpha), error frame of umbmark.h. */
double squareEndpointX(double side_m, double alpha_rad, double beta_rad, bool clockwise);

/** Solves squareEndpointX(alpha, beta, CW) = x_cw and (.., CCW) = x_ccw by
 * Newton's method from the first-order solution. Eq. 23-24 are the first-order
 * terms of this model; their second-order error is about -1.5 beta^2 on alpha
 * (e.g. Ed = 1.002 on a 4 m square: Eb - 1 off by -0.0005, a quarter of an
 * Eb error of 0.002). */
void refineExact(double side_m, double x_cw, double x_ccw, double& alpha_rad, double& beta_rad);

/** Ed from the radius of the straight-leg circle (eq. 27): (R + b/2) / (R - b/2). */
double wheelDiameterRatioFromRadius(double radius_m, double wheelbase_m);

}  // namespace hslam::calib
