#include <gtest/gtest.h>
#include <hslam/maps/CTiledGridGeometry.h>

using namespace hslam::maps;

// Thesis geometry: 0.1 m cells, 200 x 200 cells per tile (20 m x 20 m).
class TiledGridGeometry : public ::testing::Test
{
   protected:
	CTiledGridGeometry geo{0.1, 200};
};

TEST_F(TiledGridGeometry, OriginIsCentreOfHomeTile)
{
	const TGlobalCell c = geo.cellOf(0.001, 0.001);
	EXPECT_EQ(geo.tileOf(c), (TTileIndex{0, 0}));
	EXPECT_EQ(geo.localCellOf(c), (TLocalCell{100, 100}));  // thesis eq. 81: (100, 100)
	EXPECT_EQ(geo.localCellOf(geo.cellOf(-0.001, -0.001)), (TLocalCell{99, 99}));
}

TEST_F(TiledGridGeometry, MatchesThesisEq81UpToTheDocumentedHalfCellShift)
{
	// eq. 81: x_cell = 100 + ceil((x_mm - 50) / 100) (cells centred on 0.1 m
	// multiples); ours has cell edges there, so both agree on [0, 50) mm of
	// every 100 mm and ours is one less on [50, 100).
	for (double x_mm : {-9940.0, -4321.0, -51.0, -49.0, -1.0, 1.0, 49.0, 51.0, 1234.0, 9940.0})
	{
		const int thesis = 100 + static_cast<int>(std::ceil((x_mm - 50.0) / 100.0));
		const double withinCell_mm = x_mm - 100.0 * std::floor(x_mm / 100.0);
		const int expected = thesis - (withinCell_mm > 50.0 ? 1 : 0);
		EXPECT_EQ(geo.localCellOf(geo.cellOf(x_mm / 1000.0, 0.0)).lx, expected) << x_mm;
	}
}

TEST_F(TiledGridGeometry, TileBordersOnBothSidesOfTheOrigin)
{
	// Home tile covers [-10, 10) m.
	EXPECT_EQ(geo.tileOf(geo.cellOf(9.99, 0)).ix, 0);
	EXPECT_EQ(geo.localCellOf(geo.cellOf(9.99, 0)).lx, 199);
	EXPECT_EQ(geo.tileOf(geo.cellOf(10.01, 0)).ix, 1);
	EXPECT_EQ(geo.localCellOf(geo.cellOf(10.01, 0)).lx, 0);
	EXPECT_EQ(geo.tileOf(geo.cellOf(-9.99, 0)).ix, 0);
	EXPECT_EQ(geo.localCellOf(geo.cellOf(-9.99, 0)).lx, 0);
	EXPECT_EQ(geo.tileOf(geo.cellOf(-10.01, 0)).ix, -1);  // truncating division would say 0
	EXPECT_EQ(geo.localCellOf(geo.cellOf(-10.01, 0)).lx, 199);
	EXPECT_EQ(geo.tileOf(geo.cellOf(0, -30.01)).iy, -2);
	EXPECT_EQ(geo.tileOf(geo.cellOf(0, -29.99)).iy, -1);
}

TEST_F(TiledGridGeometry, GlobalLocalRoundTripAndCellCentres)
{
	for (int gx = -1005; gx <= 1005; gx += 67)
		for (int gy = -1005; gy <= 1005; gy += 71)
		{
			const TGlobalCell g{gx, gy};
			const TTileIndex t = geo.tileOf(g);
			const TLocalCell l = geo.localCellOf(g);
			ASSERT_GE(l.lx, 0);
			ASSERT_LT(l.lx, 200);
			ASSERT_GE(l.ly, 0);
			ASSERT_LT(l.ly, 200);
			EXPECT_EQ(geo.globalCellOf(t, l), g);
			const auto centre = geo.cellCentre(g);
			EXPECT_EQ(geo.cellOf(centre.x, centre.y), g);
			// eq. 84 (corrected): x = (T N + l - N/2) res
			EXPECT_NEAR(centre.x, (t.ix * 200 + l.lx - 100 + 0.5) * 0.1, 1e-9);
		}
}

TEST(FloorDiv, NegativeNumbers)
{
	EXPECT_EQ(floorDiv(-1, 200), -1);
	EXPECT_EQ(floorDiv(-200, 200), -1);
	EXPECT_EQ(floorDiv(-201, 200), -2);
	EXPECT_EQ(floorDiv(199, 200), 0);
	EXPECT_EQ(floorDiv(200, 200), 1);
}
