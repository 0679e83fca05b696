#include "bench_common.h"

#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/config/CConfigFileMemory.h>

namespace hslam::bench
{
std::vector<TPosedScan> loadPosedScans(const std::string& rawlogPath)
{
	// Odometry-only pipeline with every scan accepted; only its poses are kept.
	mrpt::config::CConfigFileMemory cfg(std::string("[process]\nlaser_label =\n[pose_estimation]\nmethod = odometry\n"));
	slam::CMappingPipeline pipeline(cfg);
	std::vector<TPosedScan> out;
	pipeline.addScanObserver([&](const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& pose) {
		out.push_back({pose, scan});
	});
	io::CRawlogReader reader(rawlogPath);
	io::TRawlogEntry entry;
	while (reader.next(entry)) pipeline.processEntry(entry);
	return out;
}

}  // namespace hslam::bench
