/* The simulator's pinhole camera (libs/sim CPinholeCameraSimulator) seen by
 * the vision code: frames rendered from known robot poses give the FOE the
 * camera's true motion predicts, and walking people appear as cylinders. */
#include <gtest/gtest.h>
#include <hslam/sim/CPinholeCameraSimulator.h>
#include <hslam/sim/scene.h>
#include <hslam/testing/test_paths.h>
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
		EXPECT_NEAR(a.foe.x_px, truth.x, 2.5);
		// y is weaker: the camera moves horizontally and most vectors run nearly horizontal near the FOE's row.
		EXPECT_NEAR(a.foe.y_px, truth.y, 10.0);
		EXPECT_GT(a.flow.vectors.size(), 100u);
	}
}

namespace
{
/** Tracked flow against the true flow of the same corner (its surface point from the first pose, projected from
 * the second), and the FOE error, over pure-translation pairs of the lab (as hslam-bench vision's simulator rows). */
struct TRenderedTranslation
{
	std::vector<double> track_error_px, foe_error_px;
};

TRenderedTranslation renderedTranslationPairs(const vision::TVisionOptions& o, int pairs)
{
	const sim::CPinholeCameraSimulator cam(smallCamera());
	const sim::CWorld world = sim::loadSceneFile(std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-worlds/lab.scene").world;
	const vision::CAnalyticRotationFlow analytic(cam.camera());
	const vision::CFlowAnalyzer analyzer(cam.camera(), &analytic, o);
	const cv::Matx33d K = vision::cameraMatrix(cam.camera().intrinsics);
	cv::RNG rng(7);
	TRenderedTranslation out;
	for (int k = 0; k < pairs; ++k)
	{
		const mrpt::poses::CPose2D p0(rng.uniform(1.0, 3.5), rng.uniform(1.5, 5.0), rng.uniform(-20.0, 20.0) * M_PI / 180);
		const mrpt::poses::CPose3D delta(rng.uniform(0.05, 0.10), 0, 0, 0, 0, 0);
		const mrpt::poses::CPose2D p1 = p0 + mrpt::poses::CPose2D(delta);
		const auto a = analyzer.analyze(renderGrey(cam, world, p0.asTPose()), renderGrey(cam, world, p1.asTPose()), 0.0);
		const cv::Point2d truth = vision::trueFoeOfRobotMotion(cam.camera(), delta);
		out.foe_error_px.push_back(a.foe.valid ? std::hypot(a.foe.x_px - truth.x, a.foe.y_px - truth.y) : 1e9);
		const mrpt::poses::CPose3D c0 = mrpt::poses::CPose3D(p0) + cam.camera().sensorPose;
		const mrpt::poses::CPose3D c1 = mrpt::poses::CPose3D(p1) + cam.camera().sensorPose;
		for (const auto& f : a.flow.vectors)
		{
			const auto X = cam.surfacePoint(world, p0.asTPose(), f.p0.x, f.p0.y);
			if (!X) continue;
			mrpt::math::TPoint3D w, X1;
			c0.composePoint(*X, w);
			c1.inverseComposePoint(w, X1);
			const cv::Point2d t1(K(0, 0) * X1.x / X1.z + K(0, 2), K(1, 1) * X1.y / X1.z + K(1, 2));
			out.track_error_px.push_back(std::hypot(t1.x - f.p1.x, t1.y - f.p1.y));
		}
	}
	return out;
}
}  // namespace

TEST(SimCamera, SurfacePointIsWhatThePixelSees)
{
	const sim::CPinholeCameraSimulator cam(smallCamera());
	// The room's east wall is 8 m ahead of the camera (0.15 m ahead of the robot at the origin): depth 7.85 m at the
	// image centre; the bottom row sees the floor (0.45 m below the camera) at 400 x 0.45 / 119.5 = 1.51 m.
	const auto centre = cam.surfacePoint(room(), {0, 0, 0}, 160, 120);
	ASSERT_TRUE(centre);
	EXPECT_NEAR(centre->z, 7.85, 1e-6);
	EXPECT_NEAR(centre->x, 0.0, 1e-9);
	const auto floor = cam.surfacePoint(room(), {0, 0, 0}, 160, 239.5);
	ASSERT_TRUE(floor);
	EXPECT_NEAR(floor->z, 400 * 0.45 / 119.5, 1e-6);
	EXPECT_NEAR(floor->y, 0.45, 1e-6);
}

TEST(SimCamera, RenderedPureTranslationTracksAndFoeMeetTheIssueTarget)
{
	// Issue #16: FOE error <= 2 px (median) for pure translation. Rendered frames of the lab, 320 x 240, forward
	// 5-10 cm (walls 3-8 m away: 1-4 px of flow). The FOE error of one line is about (track error across the flow)
	// x depth / travel, so tracks must be good to a few hundredths of a pixel. With a regular 2 x 2 sample grid per
	// pixel the renderer moved texture edges in 0.5 px steps: tracks were off by 0.15 px (median) and the FOE by
	// 5.8 px; unweighted least squares (every line counting the same at the FOE) added the rest.
	vision::TVisionOptions o;
	o.foe.noise_floor_px = 0.1;  // 320 x 240
	o.flow.corner_min_distance_px = 5;
	o.flow.max_corners = 500;
	const auto r = renderedTranslationPairs(o, 10);
	const double track = vision::medianOf(r.track_error_px), foe = vision::medianOf(r.foe_error_px);
	std::cout << "rendered pure translation, 320 x 240: track error median " << track << " px over "
			  << r.track_error_px.size() << " tracks, FOE error median " << foe << " px over "
			  << r.foe_error_px.size() << " pairs\n";
	EXPECT_LT(track, 0.09);
	EXPECT_LE(foe, 2.0);
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
