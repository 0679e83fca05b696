/* CLaserGridInserter::undo: the exact inverse of a beam's occupied update.
 * Cell units are kLogOddsScale = 1000 per nat:
 *   occupied 0.9  -> round(1000 * ln 9)       = 2197
 *   free 0.3      -> round(1000 * ln(3/7))    = -847
 *   clamp 0.98    -> round(1000 * ln 49)      = 3892 */
#include <gtest/gtest.h>
#include <hslam/maps/CLaserGridInserter.h>

#include <cmath>

using namespace hslam::maps;

namespace
{
/** 5 beams 45 deg apart over 180 deg, all at `range_m` (no two share a cell). */
mrpt::obs::CObservation2DRangeScan uniformScan(float range_m)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 80.0f;
	scan.resizeScan(5);
	for (size_t i = 0; i < 5; ++i)
	{
		scan.setScanRange(i, range_m);
		scan.setScanRangeValidity(i, true);
	}
	return scan;
}

const mrpt::poses::CPose2D kRobot(0.05, 0.05, 0.0);  // centre of cell (0,0)
const TGlobalCell kCentralHit{20, 0}, kCentralFree{15, 0}, kLeftHit{0, 20};
}  // namespace

TEST(LaserInsertionUndo, RecordHoldsTheAppliedDeltaPerHitBeam)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	TLaserInsertionRecord first, second, third;
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &first);
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &second);
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &third);
	ASSERT_EQ(first.hits.size(), 5u);
	const TOccupiedHit& h1 = first.hits[2];
	EXPECT_EQ(h1.beam, 2u);
	EXPECT_EQ(h1.cell, kCentralHit);
	EXPECT_EQ(h1.before, kUnknownCell);
	EXPECT_EQ(h1.applied, 2197);
	EXPECT_EQ(second.hits[2].before, 2197);
	EXPECT_EQ(second.hits[2].applied, 3892 - 2197);  // 4394 clamped at 3892
	EXPECT_EQ(third.hits[2].before, 3892);
	EXPECT_EQ(third.hits[2].applied, 0);  // saturated: nothing gained
}

TEST(LaserInsertionUndo, UnsaturatedCellReturnsExactlyAndFreeCellsAreUntouched)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	inserter.insert(grid, kRobot, uniformScan(2.0f));  // 2197 in every hit cell, -847 on the rays
	TLaserInsertionRecord record;
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &record);
	EXPECT_EQ(grid.rawCell(kCentralHit), 3892);
	EXPECT_EQ(CLaserGridInserter::undo(grid, record, {2}), 1u);
	EXPECT_EQ(grid.rawCell(kCentralHit), 2197);  // back to the value before
	EXPECT_EQ(grid.rawCell(kLeftHit), 3892);  // beam 4 not undone
	EXPECT_EQ(grid.rawCell(kCentralFree), -1694);  // two free updates, kept
}

TEST(LaserInsertionUndo, SaturatedCellKeepsItsSaturatedValue)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	for (int k = 0; k < 2; ++k) inserter.insert(grid, kRobot, uniformScan(2.0f));
	TLaserInsertionRecord record;
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &record);
	CLaserGridInserter::undo(grid, record, {2});
	// Subtracting the sensor model (3892 - 2197 = 1695, p = 0.84) would take
	// away log-odds the saturated wall never gained from this beam.
	EXPECT_EQ(grid.rawCell(kCentralHit), 3892);
}

TEST(LaserInsertionUndo, UnknownCellBecomesUnknownAgain)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	TLaserInsertionRecord record;
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &record);
	EXPECT_EQ(CLaserGridInserter::undo(grid, record, {0, 1, 2, 3, 4}), 5u);
	EXPECT_FALSE(grid.isObserved(kCentralHit));
	EXPECT_FALSE(grid.isObserved(kLeftHit));
	EXPECT_EQ(grid.rawCell(kCentralFree), -847);
}

TEST(LaserInsertionUndo, LaterUpdatesStayAndOnlyTheHitIsSubtracted)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	TLaserInsertionRecord record;
	inserter.insert(grid, kRobot, uniformScan(2.0f), nullptr, &record);
	inserter.insert(grid, kRobot, uniformScan(3.0f));  // free pass through (20,0): 2197 - 847 = 1350
	CLaserGridInserter::undo(grid, record, {2});
	EXPECT_EQ(grid.rawCell(kCentralHit), -847);  // what the free pass alone gives
}

TEST(LaserInsertionUndo, TwoHitsOfOneScanInOneCellUndoNewestFirst)
{
	// Two beams 0.001 rad apart end in the same cell: 2197, then 3892 (clamped).
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = 0.001f;
	scan.resizeScan(2);
	for (size_t b = 0; b < 2; ++b) scan.setScanRange(b, 2.03f), scan.setScanRangeValidity(b, true);
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	TLaserInsertionRecord record;
	inserter.insert(grid, kRobot, scan, nullptr, &record);
	ASSERT_EQ(record.hits.size(), 2u);
	ASSERT_EQ(record.hits[0].cell, record.hits[1].cell);
	EXPECT_EQ(record.hits[1].applied, 3892 - 2197);
	CLaserGridInserter::undo(grid, record, {0, 1});
	EXPECT_FALSE(grid.isObserved(record.hits[0].cell));
}
