/* Tracking (forward-backward check, noise floor at rest), camera geometry and
 * moving-object cues on exact pairs. */
#include <gtest/gtest.h>
#include <hslam/vision/moving_cues.h>
#include <opencv2/imgproc.hpp>

#include "vision_test_helpers.h"

using namespace hslam::vision;
using hslam::vision::testing::thesisCamera;

TEST(VisionFlow, NoiseFloorAtRestIsWellBelowTheThesisThreshold)
{
	TPlanePairSpec s;
	s.K = cameraMatrix(thesisCamera().intrinsics);
	s.t = {0, 0, -1e-9};  // at rest; only the pixel noise differs
	const TPlanePair pair = makePlanePair(s);
	const TFlowResult r = trackFeatures(pair.first, pair.second, TFlowOptions{});
	ASSERT_GT(r.vectors.size(), 200u);
	std::vector<cv::Point2f> flow;
	for (const auto& v : r.vectors) flow.push_back(v.flow());
	const double rms = flowMagnitudeRms(flow);
	std::cout << "flow at rest: " << rms << " px RMS (thesis: 0.2 px)\n";
	EXPECT_LT(rms, 0.2);
}

TEST(VisionFlow, ForwardBackwardCheckDropsTracksOfAChangedRegion)
{
	TPlanePairSpec s;
	s.K = cameraMatrix(thesisCamera().intrinsics);
	TPlanePair pair = makePlanePair(s);
	cv::RNG rng(5);  // the right third of the second image replaced by unrelated texture
	cv::Mat junk(pair.second.rows, pair.second.cols / 3, CV_8UC1);
	rng.fill(junk, cv::RNG::UNIFORM, 0, 255);
	cv::GaussianBlur(junk, junk, cv::Size(0, 0), 1.5);
	junk.copyTo(pair.second(cv::Rect(pair.second.cols - junk.cols, 0, junk.cols, junk.rows)));
	TFlowOptions withCheck, without;
	without.fb_max_error_px = 0;
	const TFlowResult a = trackFeatures(pair.first, pair.second, withCheck);
	const TFlowResult b = trackFeatures(pair.first, pair.second, without);
	EXPECT_GT(a.fb_rejected, 30u);
	EXPECT_EQ(b.fb_rejected, 0u);
	size_t wrongKept = 0;  // tracks kept in the replaced region
	for (const auto& v : a.vectors) wrongKept += v.p0.x > pair.second.cols - junk.cols + 15;
	EXPECT_LT(wrongKept, a.fb_rejected / 5);
	EXPECT_THROW(trackFeatures(pair.first, cv::Mat(10, 10, CV_8UC1), withCheck), std::invalid_argument);
}

TEST(VisionGeometry, ForwardCameraLooksAlongTheRobotAxis)
{
	const TMountedCamera cam = thesisCamera();
	EXPECT_NEAR(robotBearingOfPixel(cam, 320, 240), 0.0, 1e-9);
	EXPECT_NEAR(robotBearingOfPixel(cam, 0, 240), std::atan(320.0 / 800.0), 1e-9);  // left of the image = left (CCW)
	TMountedCamera panned = cam;
	panned.sensorPose = forwardCameraPose(0.1, 0, 0.4, 0.3, 0.2);
	EXPECT_NEAR(robotBearingOfPixel(panned, 320, 240), 0.3, 1e-9);
}

TEST(VisionCues, AMovingPatchIsFoundAtItsBearing)
{
	const TMountedCamera cam = thesisCamera();
	const CAnalyticRotationFlow analytic(cam);
	const TPlanePairSpec spec = scenarioPair(cam, EPlaneMotion::translation_rotation, 3, 51);
	TPlanePair pair = makePlanePair(spec);
	// A textured object moving 12 px down in the image (off the FOE's radial lines): pasted into both images, shifted in the second.
	cv::RNG rng(9);
	cv::Mat blocks(22, 15, CV_8UC1), patch;  // 4 x 4 px blocks (resized from a separate Mat: in place gave a flat patch)
	rng.fill(blocks, cv::RNG::UNIFORM, 0, 255);
	cv::resize(blocks, patch, cv::Size(60, 90), 0, 0, cv::INTER_NEAREST);
	patch.copyTo(pair.first(cv::Rect(450, 200, 60, 90)));
	patch.copyTo(pair.second(cv::Rect(450, 212, 60, 90)));
	const CFlowAnalyzer analyzer(cam, &analytic, TVisionOptions{});
	const TFrameAnalysis a = analyzer.analyze(pair.first, pair.second, spec.robot_yaw_rad);
	ASSERT_TRUE(a.foe.valid);
	ASSERT_FALSE(a.regions.empty());
	const TMovingRegion& r = a.regions.front();
	EXPECT_GE(r.vectors, 3u);
	EXPECT_TRUE(cv::Rect2f(440, 200, 85, 115).contains(r.centre)) << r.centre;
	EXPECT_NEAR(r.bearing_rad, robotBearingOfPixel(cam, 480, 257), 0.03);
	EXPECT_LT(r.bearing_rad, 0.0);  // right of the image centre = to the robot's right
	// The static plane gives no large region.
	for (size_t i = 1; i < a.regions.size(); ++i) EXPECT_LT(a.regions[i].vectors, r.vectors);
}
