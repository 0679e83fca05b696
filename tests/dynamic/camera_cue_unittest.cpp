/* Camera moving-object cues as motion evidence for leg tracks
 * (CCameraCueBuffer, [dynamic_objects] camera_cue_evidence): the bearing and
 * age rules, and that the keys load from the INI. */
#include <gtest/gtest.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/config_overrides.h>
#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/test_paths.h>

using namespace hslam::dynamic;

namespace
{
constexpr double kDeg = M_PI / 180.0;
}

TEST(CameraCues, BearingRangeWidenedByTheMargin)
{
	TCameraCueOptions o;
	o.enabled = true;
	o.margin_rad = 5 * kDeg;
	o.max_age_s = 0.3;
	CCameraCueBuffer b(o);
	b.add({{10.0, -10 * kDeg, 4 * kDeg}}, 10.0);
	EXPECT_TRUE(b.supports(0.0, 10.0));
	EXPECT_TRUE(b.supports(8.9 * kDeg, 10.1));  // 4 + 5 deg
	EXPECT_FALSE(b.supports(9.1 * kDeg, 10.1));
	EXPECT_TRUE(b.supports(-14.9 * kDeg, 10.0));
	EXPECT_FALSE(b.supports(-15.1 * kDeg, 10.0));
}

TEST(CameraCues, OldCuesExpire)
{
	TCameraCueOptions o;
	o.max_age_s = 0.3;
	CCameraCueBuffer b(o);
	b.add({{10.0, -0.1, 0.1}}, 10.0);
	EXPECT_TRUE(b.supports(0.0, 10.29));
	EXPECT_TRUE(b.supports(0.0, 9.8));  // the image may come just after the scan
	EXPECT_FALSE(b.supports(0.0, 10.31));
	b.add({{10.5, 2.0, 2.2}}, 10.5);  // drops the first
	EXPECT_EQ(b.size(), 1u);
	EXPECT_FALSE(b.supports(0.0, 10.5));
	EXPECT_TRUE(b.supports(2.1, 10.5));
}

TEST(CameraCues, RangeAcrossPi)
{
	CCameraCueBuffer b(TCameraCueOptions{});
	b.add({{0.0, 3.0, 3.3}}, 0.0);  // past +pi: 3.3 rad = -2.98 rad
	EXPECT_TRUE(b.supports(-3.0, 0.0));
	EXPECT_FALSE(b.supports(0.0, 0.0));
}

TEST(CameraCues, KeysLoadFromTheIni)
{
	const auto cfg = hslam::common::parseIniText(
		"[dynamic_objects]\ncamera_cue_evidence = true\ncamera_cue_max_age_s = 0.5\ncamera_cue_margin_deg = 8\n", "t.ini");
	const auto o = hslam::common::loadedOptions<CDynamicObjectFilter::TOptions>(cfg, "dynamic_objects");
	EXPECT_TRUE(o.camera_cues.enabled);
	EXPECT_DOUBLE_EQ(o.camera_cues.max_age_s, 0.5);
	EXPECT_NEAR(o.camera_cues.margin_rad, 8 * kDeg, 1e-12);
	EXPECT_FALSE(CDynamicObjectFilter::TOptions{}.camera_cues.enabled);  // off by default
}

namespace
{
struct TCueRun
{
	size_t legs = 0, cueLegs = 0, cueLegsWithoutEvidence = 0, regions = 0;
};

/** The batch pipeline on the simulated camera sample (two walking people, 5 Hz camera). */
TCueRun runCameraSample(bool cues)
{
	const auto cfg = hslam::common::loadConfigWithOverrides(
		std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini",
		{"vision.noise_floor_px=0.1", "vision.corner_min_distance_px=5", "vision.cue_cluster_distance_px=20",
		 std::string("dynamic_objects.camera_cue_evidence=") + (cues ? "true" : "false")});
	hslam::slam::CMappingPipeline pipeline(cfg);
	TCueRun r;
	pipeline.addScanObserver([&](const mrpt::obs::CObservation2DRangeScan&, const mrpt::poses::CPose2D&) {
		const auto& f = pipeline.dynamicFilter()->lastFrame();
		r.legs += f.legs.size();
		for (const auto& leg : f.legs)
		{
			r.cueLegs += leg.camera_cue;
			r.cueLegsWithoutEvidence += leg.camera_cue && !leg.in_free_space;
		}
	});
	hslam::io::CRawlogReader reader(std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/camera/sim.rawlog");
	for (hslam::io::TRawlogEntry e; reader.next(e);) pipeline.processEntry(e);
	for (const auto& row : pipeline.visionStage().rows()) r.regions += row.regions.size();
	return r;
}
}  // namespace

TEST(CameraCues, BatchPipelineFeedsTheVisionStageCuesToTheLegTracks)
{
	const TCueRun off = runCameraSample(false), on = runCameraSample(true);
	std::cout << "legs " << on.legs << ", covered by a camera cue " << on.cueLegs << ", cue regions " << on.regions
			  << "\n";
	EXPECT_EQ(off.cueLegs, 0u);  // default: no cue evidence at all
	EXPECT_EQ(on.legs, off.legs);  // the cues do not change what the detector sees
	EXPECT_EQ(on.regions, off.regions);
	EXPECT_GT(on.regions, 50u);  // measured 95 over 59 image pairs
	EXPECT_GT(on.cueLegs, 15u);  // measured 34
	EXPECT_EQ(on.cueLegsWithoutEvidence, 0u);  // a cue is motion evidence
}
