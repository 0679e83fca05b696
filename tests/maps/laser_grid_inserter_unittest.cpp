#include <gtest/gtest.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/grid_rendering.h>

#include <cmath>

using namespace hslam::maps;

namespace
{
/** A 180 deg scan with every beam at `range_m`. The default 5 beams are 45 deg
 * apart, so no two beams share a cell and the expected cell values are exact. */
mrpt::obs::CObservation2DRangeScan uniformScan(float range_m, size_t beams = 5)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 80.0f;
	scan.resizeScan(beams);
	for (size_t i = 0; i < beams; ++i)
	{
		scan.setScanRange(i, range_m);
		scan.setScanRangeValidity(i, true);
	}
	return scan;
}

double logit(double p) { return std::log(p / (1 - p)); }

// Cells are int16 fixed point (log-odds step 0.001): probabilities match to 1e-4.
// The robot in the middle of cell (0,0), so beam ends at whole metres fall
// in the middle of cells rather than on their edges.
const mrpt::poses::CPose2D kRobotAtCellCentre(0.05, 0.05, 0.0);
}  // namespace

TEST(LaserGridInserter, FreeThenOccupiedAlongTheCentralBeam)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	const auto scan = uniformScan(2.0f);
	const auto stats = inserter.insert(grid, kRobotAtCellCentre, scan);
	EXPECT_EQ(stats.beams_hit, 5u);
	// Central beam (index 2) points along +x: hit cell at x = 2.0 m.
	EXPECT_NEAR(grid.occupancyProbability({20, 0}), 0.9, 1e-4);  // one occupied update from 0.5
	// A cell crossed only by the central beam: exactly one free update, p = 0.3.
	EXPECT_NEAR(grid.occupancyProbability({15, 0}), 0.3, 1e-4);
	// Beyond the hit: untouched.
	EXPECT_FALSE(grid.isObserved({21, 0}));
	EXPECT_FALSE(grid.isObserved({25, 0}));
}

TEST(LaserGridInserter, BayesUpdatesAccumulateAndClampAt098)
{
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	const auto scan = uniformScan(2.0f);
	inserter.insert(grid, kRobotAtCellCentre, scan);
	inserter.insert(grid, kRobotAtCellCentre, uniformScan(3.0f));  // passes through (20,0)
	// one hit then one free pass (eq. 85 in log-odds form)
	EXPECT_NEAR(grid.logOdds({20, 0}), logit(0.9) + logit(0.3), 2e-3);  // int16 fixed point, step 0.001
	for (int k = 0; k < 20; ++k) inserter.insert(grid, kRobotAtCellCentre, scan);
	EXPECT_NEAR(grid.occupancyProbability({20, 0}), 0.98, 1e-4);
	EXPECT_NEAR(grid.occupancyProbability({15, 0}), 0.02, 1e-4);  // free side clamped at 1 - 0.98
}

TEST(LaserGridInserter, RangeLimitDropsOrClearsLongBeams)
{
	const auto scan = uniformScan(5.0f);
	{
		CTiledOccupancyGrid grid;
		CLaserGridInserter inserter;  // default: 3 m, long beams dropped
		const auto stats = inserter.insert(grid, kRobotAtCellCentre, scan);
		EXPECT_EQ(stats.beams_skipped, 5u);
		EXPECT_EQ(grid.tileCount(), 0u);
	}
	{
		CLaserGridInserter::TOptions o;
		o.insert_free_beyond_range = true;
		CTiledOccupancyGrid grid;
		CLaserGridInserter inserter(o);
		const auto stats = inserter.insert(grid, kRobotAtCellCentre, scan);
		EXPECT_EQ(stats.beams_free_only, 5u);
		EXPECT_LT(grid.occupancyProbability({30, 0}), 0.5);  // cleared up to 3 m
		EXPECT_FALSE(grid.isObserved({31, 0}));
		EXPECT_FALSE(grid.isObserved({50, 0}));  // no hit cell
	}
}

TEST(LaserGridInserter, InvalidBeamsAndExcludedHitsAreNotMarkedOccupied)
{
	auto scan = uniformScan(2.0f);
	scan.setScanRangeValidity(2, false);  // central beam invalid
	std::vector<bool> excluded(5, false);
	excluded[0] = true;  // rightmost beam (-90 deg) hits a "person"
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	inserter.insert(grid, kRobotAtCellCentre, scan, &excluded);
	EXPECT_FALSE(grid.isObserved({20, 0}));
	EXPECT_LT(grid.occupancyProbability({0, -20}), 0.5);  // excluded hit: free, not occupied
	EXPECT_GT(grid.occupancyProbability({0, 20}), 0.5);  // +90 deg beam: occupied
}

