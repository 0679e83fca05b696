#include <gtest/gtest.h>
#include <hslam/eval/point_landmark_score.h>
#include <hslam/testing/temp_dir.h>

#include <fstream>

using namespace hslam::eval;
using mrpt::math::TPoint2D;

TEST(PointLandmarkScore, HandCountedPrecisionAndRecall)
{
	const std::vector<TPoint2D> truth{{0, 0}, {4, 0}, {4, 3}};
	// Found in a frame shifted by (1, 0): (-1, 0.1) -> (0, 0.1) near truth 0;
	// (3, 2.8) -> (4, 2.8) near truth 2; (1, 1) -> (2, 1) near nothing.
	const std::vector<TPoint2D> found{{-1, 0.1}, {3, 2.8}, {1, 1}};
	const auto s = scorePointLandmarks(found, truth, 0.25, mrpt::poses::CPose2D(1, 0, 0));
	EXPECT_EQ(s.found, 3u);
	EXPECT_EQ(s.found_near_truth, 2u);
	EXPECT_EQ(s.truth_found, 2u);
	EXPECT_NEAR(s.precision(), 2.0 / 3.0, 1e-12);
	EXPECT_NEAR(s.recall(), 2.0 / 3.0, 1e-12);
	EXPECT_EQ(scorePointLandmarks(found, truth, 0.15, mrpt::poses::CPose2D(1, 0, 0)).found_near_truth, 1u);
	// A disc of radius 0.2 at (2, 1.3): the point (2, 1) is 0.1 from its surface.
	const auto d = scorePointLandmarks(found, {{2, 1.3}}, 0.15, mrpt::poses::CPose2D(1, 0, 0), {0.2});
	EXPECT_EQ(d.found_near_truth, 1u);
	EXPECT_THROW(scorePointLandmarks(found, truth, 0.1, {}, {0.2}), std::invalid_argument);
}

TEST(PointLandmarkScore, ReadsCsvColumnsAndNamesBadLines)
{
	hslam::testing::CTempDir dir;
	std::ofstream(dir.file("ok.csv")) << "id,x_m,y_m,kind\n0,1.5,-2,concave\n1, 3 ,4.25,convex\n";
	const auto points = readPointsCsv(dir.file("ok.csv"));
	ASSERT_EQ(points.size(), 2u);
	EXPECT_DOUBLE_EQ(points[1].x, 3.0);
	EXPECT_DOUBLE_EQ(points[1].y, 4.25);
	std::ofstream(dir.file("bad.csv")) << "x_m,y_m\n1,2\n1,abc\n";
	try
	{
		readPointsCsv(dir.file("bad.csv"));
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("bad.csv:3"), std::string::npos) << e.what();
	}
	std::ofstream(dir.file("nocol.csv")) << "a,b\n1,2\n";
	EXPECT_THROW(readPointsCsv(dir.file("nocol.csv")), std::runtime_error);
	EXPECT_THROW(readPointsCsv(dir.file("missing.csv")), std::runtime_error);
}
