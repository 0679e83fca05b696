/* hslam-bench sonar: the thesis' sonar work (4.3 TBF, 4.6 grid sonar models)
 * measured on simulated runs (hslam::sim: P3-DX front sonar ring with
 * specular/multipath echoes, LMS200 laser, exact world geometry), all in one
 * run:
 *   1. fast vs standard sonar model (thesis 4.6.2 iii / 4.6.3): time per ring
 *      update (8 readings) and map quality against the ground-truth map;
 *   2. laser only, sonar only and fused maps; our tiled grid vs MRPT's
 *      COccupancyGridMap2D on the same laser data (ground-truth agreement,
 *      insert time), and memory of a long sparse run;
 *   3. TBF corners: precision / recall against the scene's true corners
 *      (within 0.2 m) before and after the stability, clustering and cone-rim
 *      filters.
 * Maps are built with the TRUE poses (the models are measured, not the
 * localisation). Ground truth map: a cell is occupied if a wall or a circle
 * passes through it, free if it is reachable from the start without crossing
 * one, unknown otherwise (inside boxes, outside the building). Every map is
 * scored over the scene's cells (its bounds + 1 m) with the figures of
 * benchdata/map_scoring.h (agreement, agree(known), false occupied, walls
 * found), the same definitions as the grid, grid-range, sonar-batch and legs
 * suites.
 * The scene's convex corners and wall ends get 2 cm cylinders: real edges
 * diffract sound back from any direction (the point reflectors TBF relies
 * on), the simulator's planes are purely specular. Images go to outDir. */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/maps/CSonarGridInserter.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/maps/grid_rendering.h>
#include <hslam/sim/CSimulator.h>
#include <hslam/sonar/CTbfCornerDetector.h>
#include <mrpt/poses/CPose3D.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <unordered_set>

namespace hslam::bench
{
namespace
{
using mrpt::math::TPoint2D;

struct TPosedSonar
{
	mrpt::poses::CPose2D pose;
	mrpt::obs::CObservationRange obs;
};

struct TSimRun
{
	std::string name;
	sim::TScene scene;
	std::vector<TPosedScan> scans;
	std::vector<TPosedSonar> sonars;
	std::vector<mrpt::math::TPose2D> path;
};

class CCollector : public sim::ISimulationSink
{
   public:
	explicit CCollector(TSimRun& run) : m_run(run) {}
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan& obs, const std::vector<sim::TObjectTag>&,
					 const sim::TSimulationFrame& f) override
	{
		m_run.scans.push_back({mrpt::poses::CPose2D(f.true_pose), obs});
		m_run.path.push_back(f.true_pose);
	}
	void onSonar(const mrpt::obs::CObservationRange& obs, const std::vector<sim::TSonarEcho>&,
				 const sim::TSimulationFrame& f) override
	{
		m_run.sonars.push_back({mrpt::poses::CPose2D(f.true_pose), obs});
	}

