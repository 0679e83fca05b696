/* The default front-end on intel (910 scans) converted by our CARMEN
 * importer, its corrected poses as the reference: a scan whose line match
 * fails is matched by ICP even before ICP is due. */
#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/scan_consistency.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <cmath>

using namespace hslam;

TEST(IntelLog, AScanWhoseLinesFailIsMatchedByIcp)
{
	// t = 2414.98 s: odometry claims no turn over 0.27 m since the last ICP
	// (not due: 0.5 m / 10 deg), the line match fails, and the robot has
	// turned 8 deg (reference). Left to odometry, that scan misfitted the
	// one before by 0.150 m (reference 0.041 m) until the next ICP 6 s later.
	hslam::testing::CTempDir dir;
	slam::testing::convertCarmenReferenceLog("intel", dir.path().string());
	const auto cfg = common::loadConfigWithOverrides(slam::testing::kDefaultIni, {"loop_closure.enabled=false"});
	slam::CMappingPipeline pipeline(cfg);
	io::CRawlogReader reader(dir.file("intel.rawlog"));
	for (io::TRawlogEntry e; reader.next(e);) pipeline.processEntry(e);

	size_t linesOnlyFailed = 0;
	for (const auto& [t, e] : pipeline.estimates())
		if (e.matched && e.match_method == "lines" && e.match_quality == matching::EMatchQuality::failed)
			++linesOnlyFailed;
	EXPECT_EQ(linesOnlyFailed, 0u);  // 1 before: t = 2414.98 s

	const auto scans = eval::readScanPoints(dir.file("intel.rawlog"), "", 20.0);
	const auto c = eval::compareScanConsistency(scans, common::readTumFile(dir.file("intel.tum")),
												pipeline.trajectory(), {});
	const eval::TScanPairMisfit* turned = nullptr;
	for (const auto& p : c.pairs)
		if (std::abs(p.t_s - 2414.98) < 0.01) turned = &p;
	ASSERT_NE(turned, nullptr);
	EXPECT_NEAR(turned->reference_m, 0.041, 0.002);
	EXPECT_LT(turned->estimate_m, 0.08);  // measured 0.150 before
}
