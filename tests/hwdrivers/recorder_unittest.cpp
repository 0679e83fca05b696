/* Tests of the recording pieces: sensory-frame grouping with correct odometry
 * increments (MRPT 2.5's rawlog-grabber takes the 2nd increment w.r.t. the
 * origin), the flushable rawlog writer, and loading of the shipped INI files. */
#include <gtest/gtest.h>
#include <hslam/hwdrivers/CPioneerSensor.h>
#include <hslam/hwdrivers/CRawlogRecorder.h>
#include <hslam/hwdrivers/CSensoryFrameBuilder.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <filesystem>
#include <fstream>

using namespace hslam::hwdrivers;

namespace
{
mrpt::Clock::time_point at(double s)
{
	return mrpt::Clock::fromDouble(1.7e9 + s);
}
mrpt::obs::CObservation::Ptr odo(double t, double x, double y, double phiDeg)
{
	auto o = mrpt::obs::CObservationOdometry::Create();
	o->timestamp = at(t);
	o->sensorLabel = "ODOMETRY";
	o->odometry = mrpt::poses::CPose2D(x, y, phiDeg * M_PI / 180);
	return o;
}
mrpt::obs::CObservation::Ptr scan(double t, const std::string& label = "LASER")
{
	auto s = mrpt::obs::CObservation2DRangeScan::Create();
	s->timestamp = at(t);
	s->sensorLabel = label;
	return s;
}
mrpt::poses::CPose2D actionOf(const CSensoryFrameBuilder::TPair& p)
{
	const auto a = p.first->getBestMovementEstimation();
	if (!a) return {};
	return a->poseChange->getMeanVal();
}
}  // namespace

TEST(SensoryFrameBuilder, IncrementsAreRelativeToThePreviousReading)
{
	CSensoryFrameBuilder b(0.25);
	std::vector<CSensoryFrameBuilder::TPair> out;
	// Odometry does not start at the origin (no SETO): MRPT's bug would give
	// the first increment as (5, 2, 30deg) + motion.
	b.add(odo(0.00, 5.0, 2.0, 30), out);
	b.add(scan(0.05), out);
	b.add(odo(0.10, 5.0 + 0.1 * std::cos(M_PI / 6), 2.0 + 0.1 * std::sin(M_PI / 6), 30), out);
	b.add(scan(0.15), out);
	b.add(odo(0.20, 5.0 + 0.2 * std::cos(M_PI / 6), 2.0 + 0.2 * std::sin(M_PI / 6), 40), out);
	b.add(scan(0.25), out);
	b.add(scan(0.26, "SONAR"), out);  // same frame (different label)
	b.flush(out);
	ASSERT_EQ(out.size(), 3u);
	EXPECT_TRUE(out[0].first->size() == 0);  // first frame: no motion known yet
	const auto a1 = actionOf(out[1]), a2 = actionOf(out[2]);
	EXPECT_NEAR(a1.x(), 0.1, 1e-9);  // in the robot frame: straight ahead
	EXPECT_NEAR(a1.y(), 0.0, 1e-9);
	EXPECT_NEAR(a1.phi(), 0.0, 1e-9);
	EXPECT_NEAR(a2.x(), 0.1, 1e-9);
	EXPECT_NEAR(a2.phi(), 10 * M_PI / 180, 1e-9);
	EXPECT_EQ(out[2].second->size(), 2u);
}

TEST(SensoryFrameBuilder, SeveralReadingsComposeAndLongFramesSplit)
{
	CSensoryFrameBuilder b(0.1);
	std::vector<CSensoryFrameBuilder::TPair> out;
	b.add(odo(0.0, 0, 0, 0), out);
	b.add(scan(0.01), out);
	for (int k = 1; k <= 4; ++k) b.add(odo(0.01 + 0.01 * k, 0.05 * k, 0, 5 * k), out);  // a turn in 4 steps
	b.add(scan(0.06, "A"), out);  // same frame as the first scan (other label, within 0.1 s)
	b.add(scan(0.2, "B"), out);  // > 0.1 s after the frame start: new frame, after the turn
	b.add(scan(0.25, "B"), out);  // label repeats: new frame, no motion since
	b.flush(out);
	ASSERT_EQ(out.size(), 3u);
	mrpt::poses::CPose2D expected;
	for (int k = 1; k <= 4; ++k)
		expected = expected + (mrpt::poses::CPose2D(0.05 * k, 0, 5 * k * M_PI / 180) -
							   mrpt::poses::CPose2D(0.05 * (k - 1), 0, 5 * (k - 1) * M_PI / 180));
	const auto a = actionOf(out[1]);
	EXPECT_NEAR(a.x(), expected.x(), 1e-9);
	EXPECT_NEAR(a.y(), expected.y(), 1e-9);
	EXPECT_NEAR(a.phi(), 20 * M_PI / 180, 1e-9);
	EXPECT_EQ(out[2].first->size(), 0u);  // no motion between the last two frames
}