   private:
	TSimRun& m_run;
};

TSimRun simulate(const std::string& name, const std::string& sceneText, const std::string& waypoints,
				 const mrpt::math::TPose2D& start, double speed_mps, bool edgeCylinders)
{
	TSimRun run;
	run.name = name;
	run.scene = sim::parseSceneText(sceneText, name);
	if (edgeCylinders)
		for (const auto& c : run.scene.corners)
			if (c.kind != sim::ECornerKind::concave) run.scene.world.addCircle({c.point, 0.02});
	sim::TSimulatorConfig cfg;
	cfg.robot.start_x_m = start.x, cfg.robot.start_y_m = start.y, cfg.robot.start_yaw_rad = start.phi;
	cfg.path.waypoints = waypoints;
	cfg.path.follower.cruise_speed_mps = speed_mps;
	cfg.simulation.settle_s = 0.2;
	sim::CSimulator simulator(cfg, run.scene);
	CCollector sink(run);
	simulator.run(sink);
	return run;
}

// ------------------------------------------------------------------ ground truth
using TCellSet = std::unordered_set<maps::TGlobalCell, maps::TGlobalCellHash>;

struct TTruth
{
	TCellSet occupied;  //!< obstacle cells
	TCellSet reachable;  //!< free cells connected to the start (not inside boxes or outside the building)
	maps::TCellBounds area;  //!< the scored cells: the scene's bounds + 1 m
};

void addObstacleCells(const TSimRun& run, const maps::CTiledGridGeometry& geo, TCellSet& occupied)
{
	const double step = 0.25 * geo.resolution_m();
	for (const auto& s : run.scene.world.segments())
	{
		const double len = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
		const int n = static_cast<int>(std::ceil(len / step));
		for (int i = 0; i <= n; ++i)
		{
			const double u = n ? static_cast<double>(i) / n : 0.0;
			occupied.insert(geo.cellOf(s.a.x + u * (s.b.x - s.a.x), s.a.y + u * (s.b.y - s.a.y)));
		}
	}
	for (const auto& c : run.scene.world.circles())
		for (int i = 0; i < 64; ++i)
			occupied.insert(geo.cellOf(c.centre.x + c.radius_m * std::cos(i * M_PI / 32),
									   c.centre.y + c.radius_m * std::sin(i * M_PI / 32)));
}

TTruth groundTruth(const TSimRun& run, const maps::CTiledGridGeometry& geo)
{
	TTruth t;
	addObstacleCells(run, geo, t.occupied);
	// Flood fill of free space from the start (4-connected, inside the bounds + 1 m).
	const auto b = run.scene.world.bounds();
	const auto lo = geo.cellOf(b.min_x - 1, b.min_y - 1), hi = geo.cellOf(b.max_x + 1, b.max_y + 1);
	t.area = {lo.gx, hi.gx, lo.gy, hi.gy};
	std::vector<maps::TGlobalCell> stack{geo.cellOf(run.path.front().x, run.path.front().y)};
	while (!stack.empty())
	{
		const maps::TGlobalCell c = stack.back();
		stack.pop_back();
		if (c.gx < lo.gx || c.gx > hi.gx || c.gy < lo.gy || c.gy > hi.gy) continue;
		if (t.occupied.count(c) || !t.reachable.insert(c).second) continue;
		stack.push_back({c.gx + 1, c.gy}), stack.push_back({c.gx - 1, c.gy});
		stack.push_back({c.gx, c.gy + 1}), stack.push_back({c.gx, c.gy - 1});
	}
	return t;
}

benchdata::TCellClassOf truthClasses(const TTruth& truth)
{
	return [&truth](const maps::TGlobalCell& c) {
		if (truth.occupied.count(c)) return benchdata::ECellClass::occupied;
		return truth.reachable.count(c) ? benchdata::ECellClass::free : benchdata::ECellClass::unknown;
	};
}

benchdata::TMapScore scoreOurs(const maps::CTiledOccupancyGrid& g, const TTruth& truth)
{
	return benchdata::scoreMap(benchdata::cellClassesOf(g), truthClasses(truth), truth.area);
}

benchdata::TMapScore scoreMrpt(const mrpt::maps::COccupancyGridMap2D& m, const maps::CTiledGridGeometry& geo,
							   const TTruth& truth)
{
	return benchdata::scoreMap(benchdata::cellClassesOf(m, geo), truthClasses(truth), truth.area);
}

// ------------------------------------------------------------------ map building
void insertSonars(maps::CTiledOccupancyGrid& grid, const std::vector<TPosedSonar>& sonars,
				  const maps::CSonarGridInserter& inserter)
{
	for (const auto& s : sonars) inserter.insert(grid, s.pose, s.obs);
}

maps::CSonarGridInserter::TOptions sonarOptions(const std::string& model, double weight)
{
	maps::CSonarGridInserter::TOptions o;
	o.model = model;
	o.weight = weight;
	return o;
}

// ------------------------------------------------------------------ TBF scoring
struct TTbfScore
{
	size_t output = 0, true_positive = 0, observable = 0, recalled = 0;
	double precision() const { return output ? static_cast<double>(true_positive) / output : 0.0; }
	double recall() const { return observable ? static_cast<double>(recalled) / observable : 0.0; }
	void add(const TTbfScore& o)
	{
		output += o.output, true_positive += o.true_positive, observable += o.observable, recalled += o.recalled;
	}
};

/** True corners some transducer had in its cone, in line of sight, within 3 m. */
std::vector<TPoint2D> observableCorners(const TSimRun& run, const sim::CSonarSimulator& ring)
{
	std::vector<TPoint2D> out;
	for (const auto& c : run.scene.corners)
	{
		bool seen = false;
		for (size_t i = 0; i < run.sonars.size() && !seen; i += 2)
			for (const auto& m : ring.ring())
			{
				const auto s = run.sonars[i].pose + mrpt::poses::CPose2D(m.x_m, m.y_m, m.yaw_rad);
				const double d = std::hypot(c.point.x - s.x(), c.point.y - s.y());
				const double a = std::atan2(c.point.y - s.y(), c.point.x - s.x());
				if (d > 3.0 || std::abs(mrpt::math::wrapToPi(a - s.phi())) > 0.5 * ring.options().cone_rad) continue;
				const auto hit = run.scene.world.castRay({s.x(), s.y()}, a, d + 0.1, false);
				if (hit.hit && hit.range_m < d - 0.05) continue;
				seen = true;
				break;
			}
		if (seen) out.push_back(c.point);
	}
	return out;
}

TTbfScore scoreCorners(const std::vector<sonar::TTbfCorner>& found, const std::vector<TPoint2D>& truthCorners,
					   const std::vector<TPoint2D>& allTrue)
{
	auto near = [](const TPoint2D& p, const TPoint2D& q) { return std::hypot(p.x - q.x, p.y - q.y) <= 0.2; };
	TTbfScore s;
	s.output = found.size();
	for (const auto& f : found)
		s.true_positive += std::any_of(allTrue.begin(), allTrue.end(), [&](const TPoint2D& t) { return near(f.point, t); });
	s.observable = truthCorners.size();
	for (const auto& t : truthCorners)
		s.recalled += std::any_of(found.begin(), found.end(), [&](const sonar::TTbfCorner& f) { return near(f.point, t); });
	return s;
}

sonar::CTbfCornerDetector runTbf(const TSimRun& run, const sonar::CTbfCornerDetector::TOptions& o)
{
	sonar::CTbfCornerDetector tbf(o);
	for (const auto& s : run.sonars) tbf.process(s.pose, s.obs);
	return tbf;
}

// ------------------------------------------------------------------ images
maps::TImageFrame sceneFrame(const TSimRun& run, const maps::CTiledGridGeometry& geo, int ppc)
{
	const auto b = run.scene.world.bounds();
	maps::TImageFrame f;
	const auto lo = geo.cellOf(b.min_x - 0.5, b.min_y - 0.5), hi = geo.cellOf(b.max_x + 0.5, b.max_y + 0.5);
	f.cells = {lo.gx, hi.gx, lo.gy, hi.gy};
	f.resolution_m = geo.resolution_m();
	f.pixels_per_cell = ppc;
	return f;
}

void saveMap(const maps::CTiledOccupancyGrid& g, const TSimRun& run, const std::string& file)
{
	const auto frame = sceneFrame(run, g.geometry(), 4);
	auto img = maps::renderGrid(g, frame);
	maps::drawTrajectory(img, frame, run.path, mrpt::img::TColor(230, 120, 0), 1);
	img.saveToFile(file);
}

/** Ground truth (black walls on white), sonar reading end points (red),
 * true corners (blue circles), TBF corners (green crosses, size ~ support). */
void saveTbfImage(const TSimRun& run, const maps::CTiledGridGeometry& geo, const TTruth& truth,
				  const sonar::CTbfCornerDetector& tbf, const std::string& file)
{
	const auto frame = sceneFrame(run, geo, 4);
	mrpt::img::CImage img(frame.widthPx(), frame.heightPx(), mrpt::img::CH_RGB);
	img.filledRectangle(0, 0, frame.widthPx() - 1, frame.heightPx() - 1, mrpt::img::TColor(255, 255, 255));
	auto px = [&](double x, double y) {
		double c, r;
		frame.worldToPixel(x, y, c, r);
		return std::pair<int, int>(static_cast<int>(c), static_cast<int>(r));
	};
	for (const auto& c : truth.occupied)
	{
		const auto p = geo.cellCentre(c);
		const auto [x, y] = px(p.x, p.y);
		img.filledRectangle(x - 2, y - 2, x + 1, y + 1, mrpt::img::TColor(0, 0, 0));
	}
	for (size_t i = 0; i < run.sonars.size(); i += 2)
		for (const auto& m : run.sonars[i].obs.sensedData)
		{
			if (m.sensedDistance >= 3.0f) continue;
			const auto s = run.sonars[i].pose + mrpt::poses::CPose2D(m.sensorPose.x, m.sensorPose.y, m.sensorPose.yaw);
			const auto [x, y] = px(s.x() + m.sensedDistance * std::cos(s.phi()), s.y() + m.sensedDistance * std::sin(s.phi()));
			img.setPixel(x, y, mrpt::img::TColor(220, 0, 0));
		}
	maps::drawTrajectory(img, frame, run.path, mrpt::img::TColor(120, 120, 120), 1);
	for (const auto& c : run.scene.corners)
	{
		const auto [x, y] = px(c.point.x, c.point.y);
		img.drawCircle(x, y, 8, mrpt::img::TColor(0, 0, 255), 1);  // 8 px = 0.2 m
	}
	for (const auto& c : tbf.corners())
	{
		const auto [x, y] = px(c.point.x, c.point.y);
		img.drawMark(x, y, mrpt::img::TColor(0, 170, 0), 'x', 4 + std::min(8, c.support / 4), 2);
	}
	img.saveToFile(file);
}

// ------------------------------------------------------------------ scenes
/* Run 1: an office room (10 m x 7 m) with three blocks and a partition wall,
 * driven once round a loop (thesis 4.3.5 / 4.6.3: the robot moves in the
 * room while recording sonar readings). Run 2: a corridor with niches and a
 * side room (thesis fig. 138-like exploration). */
const char* kOfficeScene = R"(room 0 0 10 0 10 7 0 7
box 3 2.5 1.2 0.8
box 7 4.5 1.0 1.0
box 2.5 5.5 0.8 1.0
wall 5 0 5 2
)";
const char* kOfficePath = "4 1; 4 3.5; 8.5 3.3; 8.5 6; 4.5 6.2; 4 4.2; 1 4.2; 1 1";

