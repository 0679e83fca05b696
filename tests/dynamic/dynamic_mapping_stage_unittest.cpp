/* slam::CDynamicMappingStage and CRetroClearedGrid: late exclusions take back
 * exactly the occupied updates the named beams made. Cell units: 1000 per nat;
 *   occupied 0.7 -> round(1000 ln(7/3)) = 847, occupied 0.9 -> 2197,
 *   clamp 0.98   -> round(1000 ln 49)  = 3892. */
#include <gtest/gtest.h>
#include <hslam/slam/CDynamicMappingStage.h>
#include <hslam/slam/CScanArchive.h>

#include <cmath>

using namespace hslam;

namespace
{
/** Two beams along +x (0.001 rad apart) ending 2.03 m ahead; only beam 0 valid
 * if `hit`, none otherwise. */
mrpt::obs::CObservation2DRangeScan beamAlongX(bool hit)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = 0.001f;
	scan.resizeScan(2);
	for (size_t b = 0; b < 2; ++b)
	{
		scan.setScanRange(b, 2.03f);
		scan.setScanRangeValidity(b, hit && b == 0);
	}
	return scan;
}

const mrpt::poses::CPose2D kRobot(0.05, 0.05, 0.0);  // centre of cell (0,0)
const maps::TGlobalCell kEnd{20, 0};  // beam 0's end cell (x = 2.08 m)

slam::TDynamicMapUpdate keep(uint32_t scans, std::vector<slam::TRetroClear> retro = {})
{
	slam::TDynamicMapUpdate u;
	u.keep_scans = scans;
	u.retro_clear = std::move(retro);
	return u;
}
}  // namespace

TEST(DynamicMappingStage, LateExclusionUndoesExactlyThePersonHits)
{
	// Scans 0 and 1 hit a person (not yet confirmed), scan 2 the wall behind:
	// 847, 1694, 2541. Undoing scans 0 and 1 leaves exactly the static hit.
	maps::CLaserGridInserter::TOptions laser;
	laser.occupied_probability = 0.7;  // three hits stay below the clamp
	maps::CLaserGridInserter inserter(laser);
	maps::CTiledOccupancyGrid grid;
	slam::CRetroClearedGrid retro(grid);
	for (int k = 0; k < 3; ++k) retro.insert(inserter, beamAlongX(true), kRobot, keep(3));
	ASSERT_EQ(grid.rawCell(kEnd), 2541);
	retro.insert(inserter, beamAlongX(false), kRobot, keep(0, {{3, 0}, {2, 0}}));  // 3 back: scan 0
	EXPECT_EQ(grid.rawCell(kEnd), 847);
	EXPECT_EQ(retro.recordsKept(), 0u);
}

TEST(DynamicMappingStage, SaturatedWallHitByALegBeamKeepsItsValue)
{
	// A wall cell saturated by three hits (2197, 3892, 3892), then a leg beam
	// ends in it (applies 0). Taking the leg hit back leaves 3892; subtracting
	// the sensor model instead would give 3892 - 2197 = 1695 (p 0.84).
	maps::CLaserGridInserter inserter;
	maps::CTiledOccupancyGrid grid;
	slam::CRetroClearedGrid retro(grid);
	for (int k = 0; k < 4; ++k) retro.insert(inserter, beamAlongX(true), kRobot, keep(1));
	retro.insert(inserter, beamAlongX(false), kRobot, keep(0, {{1, 0}}));
	EXPECT_EQ(grid.rawCell(kEnd), 3892);
}

