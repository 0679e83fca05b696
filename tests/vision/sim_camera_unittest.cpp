/* The simulator's pinhole camera (libs/sim CPinholeCameraSimulator) seen by
 * the vision code: frames rendered from known robot poses give the FOE the
 * camera's true motion predicts, and walking people appear as cylinders. */
#include <gtest/gtest.h>
#include <hslam/sim/CPinholeCameraSimulator.h>
#include <hslam/vision/observation_image.h>
#include <hslam/vision/synthetic_evaluation.h>
#include <mrpt/obs/CObservationImage.h>

using namespace hslam;

namespace
{
/** A 12 x 8 m room around the robot at the origin. */
sim::CWorld room()
{
	sim::CWorld w;
	const std::vector<mrpt::math::TPoint2D> c{{-4, -4}, {8, -4}, {8, 4}, {-4, 4}};
	for (size_t i = 0; i < c.size(); ++i) w.addSegment({c[i], c[(i + 1) % c.size()], {sim::EObjectKind::wall, 0, 0}});
	return w;
}

sim::TCameraSimOptions smallCamera()
{
	sim::TCameraSimOptions o;
	o.enabled = true;
	o.intrinsics.width_px = 320;
	o.intrinsics.height_px = 240;
	return o;
}

cv::Mat renderGrey(const sim::CPinholeCameraSimulator& cam, const sim::CWorld& w, const mrpt::math::TPose2D& pose)
{
	std::mt19937_64 rng(3);
	const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(cam.render(w, pose, rng));
	EXPECT_TRUE(obs);
	EXPECT_EQ(obs->image.getWidth(), 320u);
	return vision::greyImageOf(*obs);
}

}  // namespace

TEST(SimCamera, RenderedMotionGivesTheTrueFoe)
{
	const sim::CPinholeCameraSimulator cam(smallCamera());
	const sim::CWorld w = room();
	vision::TVisionOptions o;
	o.foe.noise_floor_px = 0.1;  // 320 x 240
	o.flow.corner_min_distance_px = 5;
	const vision::CAnalyticRotationFlow analytic(cam.camera());
	const vision::CFlowAnalyzer analyzer(cam.camera(), &analytic, o);
	struct TCase
	{
		double dx_m, dyaw_deg;
	};
	for (const TCase c : {TCase{0.10, 0.0}, TCase{0.10, 2.0}, TCase{0.08, -3.0}})
	{
		const mrpt::math::TPose2D p0{0, 0.2, 0.05};
		const mrpt::poses::CPose3D delta(c.dx_m * std::cos(0.5 * c.dyaw_deg * M_PI / 180), c.dx_m * std::sin(0.5 * c.dyaw_deg * M_PI / 180), 0,
										 c.dyaw_deg * M_PI / 180.0, 0, 0);
		const auto p1 = (mrpt::poses::CPose2D(p0) + mrpt::poses::CPose2D(delta)).asTPose();
		const auto a = analyzer.analyze(renderGrey(cam, w, p0), renderGrey(cam, w, p1), delta.yaw());
		ASSERT_TRUE(a.foe.valid) << c.dyaw_deg;
		const cv::Point2d truth = vision::trueFoeOfRobotMotion(cam.camera(), delta);
		std::cout << "rendered pair, yaw " << c.dyaw_deg << " deg: FOE " << a.foe.x_px << ", " << a.foe.y_px
				  << " true " << truth << " (" << a.flow.vectors.size() << " tracks)\n";
		EXPECT_NEAR(a.foe.x_px, truth.x, 4.0);
		// y is weaker: the camera moves horizontally and most vectors run nearly horizontal near the FOE's row.
		EXPECT_NEAR(a.foe.y_px, truth.y, 10.0);
		EXPECT_GT(a.flow.vectors.size(), 100u);
	}
}

TEST(SimCamera, WalkingPeopleAppearAsCylinders)
{
	const sim::CPinholeCameraSimulator cam(smallCamera());
	sim::CWorld w = room();
	const cv::Mat empty = renderGrey(cam, w, {0, 0, 0});
	// Two legs of person 7 at 3 m straight ahead of the camera.
	w.setDynamicCircles({{{3.05, -0.15}, 0.06, {sim::EObjectKind::person_leg, 7, 0}},
						 {{3.25, 0.05}, 0.06, {sim::EObjectKind::person_leg, 7, 1}}});
	const cv::Mat person = renderGrey(cam, w, {0, 0, 0});
	cv::Mat diff;
	cv::absdiff(empty, person, diff);
	// The 0.2 m radius cylinder at ~3 m spans ~2 x 400 x 0.2 / 3 = 53 px; the image centre column changes, the edges do not.
	EXPECT_GT(cv::mean(diff(cv::Rect(150, 60, 20, 120)))[0], 10.0);
	EXPECT_LT(cv::mean(diff(cv::Rect(0, 0, 40, 240)))[0], 2.0);
	EXPECT_LT(cv::mean(diff(cv::Rect(280, 0, 40, 240)))[0], 2.0);
	// The person is 1.75 m tall, the camera at 0.45 m: the top rows above the head (at 3 m: 400 x 1.3 / 3 = 173 px
	// above the centre, beyond the image) ... so the whole column is covered; below, the floor in front is unchanged.
	EXPECT_LT(cv::mean(diff(cv::Rect(150, 230, 20, 10)))[0], 2.0);
}