const char* kCorridorScene = R"(polyline 0 0 4 0 4 -1 5.5 -1 5.5 0 12 0 12 -3 16 -3 16 4 12 4 12 2 9 2 9 3 7.5 3 7.5 2 0 2
)";
const char* kCorridorPath = "11 1; 14 0.5; 14 2.5; 11 1; 1 1";
// ------------------------------------------------------------------ 1. sonar models
/** Times (s) of all the runs' sonar insertions and the pooled map agreement, per model. */
struct TSonarModelTotals
{
	double fast_s = 0, standard_s = 0, whole_tile_s = 0;
	benchdata::TMapScore fast, standard;  //!< pooled over the runs
};

CReportTable sonarMapTable()
{
	return CReportTable(std::cout, {{"run", 10, true},
									{"map", 16, true},
									{"updates", 8},
									{"ms/update", 12},
									{"agreement", 11},
									{"agree(known)", 14},
									{"known", 9},
									{"false occ", 11},
									{"walls found", 13}});
}

void printSonarMapRow(const CReportTable& table, const std::string& run, const std::string& map, size_t updates,
					  double msPerUpdate, const benchdata::TMapScore& s)
{
	table.printRow({run, map, std::to_string(updates), fixed(msPerUpdate, 3), fixed(s.agreement(), 4),
					fixed(s.agreementOfOursKnown(), 4), std::to_string(s.ours_known), std::to_string(s.false_occupied),
					fixed(s.wallsFound(), 3)});
}

