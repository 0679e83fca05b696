/* hslam-navigate: what a navigation run leaves behind, for the simulated and
 * the real robot alike: the rawlog of every observation (observations-only,
 * gz), the live map (MRPT occupancy grid from the laser scans at the pose the
 * controller used), the path samples (CSV: time, pose, commanded and measured
 * speed, controller state), and the path picture (thesis figures 66-68: path
 * coloured by speed with a dot every second so the spacing shows the speed
 * too, obstacles, start, targets). */
#pragma once

#include <hslam/io/CRawlogObservationWriter.h>
#include <hslam/nav/CSubsumptionController.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <string>
#include <vector>

namespace hslam::apps
{
struct TNavLogSample
{
	double t_s = 0;
	mrpt::math::TPose2D pose;
	double v_cmd_mps = 0, w_cmd_rad_s = 0;
	std::string state;
	double nearest_m = 0;
	size_t targets_reached = 0;
	std::string layer;  //!< the layer that set the rotation (nav::navLayerName)
};

class CNavigationLog
{
   public:
	/** Opens `dir`/navigation.rawlog (the folder must exist). */
	explicit CNavigationLog(const std::string& dir);

	void observation(const mrpt::obs::CObservation& obs);
	/** Inserts a laser scan into the live map at `pose`. */
	void mapScan(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose);
	void sample(const TNavLogSample& s) { m_samples.push_back(s); }

	const mrpt::maps::COccupancyGridMap2D& liveMap() const { return m_map; }
	const std::vector<TNavLogSample>& samples() const { return m_samples; }

	/** Closes the rawlog; writes path.csv, live_map.png, live_map.gridmap.gz. */
	void finish();
	/** Path picture over `background` (map or ground-truth grid). */
	mrpt::img::CImage renderPath(const mrpt::maps::COccupancyGridMap2D& background,
								 const std::vector<mrpt::math::TPoint2D>& targets, int maxSidePx = 900) const;

   private:
	std::string m_dir;
	io::CRawlogObservationWriter m_rawlog;
	mrpt::maps::COccupancyGridMap2D m_map;
	std::vector<TNavLogSample> m_samples;
};

}  // namespace hslam::apps
