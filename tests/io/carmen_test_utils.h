/* hslam tests (io): building small CARMEN logs as text and reading rawlogs back. */
#pragma once

#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hslam::testing::carmen
{
/** "FLASER n r.. x y th x y th ipc host logger" (reference pose twice, as in corrected logs). */
inline std::string flaser(const std::vector<double>& ranges, const mrpt::math::TPose2D& p, double ipc_s,
						  double logger_s)
{
	std::ostringstream os;
	os.precision(12);
	os << "FLASER " << ranges.size();
	for (double r : ranges) os << " " << r;
	os << " " << p.x << " " << p.y << " " << p.phi << " " << p.x << " " << p.y << " " << p.phi << " " << ipc_s
	   << " testhost " << logger_s << "\n";
	return os.str();
}

inline std::string flaser(size_t beams, const mrpt::math::TPose2D& p, double t_s, double range_m = 2.0)
{
	return flaser(std::vector<double>(beams, range_m), p, t_s, t_s);
}

/** "ODOM x y th tv rv accel ipc host logger". */
inline std::string odom(const mrpt::math::TPose2D& p, double t_s, double tv = 0.3, double rv = 0.1)
{
	std::ostringstream os;
	os.precision(12);
	os << "ODOM " << p.x << " " << p.y << " " << p.phi << " " << tv << " " << rv << " 0 " << t_s << " testhost " << t_s
	   << "\n";
	return os.str();
}

/** The anchor line a corrected log has right after each FLASER. */
inline std::string anchor(const mrpt::math::TPose2D& p) { return odom(p, 0.0, 0.0, 0.0); }

inline void writeText(const std::string& path, const std::string& text)
{
	std::ofstream out(path);
	out << text;
	ASSERT_TRUE(out.good()) << path;
}

inline void writeGz(const std::string& path, const std::string& text)
{
	gzFile f = gzopen(path.c_str(), "wb");
	ASSERT_NE(f, nullptr) << path;
	ASSERT_EQ(gzwrite(f, text.data(), static_cast<unsigned>(text.size())), static_cast<int>(text.size()));
	ASSERT_EQ(gzclose(f), Z_OK);
}

inline std::string readText(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	return ss.str();
}

/** All observations of an observations-only rawlog, in order. */
inline std::vector<mrpt::obs::CObservation::Ptr> readRawlog(const std::string& path)
{
	std::vector<mrpt::obs::CObservation::Ptr> out;
	mrpt::io::CFileGZInputStream in(path);
	auto archive = mrpt::serialization::archiveFrom(in);
	mrpt::obs::CActionCollection::Ptr actions;
	mrpt::obs::CSensoryFrame::Ptr frame;
	mrpt::obs::CObservation::Ptr obs;
	size_t entry = 0;
	while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(archive, actions, frame, obs, entry))
		if (obs) out.push_back(obs);
	return out;
}

template <class T>
std::vector<typename T::Ptr> ofType(const std::vector<mrpt::obs::CObservation::Ptr>& all)
{
	std::vector<typename T::Ptr> out;
	for (const auto& o : all)
		if (auto p = std::dynamic_pointer_cast<T>(o)) out.push_back(p);
	return out;
}

inline double seconds(const mrpt::Clock::time_point& t) { return mrpt::Clock::toDouble(t); }

/** a^-1 (+) b written out by hand (independent of MRPT's pose algebra). */
inline mrpt::math::TPose2D handIncrement(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi), dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, std::remainder(b.phi - a.phi, 2 * M_PI)};
}

/** Absolute beam direction (sensor yaw + MRPT's beam angle), degrees. */
inline double beamAngle_deg(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	return (scan.sensorPose.yaw() + scan.getScanAngle(i)) * 180.0 / M_PI;
}

/** Pose equality to 1e-9 (angles compared modulo 2 pi). */
inline void expectPose(const mrpt::poses::CPose2D& actual, const mrpt::math::TPose2D& expected)
{
	EXPECT_NEAR(actual.x(), expected.x, 1e-9);
	EXPECT_NEAR(actual.y(), expected.y, 1e-9);
	EXPECT_NEAR(std::remainder(actual.phi() - expected.phi, 2 * M_PI), 0.0, 1e-9);
}

}  // namespace hslam::testing::carmen
