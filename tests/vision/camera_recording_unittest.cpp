/* Recording a camera without a camera (issue 16, part 4): the [CAMERA]
 * section of config_ini/grabber-pioneer-lms-camera.ini loads into MRPT's
 * CCameraSensor, and the same sensor with a video-file source (grabber_type
 * = ffmpeg, a video written here with cv::VideoWriter) replays the frames
 * into a rawlog that our reader and vision code read back. */
#include <gtest/gtest.h>
#include <hslam/io/CRawlogObservationWriter.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <hslam/vision/observation_image.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/hwdrivers/CCameraSensor.h>
#include <mrpt/obs/CObservationImage.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <fstream>
#include <sstream>

using namespace hslam::vision;

namespace
{
const std::string kIni = std::string(HSLAM_SOURCE_DIR) + "/config_ini/grabber-pioneer-lms-camera.ini";

/** Frame k: a moving bright square on a dark background, with a frame number bar. */
cv::Mat syntheticFrame(int k)
{
	cv::Mat bgr(240, 320, CV_8UC3, cv::Scalar(30, 30, 30));
	cv::rectangle(bgr, cv::Rect(40 + 20 * k, 80, 60, 60), cv::Scalar(230, 230, 230), cv::FILLED);
	return bgr;
}

std::string readFile(const std::string& path)
{
	std::ifstream f(path);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}
}  // namespace

TEST(VisionRecording, GrabberIniCameraSectionLoadsIntoCCameraSensor)
{
	mrpt::config::CConfigFile cfg(kIni);
	ASSERT_TRUE(cfg.sectionExists("CAMERA"));
	EXPECT_EQ(cfg.read_string("CAMERA", "driver", ""), "CCameraSensor");
	mrpt::hwdrivers::CCameraSensor camera;
	EXPECT_NO_THROW(camera.loadConfig(cfg, "CAMERA"));
}

TEST(VisionRecording, VideoFileSourceReplaysFramesIntoARawlog)
{
	hslam::testing::CTempDir dir;
	const std::string video = dir.file("clip.avi"), rawlog = dir.file("camera.rawlog");
	{
		cv::VideoWriter writer(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 10.0, cv::Size(320, 240));
		ASSERT_TRUE(writer.isOpened()) << video;
		for (int k = 0; k < 8; ++k) writer.write(syntheticFrame(k));
	}
	// The grabber INI's [CAMERA] section with its source switched to the video file.
	mrpt::config::CConfigFileMemory cfg(readFile(kIni));
	cfg.write("CAMERA", "grabber_type", "ffmpeg");
	cfg.write("CAMERA", "ffmpeg_url", video);
	mrpt::hwdrivers::CCameraSensor camera;
	camera.loadConfig(cfg, "CAMERA");
	camera.initialize();
	size_t written = 0;
	{
		hslam::io::CRawlogObservationWriter out(rawlog);
		for (int k = 0; k < 8; ++k)  // one read per frame of the video
			if (auto obs = camera.getNextFrame())
			{
				out.write(*obs);
				++written;
			}
		out.close();
	}
	EXPECT_EQ(written, 8u);
	hslam::io::CRawlogReader reader(rawlog);
	hslam::io::TRawlogEntry e;
	std::vector<cv::Mat> frames;
	mrpt::poses::CPose3D cameraPose;
	while (reader.next(e))
		if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(e.observation))
		{
			EXPECT_EQ(img->sensorLabel, "CAMERA");
			frames.push_back(greyImageOf(*img));
			cameraPose = img->cameraPose;
		}
	ASSERT_EQ(frames.size(), 8u);
	for (int k = 0; k < 8; ++k)  // the replayed frames are the written ones (up to JPEG loss)
	{
		cv::Mat expected;
		cv::cvtColor(syntheticFrame(k), expected, cv::COLOR_BGR2GRAY);
		EXPECT_LT(cv::norm(frames[static_cast<size_t>(k)], expected, cv::NORM_L1) / expected.total(), 4.0) << k;
	}
	// The INI's pose is the camera frame convention (z forward): the optical axis along the robot's x.
	const mrpt::poses::CPose3D expectedPose = forwardCameraPose(0.15, 0.0, 0.45);
	EXPECT_LT((cameraPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>() -
			   expectedPose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>())
				  .array()
				  .abs()
				  .maxCoeff(),
			  1e-6);
}
