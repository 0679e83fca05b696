/* hslam: what the dynamic object filter leaves for people to look at:
 *  - track rows (one per live track per scan) for a tracks CSV: id, kind
 *    (leg/person), state, position in the robot and world frames, world
 *    velocity and the thesis' polar velocities (4.7.2, H.1 obj[5], obj[6]);
 *  - per-scan debug images in the style of thesis figures 156-165: the scan
 *    in the robot frame (forward up), leg segments with their end points,
 *    beams flagged dynamic, track ids and velocity arrows.
 * No file I/O: callers write the CSV stream and save the images. */
#pragma once

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <mrpt/img/CImage.h>

#include <ostream>
#include <vector>

namespace hslam::dynamic
{
struct TTrackRow
{
	double t_s = 0;
	size_t scan = 0;
	const char* kind = "leg";  //!< "leg" or "person"
	TTrack track;
	double x_robot_m = 0, y_robot_m = 0;
	bool seen = false;  //!< associated with an observation in this scan
};

/** Appends one row per live leg and person track of `frame`. */
void appendTrackRows(const TDynamicFrame& frame, size_t scanIndex, std::vector<TTrackRow>& rows);

/** CSV with a header line: t_s,scan,kind,id,state,seen,x_robot_m,...,v_angular_radps */
void writeTracksCsv(std::ostream& out, const std::vector<TTrackRow>& rows);

struct TDynamicImageOptions
{
	int size_px = 600;
	double half_width_m = 4.0;  //!< the image covers +-half_width_m around the robot
};

/** Debug image of one scan and the filter state after it. */
mrpt::img::CImage renderDynamicFrame(const mrpt::obs::CObservation2DRangeScan& scan, const TDynamicFrame& frame,
									 const TDynamicImageOptions& options = {});

}  // namespace hslam::dynamic
