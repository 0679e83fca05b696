/* hslam tests: the driven run of thesis 4.9 (scripts/driven-run.sh --short):
 * our subsumption controller (hslam-navigate) drives the emulated P3-DX
 * through our Pioneer driver (ARCOS on a pseudo-terminal) with the emulated
 * LMS200 (CSickLaserSerial on a second pseudo-terminal) to 2 targets in the
 * lab world; hslam-process maps the recording. Checked against the emulator's
 * true pose and the world's ground-truth map: every target reached, no
 * collision, map agreement. The script's own guards bound every wait (emulator
 * ready 30 s, navigation 90 s); nothing here waits on the wall clock. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/sim/clearance.h>
#include <hslam/sim/scene.h>
#include <hslam/sim/scene_rendering.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPoint2D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

namespace
{
const std::string kSrc = HSLAM_SOURCE_DIR;
const mrpt::poses::CPose2D kStart(2.0, 2.2, 0.0);  // sim-nav-lab.ini [robot] start, as in the script
const std::vector<mrpt::math::TPoint2D> kTargets{{1.5, 2.7}, {1.5, 5.2}};  // --short

struct TRun
{
	int exitCode = -1;
	std::string out;
};

TRun runScript(const std::string& outDir)
{
	const auto r = hslam::testing::runCapturingOutput("HSLAM_BIN=" + std::string(HSLAM_BIN_DIR) + " " + kSrc +
													  "/scripts/driven-run.sh " + outDir + " --short");
	return {r.exitCode, r.out};
}

mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path)
{
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(path);
	mrpt::serialization::archiveFrom(in) >> grid;
	return grid;
}

/** Cells of `map` (odometry frame, origin at `start` in the world) that it
 * knows (p_occ < 0.4 free, > 0.6 occupied) compared with the ground truth:
 * a free cell agrees if the truth is free at its centre, an occupied cell if
 * the truth has an occupied cell within `tolerance_m` (one map cell, the
 * LMS200's range quantisation and the odometry drift of a short run). */
struct TAgreement
{
	size_t free = 0, freeAgreed = 0, occupied = 0, occupiedAgreed = 0;
	double fraction() const { return double(freeAgreed + occupiedAgreed) / std::max<size_t>(1, free + occupied); }
};

bool occupiedNear(const mrpt::maps::COccupancyGridMap2D& gt, double x, double y, double r)
{
	for (double dx = -r; dx <= r + 1e-9; dx += gt.getResolution())
		for (double dy = -r; dy <= r + 1e-9; dy += gt.getResolution())
			if (gt.getPos(x + dx, y + dy) < 0.5) return true;
	return false;
}

TAgreement compareWithTruth(const mrpt::maps::COccupancyGridMap2D& map, const mrpt::maps::COccupancyGridMap2D& gt,
							const mrpt::poses::CPose2D& start, double tolerance_m)
{
	TAgreement a;
	for (unsigned cy = 0; cy < map.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < map.getSizeX(); ++cx)
		{
			const double pOcc = 1.0 - map.getCell(cx, cy);
			if (pOcc > 0.4 && pOcc < 0.6) continue;
			const auto w = start + mrpt::poses::CPoint2D(map.idx2x(cx), map.idx2y(cy));
			if (pOcc >= 0.6)
				++a.occupied, a.occupiedAgreed += occupiedNear(gt, w.x(), w.y(), tolerance_m);
			else
				++a.free, a.freeAgreed += gt.getPos(w.x(), w.y()) > 0.5;
		}
	return a;
}
/** Frame of `estimate` in the world: the rigid transform that best lays it
 * onto `truth` (truth pose nearest in time to each estimate): rotation = the
 * circular mean of the heading differences, translation = the difference of
 * the centroids after the rotation. */
mrpt::poses::CPose2D estimateFrameInWorld(const hslam::common::TTrajectory2D& estimate,
										  const hslam::common::TTrajectory2D& truth)
{
	double s = 0, c = 0, ex = 0, ey = 0, tx = 0, ty = 0;
	for (const auto& e : estimate)
	{
		const auto it = std::lower_bound(truth.begin(), truth.end(), e.t_s,
										 [](const hslam::common::TTimedPose2D& p, double t) { return p.t_s < t; });
		const auto& t = it == truth.end() ? truth.back().pose : it->pose;
		s += std::sin(t.phi - e.pose.phi), c += std::cos(t.phi - e.pose.phi);
		ex += e.pose.x, ey += e.pose.y, tx += t.x, ty += t.y;
	}
	const double n = static_cast<double>(estimate.size()), yaw = std::atan2(s, c);
	const mrpt::poses::CPose2D rot(0, 0, yaw);
	const auto centroid = rot + mrpt::poses::CPoint2D(ex / n, ey / n);
	return mrpt::poses::CPose2D(tx / n - centroid.x(), ty / n - centroid.y(), yaw);
}

