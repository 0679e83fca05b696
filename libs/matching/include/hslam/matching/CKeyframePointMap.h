/* hslam: the reference for scan-to-map ICP: the points of recent keyframes
 * (scans kept every insertion_distance_m / insertion_angle_rad of travel, as
 * MRPT's icp-slam does) in the world frame. Matching against several
 * keyframes instead of only the previous scan stops the random-walk drift of
 * pure frame-to-frame matching; keeping only a bounded window (the most recent
 * keyframes and those within radius_m) keeps old, possibly misaligned parts
 * of the map from pulling the match after a long loop.
 *
 * With voxel_size_m > 0 the points of the window are merged per cell
 * (centroid), so that a wall's weight in the match does not grow with the
 * number of keyframes that saw it, and the reference (rebuilt, with its k-d
 * tree, whenever a keyframe is added) stays a few times smaller. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <vector>

namespace hslam::matching
{
class CKeyframePointMap
{
   public:
	struct TOptions
	{
		double insertion_distance_m = 0.5;  //!< new keyframe after this much travel...
		double insertion_angle_rad = 15.0 * M_PI / 180.0;  //!< ...or this much rotation
		int max_keyframes = 40;  //!< keyframes kept (oldest dropped); 0 = unlimited
		double radius_m = 0;  //!< also drop keyframes further than this from the robot; 0 = no limit
		double min_point_spacing_m = 0.03;  //!< points closer than this to the previous one are skipped
		/** Reference points of all keyframes merged per square cell of this
		 * size (centroid of the cell's points); 0 = every keyframe point. */
		double voxel_size_m = 0;
		/** referenceIndex(): keyframes added since the last full rebuild of
		 * the index before it is rebuilt from the window (until then the
		 * points of keyframes that left are skipped by the queries; exact
		 * either way). */
		int index_rebuild_keyframes = 8;

		template <class V>
		void visit(V& v)
		{
			v.real("insertion_distance_m", insertion_distance_m, 0.0, 100.0);
			v.degrees("insertion_angle_deg", insertion_angle_rad, 0.0, 360.0);
			v.integer("max_keyframes", max_keyframes, 0, 100000);
			v.real("radius_m", radius_m, 0.0, 10000.0);
			v.real("min_point_spacing_m", min_point_spacing_m, 0.0, 1.0);
			v.real("voxel_size_m", voxel_size_m, 0.0, 1.0);
			v.integer("index_rebuild_keyframes", index_rebuild_keyframes, 1, 1000);
		}
	};

	CKeyframePointMap() : CKeyframePointMap(TOptions()) {}
	explicit CKeyframePointMap(const TOptions& options) : m_options(options) {}

	const TOptions& options() const { return m_options; }
	bool empty() const { return m_keyframes.empty(); }
	size_t keyframeCount() const { return m_keyframes.size(); }

	/** True if a scan taken at `pose` should become a keyframe: it lies
	 * `spacing` x the insertion distance or angle from the newest one. */
	bool wantsKeyframe(const mrpt::poses::CPose2D& pose, double spacing = 1.0) const;
	/** Adds a keyframe: `points` in the robot frame at world pose `pose`. */
	void addKeyframe(const mrpt::poses::CPose2D& pose, const std::vector<mrpt::math::TPoint2D>& points);

	/** World-frame points of the keyframes in the window around `robotPose`
	 * (rebuilt only when the window changes). */
	const mrpt::maps::CSimplePointsMap& reference(const mrpt::poses::CPose2D& robotPose);
	/** The same points in a CPointIndex2D (for CPointToPointIcp). */
	const CPointIndex2D& referenceIndex(const mrpt::poses::CPose2D& robotPose);

   private:
	/** Updates the window of keyframes around robotPose; true if it changed. */
	bool updateWindow(const mrpt::poses::CPose2D& robotPose);
	/** World points of the window (merged per voxel if voxel_size_m > 0). */
	void windowPoints(std::vector<float>& xs, std::vector<float>& ys) const;
	void mergedWindowPoints(std::vector<float>& xs, std::vector<float>& ys) const;
	/** Brings m_index to the window by retiring and appending keyframes;
	 * false if it needs a full rebuild instead. */
	bool updateIndexIncrementally();
	void rebuildIndex();

	struct TKeyframe
	{
		mrpt::poses::CPose2D pose;
		std::vector<mrpt::math::TPoint2D> worldPoints;
	};
	TOptions m_options;
	std::deque<TKeyframe> m_keyframes;
	std::vector<size_t> m_windowIds;  //!< ids of the keyframes in m_reference
	size_t m_nextId = 0, m_firstId = 0;  //!< id of m_keyframes.front()
	mrpt::maps::CSimplePointsMap m_reference;
	CPointIndex2D m_index;
	size_t m_indexFirstId = 0, m_indexEndId = 0;  //!< keyframe ids in m_index: [first, end)
	size_t m_indexBulkKeyframes = 0;  //!< of which the first ones are in the bulk part
	std::deque<size_t> m_indexPointCounts;  //!< points of each keyframe in m_index, oldest first
	bool m_referenceStale = true, m_indexStale = true;
};

}  // namespace hslam::matching
