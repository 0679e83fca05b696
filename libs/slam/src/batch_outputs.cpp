#include <hslam/common/output_folder.h>
#include <hslam/maps/grid_rendering.h>
#include <hslam/slam/batch_outputs.h>
#include <hslam/slam/loop_closure_outputs.h>
#include <hslam/slam/pose_plots.h>
#include <hslam/slam/vision_outputs.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <algorithm>
#include <cmath>

namespace hslam::slam
{
namespace
{
const mrpt::img::TColor kEstimateColour{220, 20, 20};
const mrpt::img::TColor kOdometryColour{255, 150, 0};
const mrpt::img::TColor kCornerColour{0, 190, 0};

std::vector<mrpt::math::TPose2D> posesOf(const common::TTrajectory2D& trajectory)
{
	std::vector<mrpt::math::TPose2D> poses;
	poses.reserve(trajectory.size());
	for (const auto& p : trajectory) poses.push_back(p.pose);
	return poses;
}

/** Written under a temporary name, then renamed (a full disk never leaves a
 * truncated image under the real name). */
void savePng(const mrpt::img::CImage& image, const std::string& path)
{
	common::writeFileAtomically(path, [&image](const std::string& tmp) {
		if (!image.saveToFile(tmp)) throw std::runtime_error("cannot write image");
	});
}

/** Renders `grid` in the frame of the main map with the trajectories. */
mrpt::img::CImage renderMapWithPaths(const CMappingPipeline& pipeline, const maps::CTiledOccupancyGrid& grid,
									 const maps::TImageFrame& frame, const TOutputOptions& options)
{
	mrpt::img::CImage image = maps::renderGrid(grid, frame);
	if (options.draw_odometry && pipeline.poseEstimatorName() != "odometry")
		maps::drawTrajectory(image, frame, posesOf(pipeline.odometryTrajectory()), kOdometryColour);
	maps::drawTrajectory(image, frame, posesOf(pipeline.finalTrajectory()), kEstimateColour);
	return image;
}

/** Green cross per corner (arm length grows with support) and a circle of
 * two standard deviations (largest eigenvalue of the covariance). */
void drawCorners(mrpt::img::CImage& image, const maps::TImageFrame& frame,
				 const std::vector<sonar::TTbfCorner>& corners)
{
	for (const auto& c : corners)
	{
		double col, row;
		frame.worldToPixel(c.point.x, c.point.y, col, row);
		const int x = static_cast<int>(col), y = static_cast<int>(row);
		const int arm = 3 + std::min(6, c.support / 4);
		image.line(x - arm, y, x + arm, y, kCornerColour, 2);
		image.line(x, y - arm, x, y + arm, kCornerColour, 2);
		const double a = c.cov(0, 0), b = c.cov(0, 1), d = c.cov(1, 1);
		const double maxEig = 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
		const double radiusPx = 2.0 * std::sqrt(std::max(0.0, maxEig)) / frame.resolution_m * frame.pixels_per_cell;
		image.drawCircle(x, y, std::max(2, static_cast<int>(std::lround(radiusPx))), kCornerColour, 1);
	}
}

void writeMaps(const CMappingPipeline& pipeline, const TOutputOptions& options, const std::string& dir,
			   std::vector<std::string>& written)
{
	const maps::TImageFrame frame =
		maps::frameForObservedArea(pipeline.grid(), options.map_margin_cells, options.map_pixels_per_cell);
	mrpt::img::CImage image = renderMapWithPaths(pipeline, pipeline.grid(), frame, options);
	savePng(image, dir + "/map.png");
	written.push_back(dir + "/map.png");
	// Each overlay is drawn on its own copy of map.png's pixels (CImage copies
	// share pixels, hence the deep copy); the last one drawn takes `image`.
	const auto* loops = pipeline.loopClosureStage();
	if (pipeline.sonarStage().reportsCorners())
	{
		mrpt::img::CImage corners = loops ? image.makeDeepCopy() : image;
		drawCorners(corners, frame, pipeline.sonarStage().corners());
		savePng(corners, dir + "/map_sonar_corners.png");
		written.push_back(dir + "/map_sonar_corners.png");
	}
	if (loops)
	{
		drawLoopClosures(image, frame, *loops);
		savePng(image, dir + "/map_loop_closures.png");
		written.push_back(dir + "/map_loop_closures.png");
	}
	// Same frame as map.png so the images overlay.
	for (const auto& [grid, name] : {std::pair{pipeline.laserOnlyMap(), "map_laser_only.png"},
									 std::pair{pipeline.sonarOnlyMap(), "map_sonar_only.png"}})
	{
		if (!grid) continue;
		savePng(renderMapWithPaths(pipeline, *grid, frame, options), dir + "/" + name);
		written.push_back(dir + "/" + name);
	}
}

void writeTiles(const maps::CTiledOccupancyGrid& grid, int pixelsPerCell, const std::string& dir,
				std::vector<std::string>& written)
{
	const std::string tileDir = dir + "/tiles";
	std::filesystem::create_directories(tileDir);
	for (const auto& t : grid.tilesInCreationOrder())
	{
		const std::string path = tileDir + "/tile_" + std::to_string(t.ix) + "_" + std::to_string(t.iy) + ".png";
		savePng(maps::renderGrid(grid, maps::frameForTile(grid, t, pixelsPerCell)), path);
		written.push_back(path);
	}
}

void writeTiming(const common::CStageTimer& timer, const std::string& dir, std::vector<std::string>& written)
{
	common::writeStreamAtomically(dir + "/timing.csv", [&timer](std::ostream& csv) { timer.writeCsv(csv); });
	common::writeStreamAtomically(dir + "/timing.txt", [&timer](std::ostream& txt) { timer.printTable(txt); });
	written.push_back(dir + "/timing.csv");
	written.push_back(dir + "/timing.txt");
}
void writeDynamicObjects(const CMappingPipeline& pipeline, const std::string& dir, std::vector<std::string>& written)
{
	if (!pipeline.dynamicFilter()) return;
	const std::string path = dir + "/tracks.csv";
	common::writeStreamAtomically(path, [&pipeline](std::ostream& csv) { dynamic::writeTracksCsv(csv, pipeline.trackRows()); });
	written.push_back(path);
	if (pipeline.dynamicDebugFrames().empty()) return;
	std::filesystem::create_directories(dir + "/dynamic");
	for (const auto& f : pipeline.dynamicDebugFrames())
	{
		std::ostringstream name;
		name << dir << "/dynamic/scan_" << std::setw(6) << std::setfill('0') << f.scan_index << ".png";
		savePng(dynamic::renderDynamicFrame(f.scan, f.frame), name.str());
		written.push_back(name.str());
	}
}
}  // namespace

void writePoseEstimatesCsv(const std::vector<CMappingPipeline::TTimedEstimate>& estimates, const std::string& path)
{
	common::writeStreamAtomically(path, [&estimates](std::ostream& f) {
	f << "t_s,x_m,y_m,theta_rad,std_x_m,std_y_m,std_theta_rad,matched,match_method,match_quality,match_accepted,"
		 "match_nis,motion_prior\n";
	f.precision(9);
	for (const auto& [t, e] : estimates)
		f << std::fixed << std::setprecision(6) << t << std::defaultfloat << std::setprecision(9) << ','
		  << e.pose.x() << ',' << e.pose.y() << ',' << e.pose.phi() << ','
		  << std::sqrt(std::max(0.0, e.covariance(0, 0))) << ',' << std::sqrt(std::max(0.0, e.covariance(1, 1))) << ','
		  << std::sqrt(std::max(0.0, e.covariance(2, 2))) << ',' << (e.matched ? 1 : 0) << ','
		  << (e.matched ? e.match_method : "") << ',' << (e.matched ? matching::toString(e.match_quality) : "") << ','
		  << (e.match_accepted ? 1 : 0) << ',' << e.match_nis << ',' << e.motion_prior << '\n';
	});
}

void writeSonarCornersCsv(const std::vector<sonar::TTbfCorner>& corners, const std::string& path)
{
	common::writeStreamAtomically(path, [&corners](std::ostream& f) {
	f << "x_m,y_m,support,hypotheses,cov_xx_m2,cov_xy_m2,cov_yy_m2\n";
	f.precision(9);
	for (const auto& c : corners)
		f << c.point.x << ',' << c.point.y << ',' << c.support << ',' << c.hypotheses << ',' << c.cov(0, 0) << ','
		  << c.cov(0, 1) << ',' << c.cov(1, 1) << '\n';
	});
}

void saveGridmapGz(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& path)
{
	common::writeFileAtomically(path, [&grid](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream out;
		if (!out.open(tmp)) throw std::runtime_error("cannot open for writing");
		auto archive = mrpt::serialization::archiveFrom(out);
		archive << grid;
		out.close();
	});
}

std::vector<std::string> writeMappingOutputs(const CMappingPipeline& pipeline, const TOutputOptions& options,
											 const std::string& dir)
{
	std::filesystem::create_directories(dir);
	std::vector<std::string> written;
	writeMaps(pipeline, options, dir, written);
	if (pipeline.sonarStage().reportsCorners())
	{
		writeSonarCornersCsv(pipeline.sonarStage().corners(), dir + "/sonar_corners.csv");
		written.push_back(dir + "/sonar_corners.csv");
	}
	if (options.write_tiles) writeTiles(pipeline.grid(), options.tile_pixels_per_cell, dir, written);

	const auto& grid = pipeline.grid();
	if (!grid.observedBounds().empty())
	{
		saveGridmapGz(maps::toMrptGrid(grid, grid.observedBounds()), dir + "/map.gridmap.gz");
		written.push_back(dir + "/map.gridmap.gz");
	}
	common::writeTumFile(dir + "/trajectory.tum", pipeline.finalTrajectory());
	common::writeTumFile(dir + "/odometry.tum", pipeline.odometryTrajectory());
	written.push_back(dir + "/trajectory.tum");
	written.push_back(dir + "/odometry.tum");
	writeTiming(pipeline.timer(), dir, written);
	writePoseEstimatesCsv(pipeline.estimates(), dir + "/pose_estimates.csv");
	written.push_back(dir + "/pose_estimates.csv");
	savePng(renderPosePlot(pipeline.estimates(), pipeline.odometryTrajectory()), dir + "/pose_plot.png");
	written.push_back(dir + "/pose_plot.png");
	writeDynamicObjects(pipeline, dir, written);
	writeVisionOutputs(pipeline.visionStage(), dir, written);
	writeLoopClosureOutputs(pipeline, dir, written);  // after timing.txt: appends to it
	return written;
}

}  // namespace hslam::slam
