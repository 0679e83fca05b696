/* compareScanConsistency / readScanPoints (scan_consistency.h) on
 * hand-derived cases.
 *
 * The scans see four isolated points, 2 m apart (farther than the 0.3 m cap
 * from each other), so each point's nearest neighbour in the previous scan
 * is its own counterpart: a trajectory whose step is off by a pure
 * translation t misfits the pair by exactly min(|t|, 0.3 m), and the true
 * poses misfit it by 0. */
#include <gtest/gtest.h>
#include <hslam/eval/scan_consistency.h>
#include <hslam/io/CRawlogObservationWriter.h>
#include <hslam/testing/temp_dir.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/datetime.h>

#include <cmath>
#include <stdexcept>

using namespace hslam::eval;
using hslam::common::TTimedPose2D;
using hslam::common::TTrajectory2D;
using mrpt::poses::CPose2D;

namespace
{
const std::vector<mrpt::math::TPoint2D> kWorld = {{3, 0}, {3, 2}, {5, -2}, {1, 3}};

/** What a robot at `robot` sees of the world points, in its own frame. */
TScanPoints2D scanFrom(const CPose2D& robot, double t_s)
{
	TScanPoints2D s;
	s.t_s = t_s;
	for (const auto& p : kWorld) s.points.push_back(robot.inverseComposePoint(p));
	return s;
}

TTrajectory2D trajectory(const std::vector<CPose2D>& poses, double t0_s = 0)
{
	TTrajectory2D out;
	for (size_t i = 0; i < poses.size(); ++i) out.push_back({t0_s + static_cast<double>(i), poses[i].asTPose()});
	return out;
}
}  // namespace

TEST(ScanConsistency, ATranslationSlipMisfitsByItsLengthCappedAtTheTruncation)
{
	const std::vector<CPose2D> truth = {{0, 0, 0}, {0.5, 0.1, 0.2}, {0.9, 0.3, 0.5}, {1.2, 0.2, 0.3}};
	std::vector<TScanPoints2D> scans;
	for (size_t i = 0; i < truth.size(); ++i) scans.push_back(scanFrom(truth[i], static_cast<double>(i)));
	// the estimate: the step into scan 2 is 0.1 m too long along x (every pose
	// after it shifted too), the step into scan 3 0.5 m too long along y
	std::vector<CPose2D> est = truth;
	for (size_t i = 2; i < est.size(); ++i) est[i] = CPose2D(est[i].x() + 0.1, est[i].y(), est[i].phi());
	est[3] = CPose2D(est[3].x(), est[3].y() + 0.5, est[3].phi());

	const TScanConsistency c = compareScanConsistency(scans, trajectory(truth), trajectory(est), {});
	ASSERT_EQ(c.pairs.size(), 3u);
	EXPECT_EQ(c.scans, 4u);
	for (const auto& p : c.pairs) EXPECT_NEAR(p.reference_m, 0.0, 1e-6);
	EXPECT_NEAR(c.pairs[0].estimate_m, 0.0, 1e-6);
	EXPECT_NEAR(c.pairs[1].estimate_m, 0.1, 1e-6);  // the step's error, in the earlier scan's frame
	EXPECT_NEAR(c.pairs[2].estimate_m, 0.3, 1e-6);  // 0.5 m, capped
	EXPECT_NEAR(c.estimate_mean_m, 0.4 / 3, 1e-6);
	EXPECT_EQ(c.estimate_worse.size(), 2u);
	EXPECT_EQ(c.estimate_better.size(), 0u);
	EXPECT_DOUBLE_EQ(c.estimate_worse[0].t_s, 2.0);
}

TEST(ScanConsistency, TheReferencesSlipCountsAsEstimateBetterAndPosesAreTakenWithinMaxDt)
{
	const std::vector<CPose2D> truth = {{0, 0, 0}, {0.4, 0, 0.1}, {0.8, 0.1, 0.2}};
	std::vector<TScanPoints2D> scans;
	for (size_t i = 0; i < truth.size(); ++i) scans.push_back(scanFrom(truth[i], static_cast<double>(i)));
	std::vector<CPose2D> slipped = truth;
	slipped[2] = CPose2D(slipped[2].x() + 0.05, slipped[2].y(), slipped[2].phi());
	// estimate poses 10 ms late: within the default 20 ms
	const TScanConsistency c = compareScanConsistency(scans, trajectory(slipped), trajectory(truth, 0.01), {});
	ASSERT_EQ(c.pairs.size(), 2u);
	EXPECT_NEAR(c.pairs[1].reference_m, 0.05, 1e-6);
	EXPECT_EQ(c.estimate_better.size(), 1u);
	EXPECT_EQ(c.estimate_worse.size(), 0u);

	// 30 ms late: no scan has an estimate pose, which is an error, not a zero
	TScanConsistencyOptions strict;
	EXPECT_THROW(compareScanConsistency(scans, trajectory(slipped), trajectory(truth, 0.03), strict), std::runtime_error);
}

TEST(ScanConsistency, ReadsTheLaserOfARawlogAndRefusesAnAmbiguousOne)
{
	hslam::testing::CTempDir dir;
	const auto scanObs = [](const std::string& label, double t_s)
	{
		auto obs = mrpt::obs::CObservation2DRangeScan::Create();
		obs->sensorLabel = label;
		obs->timestamp = mrpt::Clock::fromDouble(t_s);
		obs->aperture = static_cast<float>(M_PI);
		obs->maxRange = 30;
		obs->resizeScan(181);
		for (size_t b = 0; b < 181; ++b) obs->setScanRange(b, b < 90 ? 2.0f : 25.0f), obs->setScanRangeValidity(b, true);
		return obs;
	};
	{
		hslam::io::CRawlogObservationWriter out(dir.file("two.rawlog"));
		out.write(*scanObs("FRONT", 100.0));
		out.write(*scanObs("REAR", 100.1));
		out.write(*scanObs("FRONT", 100.2));
	}
	const auto front = readScanPoints(dir.file("two.rawlog"), "FRONT", 20.0);
	ASSERT_EQ(front.size(), 2u);
	EXPECT_NEAR(front[1].t_s, 100.2, 1e-6);
	EXPECT_EQ(front[0].points.size(), 90u);  // the 25 m returns are beyond max_range_m
	try
	{
		readScanPoints(dir.file("two.rawlog"), "", 20.0);
		FAIL() << "two lasers and no label must be refused";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("'FRONT', 'REAR'"), std::string::npos) << e.what();
	}
	EXPECT_THROW(readScanPoints(dir.file("two.rawlog"), "SIDE", 20.0), std::runtime_error);
}