TEST(RawlogRecorder, FlushedPrefixIsReadableBeforeClose)
{
	hslam::testing::CTempDir tmp;
	const std::string path = tmp.file("r.rawlog");
	CRawlogRecorder rec(path, 6);
	for (int i = 0; i < 20; ++i) rec.write(*odo(i * 0.1, i, 0, 0));
	rec.flush();
	// The file is still open (as if the process were killed now).
	size_t n = 0;
	try
	{
		hslam::io::CRawlogReader reader(path);
		hslam::io::TRawlogEntry e;
		while (reader.next(e)) ++n;
	}
	catch (const std::exception&)
	{
		// an unfinished gzip stream may report its end as an error
	}
	EXPECT_EQ(n, 20u);
	rec.close();
	hslam::io::CRawlogReader reader(path);
	hslam::io::TRawlogEntry e;
	n = 0;
	while (reader.next(e)) ++n;
	EXPECT_EQ(n, 20u);
	EXPECT_EQ(rec.objectsWritten(), 20u);
}

TEST(ShippedIni, PioneerSectionsLoad)
{
	for (const char* name : {"grabber-pioneer-lms200.ini", "grabber-pioneer-lms100.ini", "grabber-pioneer-lms-camera.ini"})
	{
		mrpt::config::CConfigFile cfg(std::string(HSLAM_SOURCE_DIR) + "/config_ini/" + name);
		CPioneerSensor s;
		EXPECT_NO_THROW(s.loadConfig(cfg, "PIONEER")) << name;
		EXPECT_EQ(s.options().driver.serial_port, "/dev/ttyUSB0") << name;
		EXPECT_EQ(s.options().driver.baud, 9600);
		EXPECT_EQ(s.getProcessRate(), 20.0);
	}
	mrpt::config::CConfigFile cfg(std::string(HSLAM_SOURCE_DIR) + "/config_ini/grabber-pioneer-lms200.ini");
	CPioneerSensor s;
	s.loadConfig(cfg, "PIONEER");
	// The documented sonar ring is the P3-DX default.
	EXPECT_EQ(parseSonarPoses(s.options().sonar_poses).size(), 8u);
	EXPECT_NEAR(parseSonarPoses(s.options().sonar_poses)[3].phi, 10 * M_PI / 180, 1e-12);
}

TEST(HslamGrabber, BadConfigurationsFailWithAClearMessage)
{
	hslam::testing::CTempDir tmp;
	const auto run = [&](const std::string& iniText, const std::string& expected) {
		const std::string ini = tmp.file("bad.ini"), log = tmp.file("bad.log");
		std::ofstream(ini) << iniText;
		const int rc = hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-grabber '" + ini + "' --duration 1 -o '" +
												  tmp.file("x.rawlog") + "' > '" + log + "' 2>&1");
		std::ifstream f(log);
		const std::string out((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
		EXPECT_NE(rc, 0) << iniText;
		EXPECT_NE(out.find(expected), std::string::npos) << "expected '" << expected << "' in:\n" << out;
		EXPECT_FALSE(std::filesystem::exists(tmp.file("x.rawlog"))) << "no output file for a bad configuration";
	};
	run("[global]\n[P]\ndriver = CNoSuchSensor\nprocess_rate = 10\n", "[P] driver = 'CNoSuchSensor'");
	run("[global]\n[P]\nprocess_rate = 10\n", "[P] has no 'driver'");
	run("[global]\nGRABBER_PERIOD_MS = fast\n[P]\ndriver = CPioneerSensor\nprocess_rate = 10\n", "GRABBER_PERIOD_MS");
	run("[global]\n[P]\ndriver = CPioneerSensor\nprocess_rate = 10\nmax_v_mps = 7\n", "max_v_mps");
	run("[global]\n[P]\ndriver = CPioneerSensor\nprocess_rate = 0\n", "process_rate");
	run("[global]\n", "no sensor sections");
}