/** Sonar only: the fast and the standard model (and the standard one over the
 * whole tile, as the thesis' loop), timed and scored; maps saved into outDir. */
void measureSonarModels(const TSimRun& run, const TTruth& truth, int repetitions, const CReportTable& table,
						const std::string& outDir, TSonarModelTotals& totals)
{
	const size_t n = run.sonars.size();
	const maps::CSonarGridInserter fast(sonarOptions("fast", 1.0)), standard(sonarOptions("standard", 1.0));
	auto wholeTileOptions = sonarOptions("standard", 1.0);
	wholeTileOptions.standard_scans_whole_tile = true;
	const maps::CSonarGridInserter standardWholeTile(wholeTileOptions);
	const auto timeOf = [&](const maps::CSonarGridInserter& inserter) {
		return bestTimeOf(repetitions, [&] {
			maps::CTiledOccupancyGrid g;
			insertSonars(g, run.sonars, inserter);
		});
	};
	const double tFast = timeOf(fast), tStd = timeOf(standard);
	maps::CTiledOccupancyGrid wholeTileMap, fastMap, stdMap;
	const double tWhole = bestTimeOf(1, [&] { insertSonars(wholeTileMap, run.sonars, standardWholeTile); });
	insertSonars(fastMap, run.sonars, fast);
	insertSonars(stdMap, run.sonars, standard);
	totals.fast_s += tFast, totals.standard_s += tStd, totals.whole_tile_s += tWhole;
	const benchdata::TMapScore sf = scoreOurs(fastMap, truth), ss = scoreOurs(stdMap, truth);
	totals.fast.add(sf);
	totals.standard.add(ss);
	printSonarMapRow(table, run.name, "sonar fast", n, 1e3 * tFast / n, sf);
	printSonarMapRow(table, run.name, "sonar standard", n, 1e3 * tStd / n, ss);
	printSonarMapRow(table, run.name, "  (whole tile)", n, 1e3 * tWhole / n, scoreOurs(wholeTileMap, truth));
	saveMap(fastMap, run, outDir + "/" + run.name + "_sonar_fast.png");
	saveMap(stdMap, run, outDir + "/" + run.name + "_sonar_standard.png");
}

