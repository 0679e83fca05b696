/* Tests of the total-least-squares fit (thesis eq. 57-64) and TLineSegment. */
#include <gtest/gtest.h>
#include <hslam/features/line_fit.h>
#include <hslam/features/line_segment.h>

#include <cmath>
#include <random>

using hslam::features::fitLineTotalLeastSquares;
using hslam::features::TLineFit;
using hslam::features::TLineSegment;
using mrpt::math::TPoint2D;

namespace
{
std::vector<TPoint2D> pointsOnLine(TPoint2D a, TPoint2D b, int n)
{
	std::vector<TPoint2D> pts;
	for (int i = 0; i < n; ++i)
	{
		const double t = static_cast<double>(i) / (n - 1);
		pts.emplace_back(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
	}
	return pts;
}
}  // namespace

TEST(LineFit, ExactOnNoiselessHorizontalVerticalAndDiagonalLines)
{
	struct TCase
	{
		TPoint2D a, b;
		double rho, alpha;
	};
	const TCase cases[] = {
		{{-1, 2}, {3, 2}, 2.0, M_PI / 2},  // y = 2
		{{-1, -3}, {4, -3}, 3.0, -M_PI / 2},  // y = -3
		{{2, -1}, {2, 5}, 2.0, 0.0},  // x = 2 (vertical: the thesis' slope form fails here)
		{{-4, -1}, {-4, 5}, 4.0, M_PI},  // x = -4: alpha = pi, inside (-pi, pi]
		{{0, 2}, {2, 0}, std::sqrt(2.0), M_PI / 4},  // x + y = 2
	};
	for (const auto& c : cases)
	{
		const TLineFit fit = fitLineTotalLeastSquares(pointsOnLine(c.a, c.b, 20));
		ASSERT_TRUE(fit.valid);
		EXPECT_NEAR(fit.rho_m, c.rho, 1e-12) << c.a.x << "," << c.a.y;
		EXPECT_NEAR(fit.alpha_rad, c.alpha, 1e-12) << c.a.x << "," << c.a.y;
		EXPECT_LT(fit.rms_m, 1e-12);
		EXPECT_LT(fit.max_residual_m, 1e-12);
	}
}

TEST(LineFit, MatchesThesisQuadraticForTheSlope)
{
	// eq. 62-64: the TLS slope is a root of K2 m^2 + K1 m - K2 = 0 with
	// c = ybar - m xbar; the root that minimises eq. 59.
	std::mt19937 rng(3);
	std::normal_distribution<double> noise(0, 0.05);
	std::vector<TPoint2D> pts;
	for (int i = 0; i < 40; ++i) pts.emplace_back(0.1 * i + noise(rng), 0.7 * 0.1 * i + 1.3 + noise(rng));
	double xm = 0, ym = 0;
	for (const auto& p : pts) xm += p.x / pts.size(), ym += p.y / pts.size();
	double K2 = 0, K1 = 0;
	for (const auto& p : pts) K2 += (p.x - xm) * (p.y - ym), K1 += (p.x - xm) * (p.x - xm) - (p.y - ym) * (p.y - ym);
	auto e2 = [&](double m) {
		const double c = ym - m * xm;
		double s = 0;
		for (const auto& p : pts) s += (p.y - m * p.x - c) * (p.y - m * p.x - c) / (1 + m * m);
		return s;
	};
	const double d = std::sqrt(K1 * K1 + 4 * K2 * K2);
	const double m1 = (-K1 + d) / (2 * K2), m2 = (-K1 - d) / (2 * K2);
	const double mThesis = e2(m1) < e2(m2) ? m1 : m2;

	TLineSegment s;
	const TLineFit fit = fitLineTotalLeastSquares(pts);
	s.rho_m = fit.rho_m;
	s.alpha_rad = fit.alpha_rad;
	const auto mc = s.slopeIntercept();
	ASSERT_TRUE(mc.has_value());
	EXPECT_NEAR(mc->first, mThesis, 1e-9);
	EXPECT_NEAR(mc->second, ym - mThesis * xm, 1e-9);
	EXPECT_NEAR(mc->first, 0.7, 0.05);  // and it is the right line
}

TEST(LineFit, DegenerateInputsAreInvalid)
{
	EXPECT_FALSE(fitLineTotalLeastSquares({}).valid);
	EXPECT_FALSE(fitLineTotalLeastSquares({{1, 1}}).valid);
	EXPECT_FALSE(fitLineTotalLeastSquares({{1, 1}, {1, 1}, {1, 1}}).valid);
	EXPECT_TRUE(fitLineTotalLeastSquares({{1, 1}, {2, 1}}).valid);
}

TEST(LineFit, ResidualsOfNoisyPoints)
{
	// pairs of points 2 cm above and below y = 1: the fit is y = 1, rms = max = 2 cm
	std::vector<TPoint2D> pts;
	for (int i = 0; i < 10; ++i)
	{
		pts.emplace_back(i * 0.1, 1.02);
		pts.emplace_back(i * 0.1, 0.98);
	}
	const TLineFit fit = fitLineTotalLeastSquares(pts);
	EXPECT_NEAR(fit.rho_m, 1.0, 1e-12);
	EXPECT_NEAR(fit.alpha_rad, M_PI / 2, 1e-12);
	EXPECT_NEAR(fit.rms_m, 0.02, 1e-12);
	EXPECT_NEAR(fit.max_residual_m, 0.02, 1e-12);
}

TEST(LineSegment, DerivedQuantities)
{
	TLineSegment s;
	s.p0 = {2, -1};
	s.p1 = {2, 3};
	s.rho_m = 2;
	s.alpha_rad = 0;  // x = 2
	EXPECT_DOUBLE_EQ(s.length_m(), 4.0);
	EXPECT_DOUBLE_EQ(s.midpoint().y, 1.0);
	EXPECT_NEAR(s.directionAngle_rad(), M_PI / 2, 1e-12);
	EXPECT_FALSE(s.slopeIntercept().has_value()) << "vertical line has no slope";
	EXPECT_NEAR(s.distanceTo({3, 7}), 1.0, 1e-12);
	EXPECT_NEAR(s.distanceTo({0, 0}), -2.0, 1e-12);

	TLineSegment h;  // y = 0.5 x + 1  <=>  normal (-0.5, 1)/|.|, rho = 1/|.|
	const double len = std::hypot(0.5, 1.0);
	h.alpha_rad = std::atan2(1.0, -0.5);
	h.rho_m = 1.0 / len;
	const auto mc = h.slopeIntercept();
	ASSERT_TRUE(mc.has_value());
	EXPECT_NEAR(mc->first, 0.5, 1e-12);
	EXPECT_NEAR(mc->second, 1.0, 1e-12);
}

TEST(LineFit, LineAngleDifferenceIsUndirected)
{
	using hslam::features::lineAngleDifference_rad;
	EXPECT_NEAR(lineAngleDifference_rad(0.1, 0.1 + M_PI), 0.0, 1e-12);
	EXPECT_NEAR(lineAngleDifference_rad(M_PI - 0.05, -M_PI + 0.05), 0.1, 1e-12);
	EXPECT_NEAR(lineAngleDifference_rad(0, M_PI / 2), M_PI / 2, 1e-12);
	EXPECT_NEAR(lineAngleDifference_rad(0, 3 * M_PI / 4), M_PI / 4, 1e-12);
}

TEST(LineFit, CovarianceOfRhoAlphaMatchesMonteCarlo)
{
	// 30 points along a 1.5 m wall whose centroid is 2 m along the line from
	// the foot of the normal (so rho and alpha are correlated), noise 1 cm
	const double alpha = 0.3, rho = 3.0, sigma = 0.01;
	const double nx = std::cos(alpha), ny = std::sin(alpha), ux = -ny, uy = nx;
	std::mt19937 rng(5);
	std::normal_distribution<double> noise(0, sigma);
	const int runs = 4000;
	double sr = 0, sa = 0, srr = 0, saa = 0, sra = 0, predRR = 0, predAA = 0, predRA = 0;
	for (int k = 0; k < runs; ++k)
	{
		std::vector<TPoint2D> pts;
		for (int i = 0; i < 30; ++i)
		{
			const double t = 1.25 + 0.05 * i, e = noise(rng), f = noise(rng);
			pts.emplace_back(rho * nx + t * ux + e, rho * ny + t * uy + f);
		}
		const TLineFit fit = fitLineTotalLeastSquares(pts);
		const double dr = fit.rho_m - rho, da = fit.alpha_rad - alpha;
		sr += dr, sa += da, srr += dr * dr, saa += da * da, sra += dr * da;
		predRR += fit.var_rho_m2 / runs, predAA += fit.var_alpha_rad2 / runs, predRA += fit.cov_rho_alpha_m_rad / runs;
	}
	const double mr = sr / runs, ma = sa / runs;
	const double varR = srr / runs - mr * mr, varA = saa / runs - ma * ma, covRA = sra / runs - mr * ma;
	EXPECT_NEAR(predAA / varA, 1.0, 0.1);
	EXPECT_NEAR(predRR / varR, 1.0, 0.1);
	EXPECT_NEAR(predRA / covRA, 1.0, 0.1);
	EXPECT_GT(std::abs(covRA) / std::sqrt(varR * varA), 0.8) << "strongly correlated by construction";
	// noiseless: zero
	EXPECT_EQ(fitLineTotalLeastSquares(pointsOnLine({0, 1}, {2, 1}, 10)).var_alpha_rad2 < 1e-20, true);
}
