/* hslam: the keyframe store of the front-end (thesis figure 55: "keyframe
 * store -> pose graph"). A keyframe is a scan kept every
 * insertion_distance_m / insertion_angle_rad of travel, as MRPT's icp-slam
 * does: its pose in the world, the covariance of that pose, and its points
 * with surface normals in the robot frame (decimated to one point per
 * min_point_spacing_m). The scan-to-map matcher builds its local map from the
 * keyframes near the robot (window()); the back-end (loop closure) reads the
 * same keyframes as graph nodes and writes corrected poses back (setPose),
 * so matching continues against the corrected map.
 *
 * Normals: total-least-squares fit (PCA) of the neighbours in beam order
 * within normal_radius_m; a point whose neighbourhood is not line-like (the
 * smaller eigenvalue above a quarter of the larger: a corner, clutter) has no
 * normal and is not used for point-to-line matching. */
#pragma once

#include <hslam/common/range_data.h>

#include <Eigen/Core>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace hslam::matching
{
/** Line-like points with unit normals, robot frame (one normal per point). */
struct TOrientedPoints
{
	std::vector<Eigen::Vector2d> points, normals;
	size_t size() const { return points.size(); }
};

struct TKeyframe
{
	size_t id = 0;  //!< 0, 1, 2, ... in insertion order
	double t_s = 0;  //!< time stamp of its scan (s)
	mrpt::poses::CPose2D pose;  //!< robot pose in the world (corrected by the back-end)
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  //!< of the pose when it was added
	TOrientedPoints scan;  //!< robot frame (m), line-like points only, with normals
};

class CKeyframeStore
{
   public:
	struct TOptions
	{
		double insertion_distance_m = 0.5;  //!< new keyframe after this much travel...
		double insertion_angle_rad = 15.0 * M_PI / 180.0;  //!< ...or this much rotation
		double min_point_spacing_m = 0.05;  //!< points closer than this to the previous kept one are dropped
		double normal_radius_m = 0.25;  //!< neighbours (in beam order) within this distance fit the normal
		double max_range_m = 30.0;  //!< returns beyond this are not kept (scan matching range)
		int window_keyframes = 40;  //!< local map: the most recent keyframes...
		double window_radius_m = 0;  //!< ...plus older ones within this distance of the robot (0 = none: drifted old keyframes would pull the match; with loop closure they are corrected)
		int window_max_keyframes = 60;  //!< cap of the local map

		template <class V>
		void visit(V& v)
		{
			v.real("insertion_distance_m", insertion_distance_m, 0.0, 100.0);
			v.degrees("insertion_angle_deg", insertion_angle_rad, 0.0, 360.0);
			v.real("min_point_spacing_m", min_point_spacing_m, 0.0, 1.0);
			v.real("normal_radius_m", normal_radius_m, 0.02, 2.0);
			v.real("max_range_m", max_range_m, 0.5, 200.0);
			v.integer("window_keyframes", window_keyframes, 1, 100000);
			v.real("window_radius_m", window_radius_m, 0.0, 1000.0);
			v.integer("window_max_keyframes", window_max_keyframes, 1, 100000);
		}
	};

	CKeyframeStore() : CKeyframeStore(TOptions()) {}
	explicit CKeyframeStore(const TOptions& options) : m_options(options) {}

	const TOptions& options() const { return m_options; }
	bool empty() const { return m_keyframes.empty(); }
	size_t size() const { return m_keyframes.size(); }
	const TKeyframe& keyframe(size_t id) const { return m_keyframes.at(id); }
	const TKeyframe& latest() const { return m_keyframes.back(); }

	/** True if a scan taken at `pose` should become a keyframe. */
	bool wantsKeyframe(const mrpt::poses::CPose2D& pose) const;
	/** Adds the scan's returns (up to max_range_m) as a keyframe; returns its id. */
	size_t add(const common::TScanPoints& points, const mrpt::poses::CPose2D& pose, const Eigen::Matrix3d& covariance,
			   double t_s);
	/** The back-end moved a keyframe (loop closure). */
	void setPose(size_t id, const mrpt::poses::CPose2D& pose);
	/** Counts pose corrections: the local map is rebuilt when it changes. */
	size_t revision() const { return m_revision; }

	/** Ids of the keyframes of the local map around `robotPose` (ascending). */
	std::vector<size_t> window(const mrpt::poses::CPose2D& robotPose) const;

   private:
	TOptions m_options;
	std::deque<TKeyframe> m_keyframes;  // all of them: the back-end's nodes (memory: ~3 kB each)
	size_t m_revision = 0;
};

/** Line-like points of a scan with their normals (robot frame), decimated;
 * beams flagged in `excludedBeams` (people) are left out. See the file comment. */
TOrientedPoints pointsWithNormals(const common::TScanPoints& points, const CKeyframeStore::TOptions& options,
								  const std::vector<bool>* excludedBeams = nullptr);

}  // namespace hslam::matching