/** Laser only (thesis laser model, 3 m), fused with the default sonar weight and
 * with other weights, and fused with the laser clearing along its long beams. */
void scoreFusedMaps(const TSimRun& run, const TTruth& truth, const CReportTable& table, const std::string& outDir)
{
	const size_t n = run.sonars.size(), fusedUpdates = run.scans.size() + n;
	maps::CLaserGridInserter laser;  // thesis defaults: long beams dropped
	const auto laserMapWith = [&](maps::CLaserGridInserter& inserter) {
		maps::CTiledOccupancyGrid g;
		for (const auto& s : run.scans) inserter.insert(g, s.pose, s.scan);
		return g;
	};
	const maps::CTiledOccupancyGrid laserMap = laserMapWith(laser);
	printSonarMapRow(table, run.name, "laser", run.scans.size(), 0.0, scoreOurs(laserMap, truth));
	const maps::CSonarGridInserter fusedSonar;  // defaults: fast, weight 0.1
	maps::CTiledOccupancyGrid fusedMap = laserMapWith(laser);
	insertSonars(fusedMap, run.sonars, fusedSonar);
	printSonarMapRow(table, run.name, "laser+sonar", fusedUpdates, 0.0, scoreOurs(fusedMap, truth));
	for (const double w : {0.25, 0.5})
	{
		maps::CTiledOccupancyGrid g = laserMapWith(laser);
		insertSonars(g, run.sonars, maps::CSonarGridInserter(sonarOptions("fast", w)));
		std::ostringstream name;
		name << "  sonar w=" << w;
		printSonarMapRow(table, run.name, name.str(), fusedUpdates, 0.0, scoreOurs(g, truth));
	}
	// The same with the laser also clearing up to 3 m along its long beams.
	maps::CLaserGridInserter clearingLaser(ourLaserOptions());
	maps::CTiledOccupancyGrid fusedClearMap = laserMapWith(clearingLaser);
	insertSonars(fusedClearMap, run.sonars, fusedSonar);
	printSonarMapRow(table, run.name, "laser+sonar *", fusedUpdates, 0.0, scoreOurs(fusedClearMap, truth));
	saveMap(laserMap, run, outDir + "/" + run.name + "_laser.png");
	saveMap(fusedMap, run, outDir + "/" + run.name + "_fused.png");
}

