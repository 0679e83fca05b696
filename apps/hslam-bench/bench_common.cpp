#include "bench_common.h"

#include <hslam/common/tum_trajectory.h>
#include <hslam/benchdata/reference_grid.h>
#include <hslam/maps/grid_rendering.h>
#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace hslam::bench
{
/** A short name: the folder for <dir>/sim.rawlog, else the file stem. */
std::string rawlogName(const std::string& path)
{
	const std::filesystem::path p(path);
	std::string name = p.stem() == "sim" ? p.parent_path().filename().string() : p.stem().string();
	std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)) && c != '-'; }, '_');
	return name.substr(0, 40);
}

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

maps::CLaserGridInserter::TOptions ourLaserOptions()
{
	maps::CLaserGridInserter::TOptions o;
	o.max_range_m = kRangeLimit_m;
	o.insert_free_beyond_range = true;
	return o;
}

void insertOurs(maps::CTiledOccupancyGrid& grid, const std::vector<TPosedScan>& scans)
{
	maps::CLaserGridInserter inserter(ourLaserOptions());
	for (const auto& s : scans) inserter.insert(grid, s.pose, s.scan);
}

mrpt::maps::COccupancyGridMap2D makeMrptGrid(const maps::CTiledOccupancyGrid& sizedLike)
{
	const maps::TCellBounds b = sizedLike.observedBounds();
	const double res = sizedLike.geometry().resolution_m();
	mrpt::maps::COccupancyGridMap2D grid(static_cast<float>((b.gxMin - 5) * res), static_cast<float>((b.gxMax + 6) * res),
										 static_cast<float>((b.gyMin - 5) * res), static_cast<float>((b.gyMax + 6) * res),
										 static_cast<float>(res));
	grid.insertionOptions.maxDistanceInsertion = static_cast<float>(kRangeLimit_m);
	grid.insertionOptions.considerInvalidRangesAsFreeSpace = false;
	grid.insertionOptions.maxOccupancyUpdateCertainty = 0.9f;
	grid.insertionOptions.maxFreenessUpdateCertainty = 0.7f;
	return grid;
}

void insertMrpt(mrpt::maps::COccupancyGridMap2D& grid, const std::vector<TPosedScan>& scans)
{
	for (const auto& s : scans) grid.insertObservation(s.scan, mrpt::poses::CPose3D(s.pose));
}

size_t mrptGridBytes(const mrpt::maps::COccupancyGridMap2D& grid)
{
	return static_cast<size_t>(grid.getSizeX()) * grid.getSizeY() * sizeof(mrpt::maps::COccupancyGridMap2D::cellType);
}

void saveExclusionComparison(const maps::CTiledOccupancyGrid& without, const maps::CTiledOccupancyGrid& with,
							 int pixelsPerCell, const std::string& pngPath)
{
	const auto frame = maps::frameForObservedArea(without, 5, pixelsPerCell);
	const auto a = maps::renderGrid(without, frame), b = maps::renderGrid(with, frame);
	mrpt::img::CImage both(a.getWidth() * 2 + 10, a.getHeight(), mrpt::img::CH_RGB);
	both.filledRectangle(0, 0, static_cast<int>(both.getWidth()) - 1, static_cast<int>(both.getHeight()) - 1,
						 mrpt::img::TColor(255, 255, 255));
	both.drawImage(0, 0, a);
	both.drawImage(static_cast<int>(a.getWidth()) + 10, 0, b);
	both.textOut(5, 5, "without exclusion", mrpt::img::TColor(200, 0, 0));
	both.textOut(static_cast<int>(a.getWidth()) + 15, 5, "with exclusion", mrpt::img::TColor(0, 130, 0));
	if (!both.saveToFile(pngPath)) throw std::runtime_error(pngPath + ": cannot write");
}

mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path)
{
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(path);
	mrpt::serialization::archiveFrom(in) >> grid;
	return grid;
}

mrpt::poses::CPose2D ourMapFrameInTruth(const std::string& sampleDir, const slam::CMappingPipeline& pipeline)
{
	const auto truthTrajectory = common::readTumFile(sampleDir + "/ground_truth.tum");
	const auto& ours0 = pipeline.trajectory().front().pose;
	const auto& true0 = truthTrajectory.front().pose;
	mrpt::poses::CPose2D oursInTruth(ours0.x, ours0.y, ours0.phi);
	oursInTruth.inverse();
	return mrpt::poses::CPose2D(true0.x, true0.y, true0.phi) + oursInTruth;
}

mrpt::maps::COccupancyGridMap2D truthMapOnOurCells(const std::string& sampleDir, const slam::CMappingPipeline& pipeline,
												   const maps::TCellBounds& cells)
{
	return benchdata::resampleOntoOurCells(loadGridmap(sampleDir + "/gt_map.gridmap.gz"), pipeline.grid().geometry(), cells,
									  ourMapFrameInTruth(sampleDir, pipeline));
}

}  // namespace hslam::bench
