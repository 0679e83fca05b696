/* hslam tests: hslam-carmen2rawlog --format frames, the actions + sensory-frames
 * rawlog written with MRPT's own classes (CRawlogFramesWriter), read back with
 * MRPT's CRawlog and checked by MRPT's rawlog-edit. */
#include <gtest/gtest.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/temp_dir.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <array>
#include <cstdio>
#include <memory>

#include "carmen_test_utils.h"

using namespace hslam::io;
using namespace hslam::testing::carmen;
using mrpt::math::TPose2D;
using mrpt::obs::CActionRobotMovement2D;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationComment;
using mrpt::obs::CObservationOdometry;

namespace
{
const TPose2D kRef0{1.0, 2.0, 0.5}, kRef1{1.5, 2.2, 0.65}, kRef2{1.8, 2.1, 0.55}, kRef3{2.2, 2.4, 1.1};
const TPose2D kRaw1{1.4, 2.3, 0.7}, kRaw2{1.7, 2.0, 0.5}, kRaw3{2.1, 2.6, 1.2};

/** Four front scans, raw odometry before each but the second (a gap). */
std::string logWithGap()
{
	return odom({0.1, 0, 0}, 0.5) + flaser(181, kRef0, 1.0) + anchor(kRef0) + flaser(181, kRef1, 2.0) +
		   anchor(kRef1) + odom(kRaw2, 2.5) + flaser(181, kRef2, 3.0) + anchor(kRef2) + odom(kRaw3, 3.5) +
		   flaser(181, kRef3, 4.0) + anchor(kRef3);
}

std::string logWithoutGap()
{
	return odom({0.1, 0, 0}, 0.5) + flaser(181, kRef0, 1.0) + anchor(kRef0) + odom(kRaw1, 1.5) +
		   flaser(181, kRef1, 2.0) + anchor(kRef1) + odom(kRaw2, 2.5) + flaser(181, kRef2, 3.0) + anchor(kRef2) +
		   odom(kRaw3, 3.5) + flaser(181, kRef3, 4.0) + anchor(kRef3);
}

TCarmenImportReport convert(const hslam::testing::CTempDir& dir, const std::string& text, const std::string& format)
{
	writeText(dir.file("in.log"), text);
	TCarmenImportOptions options;
	options.format = format;
	return convertCarmenLog(dir.file("in.log"), dir.file(format + ".rawlog"), dir.file(format + ".tum"), options);
}

/** The frames rawlog as MRPT's CRawlog loads it: action, frame, action, ... */
mrpt::obs::CRawlog loadFrames(const std::string& path)
{
	mrpt::obs::CRawlog rawlog;
	EXPECT_TRUE(rawlog.loadFromRawLogFile(path)) << path;
	return rawlog;
}

/** Odometry increment of action entry `i`, if it holds a CActionRobotMovement2D. */
std::optional<mrpt::poses::CPose2D> incrementAt(const mrpt::obs::CRawlog& rawlog, size_t i)
{
	const auto move = rawlog.getAsAction(i)->getActionByClass<CActionRobotMovement2D>();
	if (!move) return std::nullopt;
	return move->poseChange->getMeanVal();
}

/** Runs a command, returns its exit status and standard output. */
std::pair<int, std::string> run(const std::string& command)
{
	const auto r = hslam::testing::runCapturingOutput(command);
	return {r.exitCode, r.out};
}
}  // namespace

TEST(CarmenFrames, OneActionAndSensoryFramePerFrontScanReadBackWithCRawlog)
{
	hslam::testing::CTempDir dir;
	const auto report = convert(dir, logWithoutGap(), "frames");
	EXPECT_EQ(report.rawlogFormat, "frames");
	const auto rawlog = loadFrames(dir.file("frames.rawlog"));
	ASSERT_EQ(rawlog.size(), 8u);  // 4 x (actions, sensory frame)
	for (size_t k = 0; k < 4; ++k)
	{
		EXPECT_EQ(rawlog.getType(2 * k), mrpt::obs::CRawlog::etActionCollection);
		ASSERT_EQ(rawlog.getType(2 * k + 1), mrpt::obs::CRawlog::etSensoryFrame);
		const auto scan = rawlog.getAsObservations(2 * k + 1)->getObservationByClass<CObservation2DRangeScan>();
		ASSERT_TRUE(scan);
		EXPECT_EQ(scan->sensorLabel, "LASER");
		EXPECT_NEAR(seconds(scan->timestamp), 1.0 + k, 1e-6);
		const auto move = rawlog.getAsAction(2 * k)->getActionByClass<CActionRobotMovement2D>();
		ASSERT_TRUE(move);
		EXPECT_EQ(move->timestamp, scan->timestamp);
	}
	// The header comment travels in the first frame.
	EXPECT_TRUE(rawlog.getAsObservations(1)->getObservationByClass<CObservationComment>());
	expectPose(*incrementAt(rawlog, 0), {0, 0, 0});  // first scan: no motion before it
	expectPose(*incrementAt(rawlog, 2), handIncrement(kRef0, kRaw1));
	expectPose(*incrementAt(rawlog, 6), handIncrement(kRef2, kRaw3));
}