TEST(LaserGridInserter, RobotPoseAndSensorOffsetAreComposed)
{
	auto scan = uniformScan(1.0f);
	scan.sensorPose = mrpt::poses::CPose3D(0.5, 0, 0, 0, 0, 0);  // laser 0.5 m ahead of the robot centre
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	// Robot at (-30, 12) facing +y: central beam hits (-30, 12 + 0.5 + 1.0), two tiles away.
	inserter.insert(grid, mrpt::poses::CPose2D(-29.95, 12.05, M_PI / 2), scan);
	const TGlobalCell hit = grid.geometry().cellOf(-29.95, 13.55);
	EXPECT_GT(grid.occupancyProbability(hit), 0.5);
	EXPECT_EQ(grid.geometry().tileOf(hit), (TTileIndex{-1, 1}));
	EXPECT_EQ(grid.tileCount(), 2u);  // the robot (y = 12) is in tile row 1; the -90 deg beam ends at y = 10.5
}

TEST(LaserGridInserter, UpsideDownLaserHitsTheMirroredCells)
{
	// The right-hand beam (scan angle -90 deg) of a laser mounted upside down
	// (roll 180 deg) looks to the robot's left: at 1 m on the right and 3 m
	// on the left, its hits are those of a level laser reading 3 m and 1 m.
	auto scan = uniformScan(2.0f);
	scan.setScanRange(0, 1.0f), scan.setScanRange(4, 3.0f);
	scan.sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, 0, M_PI);
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	inserter.insert(grid, kRobotAtCellCentre, scan);
	EXPECT_GT(grid.occupancyProbability(grid.geometry().cellOf(0.05, 1.05)), 0.5);  // left, 1 m
	EXPECT_GT(grid.occupancyProbability(grid.geometry().cellOf(0.05, -2.95)), 0.5);  // right, 3 m
	EXPECT_LT(grid.occupancyProbability(grid.geometry().cellOf(0.05, -0.95)), 0.5);  // right, 1 m: free
}

TEST(LaserGridInserter, RaysAcrossTileBordersAndNegativeCoordinates)
{
	auto scan = uniformScan(2.5f);
	CTiledOccupancyGrid grid;
	CLaserGridInserter inserter;
	// Robot just right of the border x = -10.05 facing -x: central beam crosses into tile (-1, 0).
	inserter.insert(grid, mrpt::poses::CPose2D(-8.95, 0.05, M_PI), scan);
	const TGlobalCell hit = grid.geometry().cellOf(-11.45, 0.05);
	EXPECT_EQ(grid.geometry().tileOf(hit), (TTileIndex{-1, 0}));
	EXPECT_NEAR(grid.occupancyProbability(hit), 0.9, 1e-4);
	EXPECT_LT(grid.occupancyProbability(grid.geometry().cellOf(-10.1, 0.0)), 0.5);
	EXPECT_LT(grid.occupancyProbability(grid.geometry().cellOf(-10.0, 0.0)), 0.5);
}

TEST(GridRendering, MrptGridHasSameCellsAndProbabilities)
{
	CTiledOccupancyGrid grid;
	grid.updateCell({-7, 3}, 2.0f);  // occupied: spans x [-0.7, -0.6), y [0.3, 0.4)
	grid.updateCell({5, -4}, -1.0f);  // free
	const auto bounds = grid.observedBounds();
	EXPECT_EQ(bounds.gxMin, -7);
	EXPECT_EQ(bounds.gxMax, 5);
	const auto mrptGrid = toMrptGrid(grid, {bounds.gxMin - 2, bounds.gxMax + 2, bounds.gyMin - 2, bounds.gyMax + 2});
	// MRPT stores p(free) in 8-bit log-odds: compare at its precision.
	EXPECT_NEAR(mrptGrid.getPos(-0.65, 0.35), 1.0 / (1.0 + std::exp(2.0)), 0.02);
	EXPECT_NEAR(mrptGrid.getPos(0.55, -0.35), 1.0 / (1.0 + std::exp(-1.0)), 0.02);
	EXPECT_NEAR(mrptGrid.getPos(0.05, 0.05), 0.5, 0.01);  // unknown
	// Same cell edges: both corners of our cell read the same MRPT cell, and
	// the neighbouring cells are untouched.
	EXPECT_NEAR(mrptGrid.getPos(-0.699, 0.301), mrptGrid.getPos(-0.601, 0.399), 1e-6);
	EXPECT_NEAR(mrptGrid.getPos(-0.701, 0.35), 0.5, 0.01);
	EXPECT_NEAR(mrptGrid.getPos(-0.599, 0.35), 0.5, 0.01);
}