// ------------------------------------------------------------------ 2. laser tiled vs MRPT
struct TLaserComparison
{
	std::string run;
	benchdata::TMapScore ours, mrpt;
	double ours_us = 0, mrpt_us = 0;  //!< insertion time per scan
};

/** Laser: tiled grid vs MRPT, same scans, comparable settings (bench_common.h). */
TLaserComparison compareLaserWithMrpt(const TSimRun& run, const TTruth& truth, int repetitions)
{
	TLaserComparison lr;
	lr.run = run.name;
	maps::CTiledOccupancyGrid ours;
	insertOurs(ours, run.scans);
	auto mrptGrid = makeMrptGrid(ours);
	insertMrpt(mrptGrid, run.scans);
	lr.ours = scoreOurs(ours, truth);
	lr.mrpt = scoreMrpt(mrptGrid, ours.geometry(), truth);
	const double perScan = 1e6 / static_cast<double>(run.scans.size());
	lr.ours_us = perScan * bestTimeOf(repetitions, [&] {
		maps::CTiledOccupancyGrid g;
		insertOurs(g, run.scans);
	});
	lr.mrpt_us = perScan * bestTimeOf(repetitions, [&] {
		auto g = makeMrptGrid(ours);
		insertMrpt(g, run.scans);
	});
	return lr;
}

/** The pooled laser comparison: agreement of each map, insertion time summed over runs. */
struct TLaserTotals
{
	benchdata::TMapScore ours, mrpt;  //!< pooled over the runs
	double ours_us = 0, mrpt_us = 0;
};

TLaserTotals printLaserComparison(const std::vector<TLaserComparison>& rows)
{
	std::cout << "\n2. Laser maps, tiled grid vs MRPT COccupancyGridMap2D (same scans, 3 m range), against ground truth\n";
	const CReportTable table(std::cout, {{"run", 10, true},
										 {"ours agree", 13},
										 {"MRPT agree", 13},
										 {"ours fo", 12},
										 {"MRPT fo", 12},
										 {"ours us", 11},
										 {"MRPT us", 11}});
	table.printHeader();
	TLaserTotals t;
	for (const auto& r : rows)
	{
		table.printRow({r.run, fixed(r.ours.agreement(), 4), fixed(r.mrpt.agreement(), 4),
						std::to_string(r.ours.false_occupied), std::to_string(r.mrpt.false_occupied),
						fixed(r.ours_us, 1), fixed(r.mrpt_us, 1)});
		t.ours_us += r.ours_us, t.mrpt_us += r.mrpt_us;
		t.ours.add(r.ours);
		t.mrpt.add(r.mrpt);
	}
	return t;
}

/** Memory of a large sparse run: an L-shaped corridor in a 200 m x 200 m building. */
struct TSparseMemory
{
	size_t tiled_bytes = 0, mrpt_bytes = 0;
};