TEST(CarmenFrames, MotionModelIsMrptsOwnGaussianModel)
{
	hslam::testing::CTempDir dir;
	convert(dir, logWithoutGap(), "frames");
	const auto rawlog = loadFrames(dir.file("frames.rawlog"));
	const auto move = rawlog.getAsAction(2)->getActionByClass<CActionRobotMovement2D>();
	ASSERT_TRUE(move);
	// The covariance is what MRPT's own motion model (default options) gives
	// for this increment, not zero and not a copy of literals (MRPT stores the
	// model options as float: agreement to 1e-6 relative).
	const auto inc = handIncrement(kRef0, kRaw1);
	CActionRobotMovement2D expected;
	expected.computeFromOdometry(mrpt::poses::CPose2D(inc), CActionRobotMovement2D::TMotionModelOptions());
	const auto cov = move->poseChange->getCovariance(), expectedCov = expected.poseChange->getCovariance();
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) EXPECT_NEAR(cov(r, c), expectedCov(r, c), 1e-6 * std::abs(expectedCov(r, c)) + 1e-15) << r << "," << c;
	EXPECT_GT(cov(0, 0), 0.0);
	EXPECT_GE(cov(2, 2), std::pow(CActionRobotMovement2D::TMotionModelOptions().gaussianModel.minStdPHI, 2) - 1e-15);
}

TEST(CarmenFrames, GapGivesAnEmptyActionAndIsNotDifferencedAcross)
{
	hslam::testing::CTempDir dir;
	const auto report = convert(dir, logWithGap(), "frames");
	EXPECT_EQ(report.odometryGaps, 1u);
	const auto rawlog = loadFrames(dir.file("frames.rawlog"));
	ASSERT_EQ(rawlog.size(), 8u);
	EXPECT_TRUE(incrementAt(rawlog, 0).has_value());
	EXPECT_EQ(rawlog.getAsAction(2)->size(), 0u);  // the gap: no odometry at all, not zero motion
	const auto gap = rawlog.getAsObservations(3)->getObservationByClass<CObservationComment>();
	ASSERT_TRUE(gap);
	EXPECT_EQ(gap->text.rfind("ODOMETRY_GAP:", 0), 0u) << gap->text;
	// After the gap: the increment from scan 1 to scan 2 only, never scan 0 -> 2.
	expectPose(*incrementAt(rawlog, 4), handIncrement(kRef1, kRaw2));
	expectPose(*incrementAt(rawlog, 6), handIncrement(kRef2, kRaw3));
}

TEST(CarmenFrames, OdometrySumsMatchTheObservationsOnlyRawlog)
{
	for (const auto& text : {logWithoutGap(), logWithGap()})
	{
		hslam::testing::CTempDir dir;
		convert(dir, text, "frames");
		convert(dir, text, "observations");
		const auto odometry = ofType<CObservationOdometry>(readRawlog(dir.file("observations.rawlog")));
		ASSERT_GE(odometry.size(), 3u);
		const auto rawlog = loadFrames(dir.file("frames.rawlog"));
		mrpt::poses::CPose2D sum;
		for (size_t i = 0; i < rawlog.size(); i += 2)
			if (const auto inc = incrementAt(rawlog, i)) sum = sum + *inc;
		const mrpt::poses::CPose2D chain = odometry.back()->odometry - odometry.front()->odometry;
		expectPose(sum, {chain.x(), chain.y(), chain.phi()});
	}
}

TEST(CarmenFrames, MrptRawlogEditAcceptsTheFramesRawlog)
{
	hslam::testing::CTempDir dir;
	convert(dir, logWithGap(), "frames");
	const auto [status, out] = run("rawlog-edit --info -i " + dir.file("frames.rawlog"));
	EXPECT_EQ(status, 0) << out;
	EXPECT_NE(out.find("Actions"), std::string::npos) << out;
}

TEST(CarmenFrames, UnknownFormatIsRejected)
{
	hslam::testing::CTempDir dir;
	writeText(dir.file("in.log"), logWithoutGap());
	TCarmenImportOptions options;
	options.format = "sensory";
	EXPECT_THROW(convertCarmenLog(dir.file("in.log"), dir.file("x.rawlog"), dir.file("x.tum"), options),
				 std::exception);
}
