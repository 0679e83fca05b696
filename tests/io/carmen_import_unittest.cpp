/* hslam tests: CARMEN log -> rawlog + TUM, end to end on small hand-made logs. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/temp_dir.h>

#include "carmen_test_utils.h"

using namespace hslam::io;
using namespace hslam::testing::carmen;
using mrpt::math::TPose2D;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationComment;
using mrpt::obs::CObservationOdometry;

namespace
{
// A corrected log: each FLASER is followed by its anchor, then raw odometry
// (whose timestamps may go backwards, as in intel).
const TPose2D kRef0{1.0, 2.0, 0.5}, kRef1{1.5, 2.2, 0.65}, kRef2{1.8, 2.1, 0.55}, kRef3{2.2, 2.4, 1.1};
const TPose2D kRawBefore1{1.4, 2.3, 0.7}, kRawBefore2{1.7, 2.0, 0.5}, kRawBefore3{2.1, 2.6, 1.2};

std::string anchoredLog()
{
	return "# message formats defined: PARAM SYNC ODOM FLASER\n"
		   "PARAM robot_frontlaser_offset 0.0 nohost 0\n" +
		   odom({0, 0, 0}, 0.5) + odom({0.1, 0, 0}, 1.5) + flaser(180, kRef0, 2.0) + anchor(kRef0) +
		   "NEFF 15\n" + odom({1.2, 2.1, 0.6}, 2.5) + odom(kRawBefore1, 2.9) + flaser(180, kRef1, 3.0) +
		   anchor(kRef1) + odom(kRawBefore2, 3.5) + flaser(180, kRef2, 4.0) + anchor(kRef2) +
		   odom({2.0, 2.5, 1.0}, 4.5) + odom(kRawBefore3, 4.4, 0.25, -0.05) + flaser(180, kRef3, 5.0) + anchor(kRef3);
}

struct TConverted
{
	TCarmenImportReport report;
	std::vector<mrpt::obs::CObservation::Ptr> observations;
	hslam::common::TTrajectory2D reference;
};

TConverted convertText(const hslam::testing::CTempDir& dir, const std::string& text,
					   const TCarmenImportOptions& options = {}, bool gz = false)
{
	const std::string in = dir.file(gz ? "in.log.gz" : "in.log");
	if (gz)
		writeGz(in, text);
	else
		writeText(in, text);
	TConverted out;
	out.report = convertCarmenLog(in, dir.file("out.rawlog"), dir.file("out.tum"), options);
	out.observations = readRawlog(dir.file("out.rawlog"));
	out.reference = hslam::common::readTumFile(dir.file("out.tum"));
	return out;
}

std::string errorOf(const hslam::testing::CTempDir& dir, const std::string& text,
					const TCarmenImportOptions& options = {})
{
	writeText(dir.file("bad.log"), text);
	try
	{
		convertCarmenLog(dir.file("bad.log"), dir.file("bad.rawlog"), dir.file("bad.tum"), options);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	ADD_FAILURE() << "no error";
	return {};
}

}  // namespace

TEST(CarmenImport, AnchoredIncrementsReadBackFromTheRawlog)
{
	hslam::testing::CTempDir dir;
	const auto c = convertText(dir, anchoredLog());
	const auto odometry = ofType<CObservationOdometry>(c.observations);
	const auto scans = ofType<CObservation2DRangeScan>(c.observations);
	ASSERT_EQ(scans.size(), 4u);
	ASSERT_EQ(odometry.size(), 4u);
	EXPECT_EQ(c.report.odometryGaps, 0u);
	EXPECT_EQ(c.report.odometryAnchors, 4u);
	expectPose(odometry[0]->odometry, {0.1, 0, 0});  // chain_0: last raw ODOM before the first scan
	const std::vector<std::pair<TPose2D, TPose2D>> fromTo{
		{kRef0, kRawBefore1}, {kRef1, kRawBefore2}, {kRef2, kRawBefore3}};
	for (size_t k = 0; k < fromTo.size(); ++k)
		expectPose(odometry[k + 1]->odometry - odometry[k]->odometry, handIncrement(fromTo[k].first, fromTo[k].second));
	EXPECT_TRUE(odometry[3]->hasVelocities);
	EXPECT_DOUBLE_EQ(odometry[3]->velocityLocal.vx, 0.25);
	EXPECT_DOUBLE_EQ(odometry[3]->velocityLocal.omega, -0.05);
}

TEST(CarmenImport, RawlogLayoutLabelsTimestampsAndReference)
{
	hslam::testing::CTempDir dir;
	const auto c = convertText(dir, anchoredLog());
	ASSERT_EQ(c.observations.size(), 9u);  // header + 4 x (odometry, scan)
	const auto header = std::dynamic_pointer_cast<CObservationComment>(c.observations[0]);
	ASSERT_TRUE(header);
	EXPECT_EQ(header->text.rfind("CARMEN_IMPORT:", 0), 0u);
	EXPECT_NE(header->text.find("clock: ipc"), std::string::npos) << header->text;
	for (size_t k = 0; k < 4; ++k)
	{
		const auto& odo = c.observations[1 + 2 * k];
		const auto& scan = c.observations[2 + 2 * k];
		EXPECT_EQ(odo->sensorLabel, "ODOMETRY");
		EXPECT_EQ(scan->sensorLabel, "LASER");
		EXPECT_TRUE(std::dynamic_pointer_cast<CObservation2DRangeScan>(scan));
		EXPECT_EQ(odo->timestamp, scan->timestamp);
		EXPECT_NEAR(seconds(scan->timestamp), 2.0 + k, 1e-6);
		EXPECT_NEAR(c.reference.at(k).t_s, seconds(scan->timestamp), 1e-6);
	}
	ASSERT_EQ(c.reference.size(), 4u);
	EXPECT_NEAR(c.reference[1].pose.x, kRef1.x, 1e-6);
	EXPECT_NEAR(c.reference[3].pose.phi, kRef3.phi, 1e-6);
	EXPECT_EQ(c.report.skippedMessages.at("NEFF"), 1u);
	EXPECT_EQ(c.report.skippedMessages.at("#"), 1u);
	EXPECT_EQ(c.report.parsedMessages.at("ODOM"), 11u);
}

TEST(CarmenImport, MissingOdometryGivesAGapCommentAndNoOdometry)
{
	hslam::testing::CTempDir dir;
	const std::string log = flaser(181, kRef0, 1.0) + anchor(kRef0) + flaser(181, kRef1, 2.0) + anchor(kRef1) +
							odom(kRawBefore2, 2.5) + flaser(181, kRef2, 3.0) + anchor(kRef2);
	const auto c = convertText(dir, log);
	EXPECT_EQ(c.report.odometryGaps, 1u);
	EXPECT_EQ(c.report.odometryObservations, 2u);
	ASSERT_EQ(c.observations.size(), 7u);  // header, odo+scan, gap+scan, odo+scan
	const auto gap = std::dynamic_pointer_cast<CObservationComment>(c.observations[3]);
	ASSERT_TRUE(gap);
	EXPECT_EQ(gap->text.rfind("ODOMETRY_GAP:", 0), 0u) << gap->text;
	EXPECT_NE(gap->text.find("between front scans 0 and 1"), std::string::npos) << gap->text;
	EXPECT_EQ(c.observations[4]->sensorLabel, "LASER");
	EXPECT_EQ(gap->timestamp, c.observations[4]->timestamp);
	const auto odometry = ofType<CObservationOdometry>(c.observations);
	expectPose(odometry[1]->odometry - odometry[0]->odometry, handIncrement(kRef1, kRawBefore2));
	EXPECT_EQ(c.reference.size(), 3u);
}

TEST(CarmenImport, ScanGeometryAndValidityInTheRawlog)
{
	hslam::testing::CTempDir dir;
	std::vector<double> ranges(180, 3.0);
	ranges[0] = 81.91;  // no-return marker
	ranges[1] = 79.0;  // real long return
	ranges[2] = 0.0;
	std::string log;
	for (int k = 0; k < 4; ++k) log += flaser(ranges, {0.1 * k, 0, 0}, 1.0 + k, 1.0 + k) + anchor({0.1 * k, 0, 0});
	const auto c = convertText(dir, log);
	const auto scans = ofType<CObservation2DRangeScan>(c.observations);
	ASSERT_EQ(scans.size(), 4u);
	const auto& s = *scans[0];
	EXPECT_FALSE(s.getScanRangeValidity(0));
	EXPECT_TRUE(s.getScanRangeValidity(1));
	EXPECT_FALSE(s.getScanRangeValidity(2));
	EXPECT_TRUE(s.getScanRangeValidity(3));
	EXPECT_NEAR(s.maxRange, 81.91, 1e-4);
	EXPECT_NEAR(s.stdError, 0.01, 1e-7);
	EXPECT_NEAR(beamAngle_deg(s, 0), -90.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(s, 179), 89.0, 1e-4);
	ASSERT_TRUE(c.report.noReturn_m.has_value());
	EXPECT_DOUBLE_EQ(*c.report.noReturn_m, 81.91);
}

TEST(CarmenImport, ClockFallbacks)
{
	hslam::testing::CTempDir dir;
	auto build = [](const std::vector<double>& ipc, const std::vector<double>& logger) {
		std::string log;
		for (size_t k = 0; k < ipc.size(); ++k)
			log += flaser(std::vector<double>(181, 2.0), {0, 0, 0}, ipc[k], logger[k]) + anchor({0, 0, 0});
		return log;
	};
	auto c = convertText(dir, build({10, 11, 12}, {20, 21, 22}));
	EXPECT_EQ(c.report.clockUsed, "ipc");
	EXPECT_NEAR(c.reference[2].t_s, 12.0, 1e-6);

	c = convertText(dir, build({1.13486e9, 1.13486e9, 1.13486e9}, {20, 21, 22}));
	EXPECT_EQ(c.report.clockUsed, "logger");
	EXPECT_NEAR(c.reference[2].t_s, 22.0, 1e-6);
	EXPECT_NEAR(seconds(ofType<CObservation2DRangeScan>(c.observations)[2]->timestamp), 22.0, 1e-6);

	TCarmenImportOptions options;
	options.synthetic_period_s = 0.5;
	c = convertText(dir, build({0, 0, 0}, {5, 4.29e9, 4.29e9 + 1}), options);
	EXPECT_EQ(c.report.clockUsed, "synthetic");
	const auto scans = ofType<CObservation2DRangeScan>(c.observations);
	for (size_t k = 0; k < 3; ++k)
	{
		EXPECT_NEAR(seconds(scans[k]->timestamp), 0.5 * k, 1e-6);
		EXPECT_NEAR(c.reference[k].t_s, 0.5 * k, 1e-6);
	}
}

TEST(CarmenImport, MalformedLinesFailWithTheLineNumberAndKeepWhatCameBefore)
{
	hslam::testing::CTempDir dir;
	const std::string good = flaser(181, kRef0, 1.0) + anchor(kRef0) + odom(kRawBefore1, 1.5) +
							 flaser(181, kRef1, 2.0) + anchor(kRef1);  // lines 1-5
	std::string badToken = flaser(181, kRef2, 3.0);
	badToken.replace(badToken.find(" 2 "), 3, " 2,0 ");
	std::string e = errorOf(dir, good + badToken);
	EXPECT_NE(e.find("bad.log:6:"), std::string::npos) << e;
	EXPECT_NE(e.find("bad number '2,0'"), std::string::npos) << e;
	EXPECT_NE(e.find("2 scans"), std::string::npos) << e;  // written before the error
	EXPECT_EQ(ofType<CObservation2DRangeScan>(readRawlog(dir.file("bad.rawlog"))).size(), 2u);
	EXPECT_EQ(hslam::common::readTumFile(dir.file("bad.tum")).size(), 2u);

	e = errorOf(dir, good + "FLASER 181 1 2 3 0 0 0 0 0 0 1 h 1\n");
	EXPECT_NE(e.find("bad.log:6:"), std::string::npos) << e;
	EXPECT_NE(e.find("beams"), std::string::npos) << e;

	std::string truncated = flaser(181, kRef2, 3.0);
	truncated.resize(truncated.size() / 2);
	e = errorOf(dir, good + odom(kRawBefore2, 2.5) + truncated);
	EXPECT_NE(e.find("bad.log:7: truncated line"), std::string::npos) << e;
}

TEST(CarmenImport, LenientModeSkipsAndCountsMalformedLines)
{
	hslam::testing::CTempDir dir;
	std::string log = flaser(181, kRef0, 1.0) + anchor(kRef0);
	for (int i = 0; i < 12; ++i) log += "ODOM 1 2 x 0 0 0 1 h 1\n";  // lines 3..14
	log += odom(kRawBefore1, 1.5) + flaser(181, kRef1, 2.0) + anchor(kRef1) + "FLASER 181 1 2 3\n";
	TCarmenImportOptions options;
	options.lenient = true;
	const auto c = convertText(dir, log, options);
	EXPECT_EQ(c.report.malformedLinesSkipped, 13u);
	ASSERT_EQ(c.report.malformedExamples.size(), 10u);
	EXPECT_NE(c.report.malformedExamples[0].find("in.log:3:"), std::string::npos) << c.report.malformedExamples[0];
	EXPECT_EQ(c.report.frontScans, 2u);
	EXPECT_EQ(c.report.odometryObservations, 2u);
	EXPECT_NE(formatCarmenImportReport(c.report).find("malformed lines skipped: 13"), std::string::npos);
}

TEST(CarmenImport, GzInputEqualsPlainInput)
{
	hslam::testing::CTempDir plainDir, gzDir;
	const auto plain = convertText(plainDir, anchoredLog());
	const auto gz = convertText(gzDir, anchoredLog(), {}, true);
	EXPECT_EQ(readText(plainDir.file("out.tum")), readText(gzDir.file("out.tum")));
	ASSERT_EQ(plain.observations.size(), gz.observations.size());
	const auto a = ofType<CObservation2DRangeScan>(plain.observations);
	const auto b = ofType<CObservation2DRangeScan>(gz.observations);
	for (size_t k = 0; k < a.size(); ++k)
	{
		EXPECT_EQ(a[k]->timestamp, b[k]->timestamp);
		for (size_t i = 0; i < a[k]->getScanSize(); ++i) EXPECT_EQ(a[k]->getScanRange(i), b[k]->getScanRange(i));
	}
	EXPECT_EQ(plain.report.odometryObservations, gz.report.odometryObservations);
}

TEST(CarmenImport, MissingInputAndBadOptionsAreErrors)
{
	hslam::testing::CTempDir dir;
	EXPECT_THROW(convertCarmenLog(dir.file("nope.log"), dir.file("o.rawlog"), dir.file("o.tum"), {}),
				 std::runtime_error);
	TCarmenImportOptions options;
	options.clock = "gps";
	writeText(dir.file("in.log"), anchoredLog());
	EXPECT_THROW(convertCarmenLog(dir.file("in.log"), dir.file("o.rawlog"), dir.file("o.tum"), options),
				 std::runtime_error);
}
