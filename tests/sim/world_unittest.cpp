/* Tests of the simulated world: exact ray casting against segments, circles
 * and raster cells, the scene text format, corners and the raster loaders. */
#include <gtest/gtest.h>
#include <hslam/sim/scene.h>
#include <hslam/sim/scene_rendering.h>
#include <hslam/testing/temp_dir.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

using namespace hslam::sim;
using mrpt::math::TPoint2D;

TEST(SimWorld, RayHitsWallAtExactDistanceWithNormalAndIncidence)
{
	CWorld w;
	w.addSegment(TSegment{{3, -10}, {3, 10}, TObjectTag{EObjectKind::wall, 7, 0}});
	const TRayHit straight = w.castRay({0, 0}, 0.0, 10.0);
	ASSERT_TRUE(straight.hit);
	EXPECT_NEAR(straight.range_m, 3.0, 1e-12);
	EXPECT_NEAR(straight.normal.x, -1.0, 1e-12);  // facing the ray origin
	EXPECT_NEAR(straight.incidence_rad, 0.0, 1e-9);
	EXPECT_EQ(straight.tag.group, 7);
	const TRayHit oblique = w.castRay({0, 0}, M_PI / 3, 10.0);  // 60 deg
	ASSERT_TRUE(oblique.hit);
	EXPECT_NEAR(oblique.range_m, 6.0, 1e-12);  // 3 / cos 60
	EXPECT_NEAR(oblique.incidence_rad, M_PI / 3, 1e-9);
	EXPECT_FALSE(w.castRay({0, 0}, M_PI, 10.0).hit);  // away from the wall
	const TRayHit tooFar = w.castRay({0, 0}, 0.0, 2.5);
	EXPECT_FALSE(tooFar.hit);
	EXPECT_DOUBLE_EQ(tooFar.range_m, 2.5);
}

TEST(SimWorld, RayHitsNearestOfCircleAndWall)
{
	CWorld w;
	w.addSegment(TSegment{{5, -5}, {5, 5}, {}});
	w.addCircle(TCircle{{2, 0}, 0.1, TObjectTag{EObjectKind::furniture, 3, 1}});
	const TRayHit h = w.castRay({0, 0}, 0.0, 10.0);
	ASSERT_TRUE(h.hit);
	EXPECT_NEAR(h.range_m, 1.9, 1e-12);
	EXPECT_EQ(h.tag.kind, EObjectKind::furniture);
	EXPECT_EQ(h.tag.part, 1);
	// A ray passing 0.2 m beside the circle reaches the wall.
	const TRayHit beside = w.castRay({0, 0.2}, 0.0, 10.0);
	EXPECT_NEAR(beside.range_m, 5.0, 1e-12);
	// Dynamic circles occlude only when included.
	w.setDynamicCircles({TCircle{{1, 0.2}, 0.05, TObjectTag{EObjectKind::person_leg, 0, 1}}});
	EXPECT_NEAR(w.castRay({0, 0.2}, 0.0, 10.0).range_m, 0.95, 1e-12);
	EXPECT_NEAR(w.castRay({0, 0.2}, 0.0, 10.0, false).range_m, 5.0, 1e-12);
}

TEST(SimWorld, RasterCellsAreHitOnTheirFaces)
{
	TOccupancyRaster r;
	r.resolution_m = 0.1;
	r.width = 100;
	r.height = 100;
	r.occupied.assign(100 * 100, 0);
	for (int j = 0; j < 100; ++j) r.occupied[j * 100 + 70] = 1;  // column of cells at x in [7.0, 7.1)
	CWorld w;
	w.setRaster(r);
	const TRayHit h = w.castRay({2.05, 5.0}, 0.0, 20.0);
	ASSERT_TRUE(h.hit);
	EXPECT_NEAR(h.range_m, 4.95, 1e-9);
	EXPECT_NEAR(h.normal.x, -1.0, 1e-12);
	const TRayHit diag = w.castRay({2.0, 5.0}, M_PI / 6, 20.0);
	EXPECT_NEAR(diag.range_m, 5.0 / std::cos(M_PI / 6), 1e-9);
	EXPECT_FALSE(w.castRay({2.0, 5.0}, M_PI, 20.0).hit);
}

