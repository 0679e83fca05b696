#include <hslam/matching/CKeyframePointMap.h>
#include <hslam/matching/icp_odometry.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/slam/CICP.h>

#include <cmath>

namespace hslam::matching
{
std::vector<mrpt::poses::CPose2D> icpOdometry(const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans)
{
	mrpt::slam::CICP icp;
	icp.options.maxIterations = 200;
	icp.options.thresholdDist = 0.3;
	icp.options.thresholdAng = 2 * M_PI / 180;
	icp.options.ALFA = 0.5;
	icp.options.smallestThresholdDist = 0.02;
	std::vector<mrpt::poses::CPose2D> poses(scans.size());
	mrpt::poses::CPose2D lastDelta;
	CKeyframePointMap::TOptions kfOptions;
	kfOptions.insertion_distance_m = 0.3;
	kfOptions.insertion_angle_rad = 10 * M_PI / 180;
	kfOptions.max_keyframes = 20;
	CKeyframePointMap keyframes(kfOptions);
	for (size_t i = 0; i < scans.size(); ++i)
	{
		mrpt::maps::CSimplePointsMap current;
		current.insertObservation(*scans[i]);
		if (i > 0)
		{
			const mrpt::poses::CPose2D guess = poses[i - 1] + lastDelta;
			const auto pdf = icp.Align(&keyframes.reference(guess), &current, guess);
			poses[i] = pdf->getMeanVal();
			lastDelta = poses[i] - poses[i - 1];
		}
		if (keyframes.empty() || keyframes.wantsKeyframe(poses[i]))
		{
			std::vector<mrpt::math::TPoint2D> points(current.size());
			for (size_t k = 0; k < current.size(); ++k) current.getPoint(k, points[k].x, points[k].y);
			keyframes.addKeyframe(poses[i], points);
		}
	}
	return poses;
}
}  // namespace hslam::matching