TSparseMemory measureSparseMemory()
{
	const TSimRun sparse = simulate("sparse", "polyline -95 -81 81 -81 81 95\npolyline -95 -79 79 -79 79 95\n",
									"80 -80; 80 90", {-92, -80, 0}, 1.0, false);
	maps::CTiledOccupancyGrid sparseOurs;
	insertOurs(sparseOurs, sparse.scans);
	const auto sparseMrpt = makeMrptGrid(sparseOurs);
	const TSparseMemory m{sparseOurs.memoryBytes(), mrptGridBytes(sparseMrpt)};
	std::cout << "   sparse L corridor (" << sparse.scans.size() << " scans, 172 m + 170 m): ours " << sparseOurs.tileCount()
			  << " tiles = " << m.tiled_bytes / 1024 << " KiB, MRPT one rectangle " << sparseMrpt.getSizeX() << "x"
			  << sparseMrpt.getSizeY() << " = " << m.mrpt_bytes / 1024 << " KiB\n";
	return m;
}

// ------------------------------------------------------------------ 3. TBF
struct TTbfVariant
{
	std::string name;
	bool stability, clustering;
	double coneFraction;
};

const std::vector<TTbfVariant> kTbfVariants{{"in-cone only (basic TBF)", false, false, 1.0},
											{"+ stability 20 deg", true, false, 1.0},
											{"+ stability + clustering", true, true, 1.0},
											{"clustering + cone-rim, no stability", false, true, 0.8},
											{"+ cone-rim rejection (default)", true, true, 0.8}};

/** Scores of the default filters (the last variant), also with a minimum support. */
struct TTbfDefaultScores
{
	TTbfScore all, support4, support8;
};

CReportTable tbfTable()
{
	return CReportTable(std::cout, {{"filters", 34, true}, {"corners", 9}, {"precision", 11}, {"observable", 12}, {"recall", 9}});
}

void printTbfRow(const CReportTable& table, const std::string& name, const TTbfScore& s)
{
	table.printRow({name, std::to_string(s.output), fixed(s.precision(), 3), std::to_string(s.observable), fixed(s.recall(), 3)});
}

/** One variant's corners on every run, pooled; for the default variant also the
 * support >= 4 / 8 scores and the corner images in outDir. */
TTbfScore scoreTbfVariant(const TTbfVariant& v, bool isDefault, const std::vector<TSimRun>& runs,
						  const sim::CSonarSimulator& ring, const std::string& outDir, TTbfDefaultScores& defaults)
{
	TTbfScore total;
	for (const auto& run : runs)
	{
		sonar::CTbfCornerDetector::TOptions o;
		o.use_stability_filter = v.stability;
		o.use_clustering = v.clustering;
		o.cone_fraction = v.coneFraction;
		const auto tbf = runTbf(run, o);
		std::vector<TPoint2D> all;
		for (const auto& c : run.scene.corners) all.push_back(c.point);
		const auto observable = observableCorners(run, ring);
		total.add(scoreCorners(tbf.corners(), observable, all));
		if (!isDefault) continue;
		defaults.support4.add(scoreCorners(tbf.corners(4), observable, all));
		defaults.support8.add(scoreCorners(tbf.corners(8), observable, all));
		maps::CTiledOccupancyGrid probe;
		saveTbfImage(run, probe.geometry(), groundTruth(run, probe.geometry()), tbf,
					 outDir + "/" + run.name + "_tbf_corners.png");
	}
	return total;
}

TTbfDefaultScores evaluateTbfVariants(const std::vector<TSimRun>& runs, const sim::CSonarSimulator& ring,
									  const std::string& outDir)
{
	std::cout << "\n3. TBF sonar corners vs true corners (within 0.2 m); observable = in some cone within 3 m, in sight\n";
	const CReportTable table = tbfTable();
	table.printHeader();
	TTbfDefaultScores defaults;
	for (const auto& v : kTbfVariants)
	{
		const bool isDefault = &v == &kTbfVariants.back();
		const TTbfScore total = scoreTbfVariant(v, isDefault, runs, ring, outDir, defaults);
		printTbfRow(table, v.name, total);
		if (isDefault) defaults.all = total;
	}
	printTbfRow(table, "default, support >= 4", defaults.support4);
	printTbfRow(table, "default, support >= 8", defaults.support8);
	return defaults;
}