TEST(DynamicMappingStage, RecordsOlderThanKeepScansAreForgotten)
{
	maps::CLaserGridInserter::TOptions laser;
	laser.occupied_probability = 0.7;
	maps::CLaserGridInserter inserter(laser);
	maps::CTiledOccupancyGrid grid;
	slam::CRetroClearedGrid retro(grid);
	for (int k = 0; k < 2; ++k) retro.insert(inserter, beamAlongX(true), kRobot, keep(1));
	EXPECT_EQ(retro.recordsKept(), 1u);
	retro.insert(inserter, beamAlongX(false), kRobot, keep(2, {{2, 0}}));  // scan 0: forgotten
	EXPECT_EQ(grid.rawCell(kEnd), 1694);
	retro.insert(inserter, beamAlongX(false), kRobot, keep(0, {{2, 0}}));  // scan 1: kept, undone
	EXPECT_EQ(grid.rawCell(kEnd), 847);
}

TEST(DynamicMappingStage, FrameBecomesScansBackAndRecordsToKeep)
{
	dynamic::TDynamicFrame frame;
	frame.scan_index = 10;
	frame.beam_is_dynamic = {false, true};
	frame.retro_clear_beams = {{7, 3}, {9, 1}};
	frame.pending_since_scan = 8;  // scans 8, 9, 10 may still be named
	const auto u = slam::dynamicMapUpdate(frame);
	EXPECT_EQ(u.excluded, frame.beam_is_dynamic);
	ASSERT_EQ(u.retro_clear.size(), 2u);
	EXPECT_EQ(u.retro_clear[0].scans_back, 3u);
	EXPECT_EQ(u.retro_clear[0].beam, 3u);
	EXPECT_EQ(u.retro_clear[1].scans_back, 1u);
	EXPECT_EQ(u.keep_scans, 3u);
	frame.pending_since_scan = 11;  // nothing pending
	EXPECT_EQ(slam::dynamicMapUpdate(frame).keep_scans, 0u);
}

TEST(DynamicMappingStage, WithoutFilterEveryGridGetsThePlainScan)
{
	maps::CLaserGridInserter inserter;
	maps::CTiledOccupancyGrid a, b;
	slam::CDynamicMappingStage stage(inserter);
	EXPECT_EQ(stage.addGrid(a), 0u);
	EXPECT_EQ(stage.addGrid(b), 1u);
	const auto& u = stage.process(beamAlongX(true), kRobot, 0.0);
	EXPECT_TRUE(u.excluded.empty());
	EXPECT_EQ(u.keep_scans, 0u);
	EXPECT_EQ(a.rawCell(kEnd), 2197);
	EXPECT_EQ(b.rawCell(kEnd), 2197);
	EXPECT_THROW(stage.insertScan(2, beamAlongX(true), {}, u), std::out_of_range);
}

TEST(DynamicMappingStage, ArchiveReplayAtTheSamePosesRebuildsTheMapBitForBit)
{
	// Online: three hits (847 each), then the first two taken back; the
	// archive stores each scan's update, and replaying it gives 847 again,
	// every other cell equal too.
	maps::CLaserGridInserter::TOptions laser;
	laser.occupied_probability = 0.7;
	maps::CLaserGridInserter inserter(laser);
	maps::CTiledOccupancyGrid online, replayed;
	slam::CDynamicMappingStage stage(inserter);
	stage.addGrid(online);
	slam::CScanArchive archive;
	std::vector<mrpt::poses::CPose2D> poses;
	const std::vector<slam::TDynamicMapUpdate> updates = {keep(3), keep(3), keep(3), keep(0, {{3, 0}, {2, 0}})};
	for (size_t k = 0; k < updates.size(); ++k)
	{
		const auto scan = beamAlongX(k < 3);
		stage.insertScan(0, scan, kRobot, updates[k]);
		archive.add(scan, updates[k]);
		poses.push_back(kRobot);
	}
	archive.replay(replayed, poses, inserter);
	EXPECT_EQ(online.rawCell(kEnd), 847);
	EXPECT_EQ(replayed.rawCell(kEnd), 847);
	const auto b = online.observedBounds();
	for (int gy = b.gyMin; gy <= b.gyMax; ++gy)
		for (int gx = b.gxMin; gx <= b.gxMax; ++gx) ASSERT_EQ(online.rawCell({gx, gy}), replayed.rawCell({gx, gy}));
}
