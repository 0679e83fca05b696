/* hslam: the files a mapping run leaves in its output folder (written by the
 * batch job, libs/batch, and by hslam-grabber --map-out):
 *   map.png             merged map, estimated trajectory (red) and odometry (orange)
 *   tiles/tile_X_Y.png  one image per tile (tile indices relative to the home tile)
 *   map.gridmap.gz      merged mrpt::maps::COccupancyGridMap2D (MRPT tools load it)
 *   trajectory.tum      estimated pose per scan (TUM format; corrected by the
 *                       pose graph with [loop_closure] on, see loop_closure_outputs.h)
 *   odometry.tum        dead-reckoning pose per scan (TUM format)
 *   timing.csv / .txt   per-stage time per scan: mean, p95, max
 *   pose_estimates.csv  per scan: pose, standard deviations, match method/quality/NIS
 *   pose_plot.png       x, y, theta over time with +-1 sigma and odometry (thesis figs 117-127)
 *   frames/frame_N.png  on request (debug_frames_every): scan with its line segments (figs 88, 95)
 *   tracks.csv          leg and person tracks per scan (dynamic object filter on)
 *   dynamic/scan_N.png  per-scan debug images of the filter (dynamic_debug_images)
 *   sonar_corners.csv   TBF sonar corners (x, y, support, covariance) ([tbf] enabled)
 *   map_sonar_corners.png  map.png with the TBF corners (green crosses, 2-sigma circles)
 *   map_laser_only.png, map_sonar_only.png  the grid of each sensor alone (write_sensor_maps)
 * The last four only when the log holds sonar readings: for a laser-only log
 * they would be an empty picture and copies of map.png. */
#pragma once

#include <hslam/slam/CMappingPipeline.h>

#include <string>
#include <vector>

namespace hslam::slam
{
struct TOutputOptions
{
	int map_pixels_per_cell = 2;  //!< scale of map.png
	int map_margin_cells = 20;  //!< unknown border around the observed area in map.png
	bool write_tiles = true;  //!< write tiles/tile_X_Y.png
	int tile_pixels_per_cell = 1;  //!< scale of the tile images
	bool draw_odometry = true;  //!< also draw the dead-reckoning path on map.png
	int debug_frames_every = 0;  //!< write frames/frame_N.png for every N-th scan; 0 = none
	bool dynamic_debug_images = false;  //!< write dynamic/scan_N.png (thesis figures 156-165)
	int dynamic_debug_max_images = 200;  //!< first scans with legs that get an image
	bool write_sensor_maps = true;  //!< write map_laser_only.png and map_sonar_only.png

	template <class V>
	void visit(V& v)
	{
		v.integer("map_pixels_per_cell", map_pixels_per_cell, 1, 16);
		v.integer("map_margin_cells", map_margin_cells, 0, 1000);
		v.flag("write_tiles", write_tiles);
		v.integer("tile_pixels_per_cell", tile_pixels_per_cell, 1, 16);
		v.flag("draw_odometry", draw_odometry);
		v.integer("debug_frames_every", debug_frames_every, 0, 1000000);
		v.flag("dynamic_debug_images", dynamic_debug_images);
		v.integer("dynamic_debug_max_images", dynamic_debug_max_images, 1, 1000000);
		v.flag("write_sensor_maps", write_sensor_maps);
	}
};

/** Writes all outputs into `dir` (created if needed); returns the paths
 * written. Throws std::runtime_error naming the file on a write failure. */
std::vector<std::string> writeMappingOutputs(const CMappingPipeline& pipeline, const TOutputOptions& options,
											 const std::string& dir);

/** Writes pose_estimates.csv: one row per scan. */
void writePoseEstimatesCsv(const std::vector<CMappingPipeline::TTimedEstimate>& estimates, const std::string& path);

/** Writes sonar_corners.csv: one row per TBF corner, positions in the map frame. */
void writeSonarCornersCsv(const std::vector<sonar::TTbfCorner>& corners, const std::string& path);

/** Saves a grid as a gz-compressed serialized COccupancyGridMap2D (.gridmap.gz). */
void saveGridmapGz(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path);

}  // namespace hslam::slam
