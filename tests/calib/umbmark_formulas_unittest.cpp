/* hslam tests: UMBmark formulas (thesis 4.1, eq. 21-28) on hand-derived cases,
 * and the odometry correction's increment arithmetic. */
#include <gtest/gtest.h>
#include <hslam/calib/COdometryCorrection.h>
#include <hslam/calib/umbmark.h>

#include <cmath>

using namespace hslam::calib;

TEST(UmbmarkFormulas, PureTypeAErrorGivesEbOnly)
{
	// First-order model: x_cw = -2L(alpha + beta), x_ccw = -2L(alpha - beta).
	const double L = 4.0, alpha = 0.01;
	std::vector<TUmbmarkEndpoint> runs{{true, -2 * L * alpha, -2 * L * alpha, ""},
									   {false, -2 * L * alpha, 2 * L * alpha, ""}};
	TUmbmarkOptions o;
	o.side_length_m = L;
	o.exact_model = false;  // the first-order formulas as printed
	const auto r = computeUmbmark(runs, o);
	EXPECT_NEAR(r.alpha_rad, alpha, 1e-12);
	EXPECT_NEAR(r.beta_rad, 0.0, 1e-12);
	EXPECT_TRUE(std::isinf(r.radius_m));
	EXPECT_DOUBLE_EQ(r.ed, 1.0);
	EXPECT_NEAR(r.eb, 90.0 / (90.0 - alpha * 180 / M_PI), 1e-12);
	EXPECT_NEAR(r.corrected_wheelbase_m, r.eb * 0.335, 1e-12);
	EXPECT_NEAR(r.e_max_syst_m, 2 * L * alpha * std::sqrt(2.0), 1e-12);
}

TEST(UmbmarkFormulas, PureTypeBErrorGivesEdAndWheelFactors)
{
	const double L = 4.0, beta = 0.02, b = 0.335;
	std::vector<TUmbmarkEndpoint> runs{{true, -2 * L * beta, -2 * L * beta, ""},
									   {false, 2 * L * beta, -2 * L * beta, ""}};
	TUmbmarkOptions o;
	o.side_length_m = L;
	o.exact_model = false;
	const auto r = computeUmbmark(runs, o);
	EXPECT_NEAR(r.beta_rad, beta, 1e-12);
	EXPECT_NEAR(r.radius_m, 2.0 / std::sin(0.01), 1e-9);  // eq. 26
	const double R = r.radius_m;
	EXPECT_NEAR(r.ed, (R + b / 2) / (R - b / 2), 1e-12);  // eq. 27 (Eb = 1)
	EXPECT_NEAR(r.left_factor, 2 / (r.ed + 1), 1e-12);  // eq. 28
	EXPECT_NEAR(r.right_factor, 2 / (1 / r.ed + 1), 1e-12);
	EXPECT_GT(r.ed, 1.0) << "beta > 0 (left curve) means a larger right wheel";
}

TEST(UmbmarkFormulas, ThesisEq29HoldsOnlyWithRInCentimetres)
{
	// Thesis eq. 29: R = 110 000 and b = 33.5 cm give the printed d = 1.0003
	// only if R is in cm (1.1 km); read as mm it would be d = 1.00305.
	EXPECT_NEAR(wheelDiameterRatioFromRadius(110000, 33.5), 1.000305, 1e-6);
	EXPECT_NEAR(wheelDiameterRatioFromRadius(110000, 335), 1.003050, 1e-6);
	// Eq. 28 with d = 1.0003: left 0.99985, right 1.00015 (the thesis's eq. 30
	// prints them swapped: right 0.9998, left 1.0001).
	const double d = 1.0003;
	EXPECT_NEAR(2 / (1 + d), 0.99985, 1e-5);
	EXPECT_NEAR(2 / (1 / d + 1), 1.00015, 1e-5);
}

TEST(UmbmarkFormulas, ExactSquareModelRemovesTheSecondOrderBias)
{
	// End points of exact squares (L = 4 m, alpha = 0.004 rad, beta = 0.024 rad).
	const double L = 4.0, alpha = 0.004, beta = 0.024;
	const double xcw = squareEndpointX(L, alpha, beta, true), xccw = squareEndpointX(L, alpha, beta, false);
	EXPECT_NEAR(xcw, -2 * L * (alpha + beta), 0.01) << "first order holds to ~1 cm";
	double a = (xcw + xccw) / (-4 * L), b = (xcw - xccw) / (-4 * L);
	EXPECT_NEAR(a - alpha, -1.5 * beta * beta, 3e-4) << "eq. 23 is biased by about -1.5 beta^2";
	refineExact(L, xcw, xccw, a, b);
	EXPECT_NEAR(a, alpha, 1e-9);
	EXPECT_NEAR(b, beta, 1e-9);
}

TEST(UmbmarkFormulas, NeedsBothDirections)
{
	std::vector<TUmbmarkEndpoint> runs{{true, 0.1, 0.1, ""}};
	EXPECT_THROW(computeUmbmark(runs, {}), std::invalid_argument);
}

TEST(OdometryCorrection, DisabledIsIdentityAndUnitFactorsChangeNothing)
{
	const mrpt::poses::CPose2D inc = arcIncrement(0.05, 0.03);  // a differential drive moves on arcs
	COdometryCorrection off;
	EXPECT_EQ(off.correctIncrement(inc), inc);
	TOdometryCorrection unit;
	unit.enabled = true;
	const auto same = COdometryCorrection(unit).correctIncrement(inc);
	EXPECT_NEAR(same.x(), inc.x(), 1e-6);
	EXPECT_NEAR(same.y(), inc.y(), 1e-6);
	EXPECT_NEAR(same.phi(), inc.phi(), 1e-12);
}

TEST(OdometryCorrection, IncrementMatchesWheelTravelArithmetic)
{
	// Nominal wheel travels dL = 0.048, dR = 0.052 on b = 0.335; factors applied by hand.
	TOdometryCorrection c;
	c.enabled = true;
	c.left_factor = 1.01;
	c.right_factor = 0.99;
	c.wheelbase_ratio = 1.02;
	const double b = 0.335, dL = 0.048, dR = 0.052;
	const auto nominal = arcIncrement(0.5 * (dL + dR), (dR - dL) / b);
	const auto corrected = COdometryCorrection(c).correctIncrement(nominal);
	const auto expected = arcIncrement(0.5 * (1.01 * dL + 0.99 * dR), (0.99 * dR - 1.01 * dL) / (1.02 * b));
	EXPECT_NEAR(corrected.x(), expected.x(), 1e-9);
	EXPECT_NEAR(corrected.y(), expected.y(), 1e-9);
	EXPECT_NEAR(corrected.phi(), expected.phi(), 1e-9);
	// Backwards motion keeps its sign.
	const auto back = COdometryCorrection(c).correctIncrement(arcIncrement(-0.05, 0.0));
	EXPECT_LT(back.x(), -0.049);
}
