/* hslam: the beams scan matching leaves out (see
 * CDynamicObjectFilter::predictedDynamicBeams). */
#include <hslam/dynamic/CDynamicObjectFilter.h>

#include <cmath>

namespace hslam::dynamic
{
std::vector<bool> CDynamicObjectFilter::predictedDynamicBeams(const common::TRangeData& scan,
															  const mrpt::poses::CPose2D& predictedPose, double t_s,
															  double poseMargin_m) const
{
	std::vector<bool> mask(scan.beamCount(), false);
	std::vector<std::pair<mrpt::math::TPoint2D, double>> discs;  // robot-frame centre, radius^2
	const auto addDiscs = [&](const std::vector<TTrack>& tracks, double radiusOf)
	{
		for (const auto& t : tracks)
		{
			if (t.state != ETrackState::dynamic) continue;
			const double dt = std::max(0.0, t_s - t.t_last_s);
			const mrpt::math::TPoint2D world(t.x[0] + t.x[2] * dt, t.x[1] + t.x[3] * dt);
			const double r = (radiusOf > 0 ? radiusOf : maskRadius(t)) + poseMargin_m;
			discs.push_back({predictedPose.inverseComposePoint(world), r * r});
		}
	};
	addDiscs(m_frame.person_tracks, 0.0);
	if (m_options.exclude_legs_from_matching) addDiscs(m_frame.leg_tracks, 0.5 * m_options.pair_max_distance_m);
	if (discs.empty()) return mask;
	for (size_t i = 0; i < scan.points.size(); ++i)
		for (const auto& [c, r2] : discs)
		{
			const auto& p = scan.points.xy[i];
			if ((p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y) > r2) continue;
			mask[scan.points.beam[i]] = true;
			break;
		}
	return mask;
}

}  // namespace hslam::dynamic