void printSonarKeys(const TLaserTotals& laser, const TSparseMemory& sparse, const TSonarModelTotals& models,
					size_t sonarUpdates, const TTbfScore& tbf)
{
	std::cout << "\n";
	CKeyValueLines(std::cout)("laser_tiled_vs_mrpt_insert_speedup", laser.mrpt_us / laser.ours_us)(
		"laser_tiled_truth_agreement", laser.ours.agreement())("laser_mrpt_truth_agreement", laser.mrpt.agreement())(
		"sparse_run_tiled_bytes", sparse.tiled_bytes)("sparse_run_mrpt_bytes", sparse.mrpt_bytes)(
		"sonar_fast_ms_per_update", 1e3 * models.fast_s / sonarUpdates)(
		"sonar_standard_ms_per_update", 1e3 * models.standard_s / sonarUpdates)(
		"sonar_standard_whole_tile_ms_per_update", 1e3 * models.whole_tile_s / sonarUpdates)(
		"sonar_fast_vs_whole_tile_standard_speedup", models.whole_tile_s / models.fast_s)(
		"sonar_fast_vs_standard_speedup", models.standard_s / models.fast_s)(
		"sonar_fast_cell_agreement", models.fast.agreement())("sonar_standard_cell_agreement", models.standard.agreement())(
		"tbf_precision", tbf.precision())("tbf_recall", tbf.recall());
}
}  // namespace

int runSonarSuite(int repetitions, const std::string& outDir)
{
	std::filesystem::create_directories(outDir);
	std::vector<TSimRun> runs;
	runs.push_back(simulate("office", kOfficeScene, kOfficePath, {1, 1, 0}, 0.4, true));
	runs.push_back(simulate("corridor", kCorridorScene, kCorridorPath, {1, 1, 0}, 0.4, true));
	const sim::CSonarSimulator ring;  // the simulator's ring geometry / cone (defaults)

	std::cout << "Suite sonar: thesis sonar models (4.6) and TBF corners (4.3) on simulated runs (true poses), best of "
			  << repetitions << " runs\n\n";
	std::cout << "1. Sonar grid models (range limit 3 m, cone " << ring.options().cone_rad * 180 / M_PI
			  << " deg, 0.1 m cells); agreement with the ground-truth map\n";
	const CReportTable table = sonarMapTable();
	table.printHeader();
	TSonarModelTotals models;
	std::vector<TLaserComparison> laserRows;
	for (const auto& run : runs)
	{
		maps::CTiledOccupancyGrid probe;
		const TTruth truth = groundTruth(run, probe.geometry());
		measureSonarModels(run, truth, repetitions, table, outDir, models);
		scoreFusedMaps(run, truth, table, outDir);
		laserRows.push_back(compareLaserWithMrpt(run, truth, repetitions));
	}
	std::cout << "   (whole tile) = standard model testing every cell of the sensor's 200x200 tile per reading, as the"
				 " thesis' loop (4.6.3)\n   laser+sonar = fused, sonar weight 0.1 (default); sonar w = other weights\n   * = laser long beams clear free space up to 3 m (insert_free_beyond_range)\n";
	const TLaserTotals laser = printLaserComparison(laserRows);
	const TSparseMemory sparse = measureSparseMemory();
	const TTbfDefaultScores tbf = evaluateTbfVariants(runs, ring, outDir);
	std::cout << "\nimages: " << outDir << "/{office,corridor}_{sonar_fast,sonar_standard,laser,fused,tbf_corners}.png\n";
	printSonarKeys(laser, sparse, models, runs[0].sonars.size() + runs[1].sonars.size(), tbf.all);
	return 0;
}

}  // namespace hslam::bench
