/* alignmentFit (alignment_fit.h) on hand-derived cases. The reference is a
 * wall y = 0 sampled every 1 mm from x = -1 to 11 m, so the nearest reference
 * point of (x, y) with 0 <= x <= 10 lies at distance |y| (to 0.5 mm). The
 * scan holds 10 points (1 ... 10, 0) in the robot frame.
 *   pose (0, 0, 0):      every d = 0         -> fit = 1
 *   pose (0, s, 0):      every d = s = sigma -> fit = exp(-1/2) = 0.6065
 *   pose (0, 0, theta):  point k at d = k sin(theta); for theta = 0.01 rad,
 *                        sigma = 0.05 m: mean of exp(-(0.01 k)^2 / 0.005)
 *                        over k = 1..10 (to 1e-4) = 0.5545
 * and the seed case the fit decides: a scan that pairs equally at two poses
 * under a loose threshold but fits one of them far better. */
#include <gtest/gtest.h>
#include <hslam/matching/CPointIndex2D.h>
#include <hslam/matching/alignment_fit.h>
#include <hslam/matching/scan_points.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace hslam::matching;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kSigma_m = 0.05;

mrpt::maps::CSimplePointsMap wallMap()
{
	mrpt::maps::CSimplePointsMap m;
	for (int i = -1000; i <= 11000; ++i) m.insertPointFast(0.001f * static_cast<float>(i), 0.f, 0.f);
	m.mark_as_modified();
	return m;
}

CPointIndex2D wallIndex()
{
	std::vector<float> xs, ys;
	for (int i = -1000; i <= 11000; ++i) xs.push_back(0.001f * static_cast<float>(i)), ys.push_back(0.f);
	CPointIndex2D index;
	index.build(std::move(xs), std::move(ys));
	return index;
}

mrpt::maps::CSimplePointsMap scanPoints()
{
	mrpt::maps::CSimplePointsMap m;
	for (int k = 1; k <= 10; ++k) m.insertPointFast(static_cast<float>(k), 0.f, 0.f);
	return m;
}

double expectedRotatedFit(double theta_rad)
{
	double sum = 0;
	for (int k = 1; k <= 10; ++k)
	{
		const double d = k * std::sin(theta_rad);
		sum += std::exp(-0.5 * d * d / (kSigma_m * kSigma_m));
	}
	return sum / 10;
}
}  // namespace

/** The three hand-derived figures of the file comment, for either reference type. */
template <class Reference>
void expectHandDerivedFigures(const Reference& reference)
{
	const auto scan = scanPoints();
	EXPECT_NEAR(alignmentFit(reference, scan, CPose2D(0, 0, 0), kSigma_m), 1.0, 1e-3);
	EXPECT_NEAR(alignmentFit(reference, scan, CPose2D(0, kSigma_m, 0), kSigma_m), std::exp(-0.5), 1e-3);
	EXPECT_NEAR(alignmentFit(reference, scan, CPose2D(0, 0, 0.01), kSigma_m), expectedRotatedFit(0.01), 2e-3);
}

TEST(AlignmentFit, IsOneOnTheReferenceAndExpMinusHalfOneSigmaOff)
{
	expectHandDerivedFigures(wallMap());
	EXPECT_NEAR(expectedRotatedFit(0.01), 0.5545, 1e-4);
}

TEST(AlignmentFit, IndexReferenceGivesTheSameFigures) { expectHandDerivedFigures(wallIndex()); }

TEST(AlignmentFit, EmptyInputsAndNoSigmaGiveZero)
{
	const auto ref = wallMap();
	EXPECT_EQ(alignmentFit(ref, mrpt::maps::CSimplePointsMap(), CPose2D(), kSigma_m), 0.0);
	EXPECT_EQ(alignmentFit(mrpt::maps::CSimplePointsMap(), scanPoints(), CPose2D(), kSigma_m), 0.0);
	EXPECT_EQ(alignmentFit(ref, scanPoints(), CPose2D(), 0.0), 0.0);
}

TEST(AlignmentFit, TellsApartTwoPosesAThresholdCountCannot)
{
	// At 0.04 m and 0.12 m off the wall every point is within a 0.15 m
	// pairing threshold (a goodness of 1 for both); the fit is exp(-0.32) =
	// 0.726 against exp(-2.88) = 0.056.
	const auto ref = wallMap();
	const auto scan = scanPoints();
	const double nearFit = alignmentFit(ref, scan, CPose2D(0, 0.04, 0), kSigma_m);
	const double farFit = alignmentFit(ref, scan, CPose2D(0, 0.12, 0), kSigma_m);
	EXPECT_NEAR(nearFit, std::exp(-0.32), 2e-3);
	EXPECT_NEAR(farFit, std::exp(-2.88), 2e-3);
	EXPECT_GT(nearFit, 10 * farFit);
}

namespace
{
/** A 1 deg, 181-beam scan from (x0, 0) facing +x down a corridor between
 * the walls y = +-1 that ends at x = 8, in the robot frame. */
mrpt::maps::CSimplePointsMap corridorScanFrom(double x0)
{
	mrpt::maps::CSimplePointsMap m;
	for (int b = -90; b <= 90; ++b)
	{
		const double a = mrpt::DEG2RAD(static_cast<double>(b)), c = std::cos(a), s = std::sin(a);
		double range = c > 0 ? (8.0 - x0) / c : 1e9;  // the end wall
		if (std::abs(s) > 1e-9) range = std::min(range, 1.0 / std::abs(s));  // a side wall
		m.insertPointFast(static_cast<float>(range * c), static_cast<float>(range * s), 0.f);
	}
	return m;
}
}  // namespace

TEST(AlignmentFit, SegmentsDoNotFavourTheReferenceScansOwnPose)
{
	// The reference scan from x = 0, the scan from x = 0.3 m. Placed at zero
	// motion the scan's 166 side-wall points land exactly on reference points
	// (same bearings, same walls) and only its 15 end-wall points are off by
	// 0.3 m; at the true pose the side-wall points fall between the
	// reference's samples, which lie 0.16 m apart 3 m ahead and 0.44 m apart
	// 5 m ahead. Nearest points prefer zero motion; segments between
	// neighbouring samples (at most 0.5 m long) prefer the true pose (the
	// points more than 5.3 m ahead, samples over 0.5 m apart, still fit badly).
	const auto reference = corridorScanFrom(0.0);
	const auto scan = corridorScanFrom(0.3);
	const CPose2D truth(0.3, 0, 0), zero(0, 0, 0);
	const double pointTrue = alignmentFit(reference, scan, truth, kSigma_m);
	const double pointZero = alignmentFit(reference, scan, zero, kSigma_m);
	EXPECT_NEAR(pointZero, 166.0 / 181.0, 1e-3);
	EXPECT_LT(pointTrue, pointZero - 0.04);  // 0.859 against 0.917
	const double segmentTrue = alignmentFit(reference, scan, truth, kSigma_m, 0.5);
	const double segmentZero = alignmentFit(reference, scan, zero, kSigma_m, 0.5);
	EXPECT_NEAR(segmentZero, 166.0 / 181.0, 1e-3);
	EXPECT_GT(segmentTrue, segmentZero + 0.03);  // 0.956 against 0.917
	// segments longer than the limit are not bridged: 0.01 m keeps nearest points
	EXPECT_NEAR(alignmentFit(reference, scan, truth, kSigma_m, 0.01), pointTrue, 1e-6);
	std::cout << "corridor fits, nearest point: true " << pointTrue << ", zero " << pointZero
			  << "; segment: true " << segmentTrue << ", zero " << segmentZero << "\n";
}