TEST(GridRendering, ImageColoursAndOrientation)
{
	CTiledOccupancyGrid grid;
	grid.updateCell({0, 0}, 3.0f);  // occupied, top-left of a 2x2 block when north is up
	grid.updateCell({1, -1}, -3.0f);  // free, bottom-right
	TImageFrame frame;
	frame.cells = {0, 1, -1, 0};
	const auto img = renderGrid(grid, frame);
	ASSERT_EQ(img.getWidth(), 2u);
	ASSERT_EQ(img.getHeight(), 2u);
	EXPECT_LT(*img(0, 0, 0), 20);  // dark: occupied at the top-left
	EXPECT_GT(*img(1, 1, 0), 235);  // white: free at the bottom-right
	EXPECT_EQ(*img(1, 0, 1), kUnknownCellColour.G);  // unknown cell: marker colour
}

TEST(GridRendering, EveryPixelIsItsCellsColourAcrossTiles)
{
	// Cells scattered over four tiles (10-cell tiles, negative indices too),
	// a frame that cuts through tiles and reaches past them, 2 pixels per
	// cell: every pixel is its cell's colour from the cell's own probability
	// (the renderer walks tiles, not cells).
	CTiledOccupancyGrid::TOptions options;
	options.tile_size_cells = 10;
	CTiledOccupancyGrid grid(options);
	for (int i = 0; i < 300; ++i)
		grid.updateCell({(i * 7) % 23 - 11, (i * 13) % 19 - 9}, 0.37f * static_cast<float>(i % 11) - 1.8f);
	TImageFrame frame;
	frame.cells = {-14, 9, -12, 6};
	frame.pixels_per_cell = 2;
	const auto img = renderGrid(grid, frame);
	ASSERT_EQ(img.getWidth(), 48u);
	ASSERT_EQ(img.getHeight(), 38u);
	size_t observed = 0;
	for (int gy = frame.cells.gyMin; gy <= frame.cells.gyMax; ++gy)
		for (int gx = frame.cells.gxMin; gx <= frame.cells.gxMax; ++gx)
		{
			const bool seen = grid.isObserved({gx, gy});
			observed += seen ? 1 : 0;
			const auto grey = static_cast<int>(std::lround(255.0 * (1.0 - grid.occupancyProbability({gx, gy}))));
			const int bgr[3] = {seen ? grey : kUnknownCellColour.B, seen ? grey : kUnknownCellColour.G,
								seen ? grey : kUnknownCellColour.R};
			for (int d = 0; d < 4; ++d)
			{
				const unsigned col = static_cast<unsigned>((gx - frame.cells.gxMin) * 2 + d % 2);
				const unsigned row = static_cast<unsigned>((frame.cells.gyMax - gy) * 2 + d / 2);
				for (unsigned ch = 0; ch < 3; ++ch)
					ASSERT_EQ(*img(col, row, ch), bgr[ch]) << gx << " " << gy << " channel " << ch;
			}
		}
	EXPECT_GT(observed, 150u);  // 23 x 19 cells updated, most of them inside the frame
	EXPECT_LT(observed, 24u * 19u);  // and some of the frame unknown
}

TEST(TiledOccupancyGrid, MemoryGrowsWithExploredAreaOnly)
{
	CTiledOccupancyGrid grid;
	// Two far-apart corridors 200 m apart: only the tiles they touch exist.
	for (int i = 0; i < 1000; ++i) grid.updateCell({i, 0}, 1.0f);
	for (int i = 0; i < 1000; ++i) grid.updateCell({0, -2000 + i}, 1.0f);
	EXPECT_EQ(grid.tileCount(), 12u);  // x cells 0..999 -> tiles 0..5; y cells -2000..-1001 -> tiles -10..-5
	EXPECT_EQ(grid.memoryBytes(), 12u * 200 * 200 * 2);  // int16 log-odds, unknown = sentinel
}