TEST(SimScene, ParsesItemsAndClassifiesCorners)
{
	const TScene s = parseSceneText(
		"room 0 0 10 0 10 8 0 8   # 4 concave corners\n"
		"box 5 4 1 1              # 4 convex corners\n"
		"box 9.5 2 1 1            # touches the east wall: 2 corners become concave\n"
		"chair 2 2\n"
		"table 3 6 1.2 0.8 90\n"
		"person 1.0 0.06 0.6 1 1 4 1 loop\n",
		"test.scene");
	EXPECT_EQ(s.world.segments().size(), 12u);
	EXPECT_EQ(s.world.circles().size(), 8u);
	ASSERT_EQ(s.people.size(), 1u);
	EXPECT_DOUBLE_EQ(s.people[0].leg_radius_m, 0.06);
	int concave = 0, convex = 0;
	for (const auto& c : s.corners)
	{
		if (c.kind == ECornerKind::concave)
		{
			++concave;
			EXPECT_NEAR(c.free_angle_deg, 90.0, 1e-9);
		}
		if (c.kind == ECornerKind::convex)
		{
			++convex;
			EXPECT_NEAR(c.free_angle_deg, 270.0, 1e-9);
		}
	}
	EXPECT_EQ(concave, 4 + 2);
	EXPECT_EQ(convex, 4 + 2);
}

TEST(SimScene, ErrorsNameFileAndLine)
{
	try
	{
		parseSceneText("room 0 0 1 0 1 1\nwall 0 0 1 nan\n", "bad.scene");
		FAIL() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("bad.scene:2:"), std::string::npos) << e.what();
	}
	EXPECT_THROW(parseSceneText("sofa 1 2\n", "x"), std::runtime_error);
	EXPECT_THROW(parseSceneText("polyline 0 0 1\n", "x"), std::runtime_error);
	EXPECT_THROW(parseSceneText("person 9 0.06 0.6 0 0 1 1\n", "x"), std::runtime_error);  // 9 m/s
	EXPECT_THROW(loadSceneFile("/nonexistent/file.scene"), std::runtime_error);
}

TEST(SimScene, LoadsPngAndGridmapRasters)
{
	hslam::testing::CTempDir dir;
	// 200 x 100 px image at 5 cm: a dark vertical bar at columns 150..151 (x = 7.5 m).
	mrpt::img::CImage img(200, 100, mrpt::img::CH_GRAY);
	img.filledRectangle(0, 0, 199, 99, mrpt::img::TColor(255, 255, 255));
	img.filledRectangle(150, 0, 151, 99, mrpt::img::TColor(0, 0, 0));
	ASSERT_TRUE(img.saveToFile(dir.file("map.png")));
	CWorld w;
	w.setRaster(loadOccupancyImage(dir.file("map.png"), 0.05, 0.0, 0.0));
	EXPECT_NEAR(w.castRay({1.0, 2.5}, 0.0, 20.0).range_m, 6.5, 1e-9);

	// The same world through a rasterised MRPT grid written as .gridmap.gz.
	CWorld walls;
	walls.addSegment(TSegment{{3.0, -1}, {3.0, 1}, {}});
	const auto grid = rasterizeWorld(walls, 0.05, 1.0);
	{
		mrpt::io::CFileGZOutputStream out(dir.file("w.gridmap.gz"));
		auto a = mrpt::serialization::archiveFrom(out);
		a << grid;
	}
	CWorld fromGrid;
	fromGrid.setRaster(loadGridMapFile(dir.file("w.gridmap.gz")));
	const TRayHit h = fromGrid.castRay({0.0, 0.0}, 0.0, 10.0);
	ASSERT_TRUE(h.hit);
	EXPECT_NEAR(h.range_m, 3.0, 0.05);  // within one cell
	EXPECT_THROW(loadGridMapFile(dir.file("map.png")), std::runtime_error);
	EXPECT_THROW(loadOccupancyImage(dir.file("none.png"), 0.05, 0, 0), std::runtime_error);
}