/** The true path (emulator, 20 Hz): each target reached in order, within
 * the controller's 0.2 m plus the odometry's drift; never within 0.2 m of a
 * static obstacle (the collision criterion of sim::runClosedLoop). */
void checkTruePath(const hslam::common::TTrajectory2D& truth, const hslam::sim::CWorld& world)
{
	ASSERT_GT(truth.size(), 50u);
	size_t next = 0;
	double minClearance = std::numeric_limits<double>::infinity(), nearest = 1e9;
	for (const auto& p : truth)
	{
		minClearance = std::min(minClearance, hslam::sim::clearance_m(world, {p.pose.x, p.pose.y}, false));
		if (next < kTargets.size())
		{
			const double d = std::hypot(p.pose.x - kTargets[next].x, p.pose.y - kTargets[next].y);
			nearest = std::min(nearest, d);
			if (d < 0.3) ++next, nearest = 1e9;
		}
	}
	EXPECT_EQ(next, kTargets.size()) << "true pose never within 0.3 m of target " << next + 1 << " (nearest " << nearest
									 << " m)";
	EXPECT_GT(minClearance, 0.2) << "collision";
	std::printf("driven run: %zu true poses, min clearance %.3f m\n", truth.size(), minClearance);
}
}  // namespace

TEST(DrivenRunIntegration, ShortRunReachesBothTargetsWithoutCollisionAndMapsTheLab)
{
	hslam::testing::CTempDir tmp;
	const std::string out = tmp.file("run");
	const auto r = runScript(out);
	ASSERT_EQ(r.exitCode, 0) << r.out;
	EXPECT_NE(r.out.find("targets reached: 2 / 2"), std::string::npos) << r.out;
	for (const char* f : {"nav/navigation.rawlog", "nav/path.csv", "nav/path.png", "nav/live_map.png",
						  "map/map.gridmap.gz", "map/map.png", "truth.tum"})
		EXPECT_TRUE(std::filesystem::exists(out + "/" + f)) << f;

	const auto scene = hslam::sim::loadSceneFile(kSrc + "/config_ini/sim-worlds/nav-lab.scene");
	checkTruePath(hslam::common::readTumFile(out + "/truth.tum"), scene.world);

	// The batch map of the recording (hslam-process) and the live map
	// (hslam-navigate, scans at the odometry pose) against the world's ground
	// truth. Measured over 24 runs (docs/nav.md, "The driven run"): overall
	// 0.936-0.989 batch, 0.976-0.992 live; free cells 0.977-0.996; occupied
	// cells 0.59-0.94 batch, 0.81-0.999 live. Thresholds below the worst with
	// margin. The batch map is laid onto the world by its own trajectory (as
	// an ATE is): under CPU load a scan read late carries a late time stamp,
	// and if that happens while the robot turns at the start the whole batch
	// map comes out rotated by a few degrees, self-consistent and 1 cm from
	// the true path (seen at 4.5 deg, occupied agreement 0.26 against kStart).
	struct TCase
	{
		const char* file;
		mrpt::poses::CPose2D frame;
		double minOverall, minOccupied;
	};
	const auto gt = hslam::sim::rasterizeWorld(scene.world, 0.05, 0.5);
	const auto truth = hslam::common::readTumFile(out + "/truth.tum");
	const auto batchFrame = estimateFrameInWorld(hslam::common::readTumFile(out + "/map/trajectory.tum"), truth);
	std::printf("batch map frame in the world: %.3f %.3f %.2f deg (start %.3f %.3f %.2f deg)\n", batchFrame.x(),
				batchFrame.y(), mrpt::RAD2DEG(batchFrame.phi()), kStart.x(), kStart.y(), mrpt::RAD2DEG(kStart.phi()));
	EXPECT_LT(std::abs(mrpt::RAD2DEG(batchFrame.phi())), 10.0);
	for (const auto& [name, frame, minOverall, minOcc] :
		 {TCase{"map/map.gridmap.gz", batchFrame, 0.90, 0.4}, TCase{"nav/live_map.gridmap.gz", kStart, 0.95, 0.7}})
	{
		const auto a = compareWithTruth(loadGridmap(out + "/" + name), gt, frame, 0.1);
		const double freeOk = double(a.freeAgreed) / std::max<size_t>(1, a.free);
		const double occOk = double(a.occupiedAgreed) / std::max<size_t>(1, a.occupied);
		std::printf("%s vs ground truth: %zu free cells (%.4f agree), %zu occupied (%.4f agree), overall %.4f\n", name,
					a.free, freeOk, a.occupied, occOk, a.fraction());
		EXPECT_GT(a.free, 2000u) << name;
		EXPECT_GT(a.occupied, 200u) << name;
		EXPECT_GT(a.fraction(), minOverall) << name;
		EXPECT_GT(freeOk, 0.96) << name;
		EXPECT_GT(occOk, minOcc) << name;
	}
}
