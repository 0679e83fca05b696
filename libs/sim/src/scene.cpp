/* hslam sim: scene text parser, corner extraction and raster loaders. */
#include <hslam/common/parse_number.h>
#include <hslam/sim/scene.h>

#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hslam::sim
{
using mrpt::math::TPoint2D;

const char* cornerKindName(ECornerKind kind)
{
	switch (kind)
	{
		case ECornerKind::concave: return "concave";
		case ECornerKind::convex: return "convex";
		case ECornerKind::end: return "end";
	}
	return "end";
}

namespace
{
constexpr double kDegToRad = M_PI / 180.0;
constexpr double kMinCornerTurnDeg = 10.0;

class CLineError
{
   public:
	CLineError(const std::string& name, int line) : m_where(name + ":" + std::to_string(line) + ": ") {}
	[[noreturn]] void fail(const std::string& why) const { throw std::runtime_error(m_where + why); }

   private:
	std::string m_where;
};

double parseNumber(const std::string& token, const CLineError& err)
{
	const auto v = hslam::common::tryParseDouble(token);
	if (!v) err.fail("'" + token + "' is not a finite number");
	return *v;
}

/** Adds a chain of walls (free on the left) and its corners. */
void addChain(TScene& scene, const std::vector<TPoint2D>& pts, bool closed, int chain)
{
	const size_t n = pts.size();
	const size_t nSeg = closed ? n : n - 1;
	for (size_t k = 0; k < nSeg; ++k)
		scene.world.addSegment(TSegment{pts[k], pts[(k + 1) % n], TObjectTag{EObjectKind::wall, chain, static_cast<int>(k)}});
	auto addCorner = [&](const TPoint2D& p, ECornerKind kind, double freeAngle) {
		scene.corners.push_back(TWorldCorner{static_cast<int>(scene.corners.size()), p, kind, freeAngle, chain});
	};
	for (size_t k = 0; k < n; ++k)
	{
		const bool hasPrev = closed || k > 0, hasNext = closed || k + 1 < n;
		if (!hasPrev || !hasNext)
		{
			addCorner(pts[k], ECornerKind::end, 360.0);
			continue;
		}
		const TPoint2D& a = pts[(k + n - 1) % n];
		const TPoint2D& v = pts[k];
		const TPoint2D& b = pts[(k + 1) % n];
		const double h1 = std::atan2(v.y - a.y, v.x - a.x), h2 = std::atan2(b.y - v.y, b.x - v.x);
		double turn = std::remainder(h2 - h1, 2 * M_PI);  // > 0: left turn
		if (std::abs(turn) < kMinCornerTurnDeg * kDegToRad) continue;
		// Free space on the left: a left turn closes around the free side (inside corner).
		const double freeAngleDeg = 180.0 - turn / kDegToRad;
		addCorner(v, turn > 0 ? ECornerKind::concave : ECornerKind::convex, freeAngleDeg);
	}
}

double signedArea(const std::vector<TPoint2D>& pts)
{
	double a = 0;
	for (size_t k = 0; k < pts.size(); ++k)
	{
		const auto& p = pts[k];
		const auto& q = pts[(k + 1) % pts.size()];
		a += p.x * q.y - q.x * p.y;
	}
	return 0.5 * a;
}

std::vector<TPoint2D> rectangle(double cx, double cy, double w, double h, double yawDeg)
{
	const double c = std::cos(yawDeg * kDegToRad), s = std::sin(yawDeg * kDegToRad);
	std::vector<TPoint2D> pts;
	for (const auto& [u, v] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}})
		pts.push_back(TPoint2D{cx + c * u * w - s * v * h, cy + s * u * w + c * v * h});
	return pts;
}

void addLegs(TScene& scene, const std::vector<TPoint2D>& corners, double legRadius, int furnitureId)
{
	int part = 0;
	for (const auto& p : corners)
		scene.world.addCircle(TCircle{p, legRadius, TObjectTag{EObjectKind::furniture, furnitureId, part++}});
}

std::vector<TPoint2D> pointList(const std::vector<double>& v, size_t minPoints, const CLineError& err)
{
	if (v.size() % 2 != 0) err.fail("odd number of coordinates");
	if (v.size() / 2 < minPoints) err.fail("needs at least " + std::to_string(minPoints) + " points");
	std::vector<TPoint2D> pts;
	for (size_t k = 0; k < v.size(); k += 2) pts.push_back(TPoint2D{v[k], v[k + 1]});
	return pts;
}

void requireCount(const std::vector<double>& v, size_t lo, size_t hi, const std::string& what, const CLineError& err)
{
	if (v.size() < lo || v.size() > hi)
		err.fail(what + " takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + "-" + std::to_string(hi)) +
				 " numbers, got " + std::to_string(v.size()));
}

void parsePerson(TScene& scene, const std::vector<std::string>& words, const CLineError& err)
{
	TPersonSpec p;
	p.id = static_cast<int>(scene.people.size());
	std::vector<double> nums;
	for (size_t k = 1; k < words.size(); ++k)
	{
		const std::string& w = words[k];
		if (w == "loop")
			p.loop = true;
		else if (w == "pingpong")
			p.loop = false;
		else if (w.rfind("delay=", 0) == 0)
			p.start_delay_s = parseNumber(w.substr(6), err);
		else
			nums.push_back(parseNumber(w, err));
	}
	if (nums.size() < 7) err.fail("person needs speed_mps leg_r step_m and at least 2 waypoints");
	p.speed_mps = nums[0];
	p.leg_radius_m = nums[1];
	p.step_length_m = nums[2];
	if (!(p.speed_mps > 0 && p.speed_mps < 3)) err.fail("person speed must be in (0, 3) m/s");
	if (!(p.leg_radius_m >= 0.02 && p.leg_radius_m <= 0.2)) err.fail("person leg radius must be in [0.02, 0.2] m");
	if (!(p.step_length_m >= 0.1 && p.step_length_m <= 1.5)) err.fail("person step length must be in [0.1, 1.5] m");
	p.waypoints = pointList(std::vector<double>(nums.begin() + 3, nums.end()), 2, err);
	try
	{
		CWalkingPerson check(p);
	}
	catch (const std::exception& e)
	{
		err.fail(e.what());
	}
	scene.people.push_back(p);
}
/** A convex corner of one chain that touches a wall of another chain (a box
 * pushed against a room wall) is seen from free space as an inside corner:
 * its free opening is the convex opening minus the 180 deg of the wall. */
void classifyJunctions(TScene& scene)
{
	for (auto& c : scene.corners)
	{
		if (c.kind != ECornerKind::convex) continue;
		for (const auto& s : scene.world.segments())
		{
			if (s.tag.group == c.chain) continue;
			const double ex = s.b.x - s.a.x, ey = s.b.y - s.a.y, len2 = ex * ex + ey * ey;
			if (len2 <= 0) continue;
			const double u = std::clamp(((c.point.x - s.a.x) * ex + (c.point.y - s.a.y) * ey) / len2, 0.0, 1.0);
			if (std::hypot(c.point.x - (s.a.x + u * ex), c.point.y - (s.a.y + u * ey)) > 1e-3) continue;
			c.kind = ECornerKind::concave;
			c.free_angle_deg -= 180.0;
			break;
		}
	}
}
}  // namespace

namespace
{
/** The words of a scene line, comments ('#' to the end) removed. */
std::vector<std::string> sceneWords(std::string line)
{
	if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
	std::istringstream ls(line);
	std::vector<std::string> words;
	for (std::string w; ls >> w;) words.push_back(w);
	return words;
}

/** The scene being read and the numbering of its wall chains and furniture. */
struct TSceneBuilder
{
	TScene scene;
	int chain = 0, furniture = 0;
};

/** wall, polyline, room and box items (chains of wall segments); false for other kinds. */
bool addWallItem(TSceneBuilder& b, const std::string& kind, const std::vector<double>& v, const CLineError& err)
{
	if (kind == "wall")
	{
		requireCount(v, 4, 4, "wall", err);
		addChain(b.scene, pointList(v, 2, err), false, b.chain++);
	}
	else if (kind == "polyline")
		addChain(b.scene, pointList(v, 2, err), false, b.chain++);
	else if (kind == "room")
	{
		auto pts = pointList(v, 3, err);
		if (signedArea(pts) < 0) std::reverse(pts.begin(), pts.end());  // CCW: free inside = left
		addChain(b.scene, pts, true, b.chain++);
	}
	else if (kind == "box")
	{
		requireCount(v, 4, 5, "box", err);
		if (!(v[2] > 0 && v[3] > 0)) err.fail("box width and height must be > 0");
		auto pts = rectangle(v[0], v[1], v[2], v[3], v.size() > 4 ? v[4] : 0.0);
		std::reverse(pts.begin(), pts.end());  // CW: free outside = left
		addChain(b.scene, pts, true, b.chain++);
	}
	else
		return false;
	return true;
}

/** circle, chair and table items (furniture); false for other kinds. */
bool addFurnitureItem(TSceneBuilder& b, const std::string& kind, const std::vector<double>& v, const CLineError& err)
{
	if (kind == "circle")
	{
		requireCount(v, 3, 3, "circle", err);
		if (!(v[2] > 0)) err.fail("circle radius must be > 0");
		b.scene.world.addCircle(TCircle{TPoint2D{v[0], v[1]}, v[2], TObjectTag{EObjectKind::furniture, b.furniture++, 0}});
	}
	else if (kind == "chair")
	{
		requireCount(v, 2, 5, "chair", err);
		const double size = v.size() > 3 ? v[3] : 0.45, legR = v.size() > 4 ? v[4] : 0.015;
		if (!(size > 0 && legR > 0 && 2 * legR < size)) err.fail("chair size/leg radius invalid");
		addLegs(b.scene, rectangle(v[0], v[1], size - 2 * legR, size - 2 * legR, v.size() > 2 ? v[2] : 0.0), legR,
				b.furniture++);
	}
	else if (kind == "table")
	{
		requireCount(v, 4, 6, "table", err);
		const double legR = v.size() > 5 ? v[5] : 0.025;
		if (!(v[2] > 2 * legR && v[3] > 2 * legR && legR > 0)) err.fail("table size/leg radius invalid");
		addLegs(b.scene, rectangle(v[0], v[1], v[2] - 2 * legR, v[3] - 2 * legR, v.size() > 4 ? v[4] : 0.0), legR,
				b.furniture++);
	}
	else
		return false;
	return true;
}
}  // namespace

TScene parseSceneText(const std::string& text, const std::string& name)
{
	TSceneBuilder b;
	std::istringstream in(text);
	std::string line;
	for (int lineNo = 1; std::getline(in, line); ++lineNo)
	{
		const CLineError err(name, lineNo);
		const std::vector<std::string> words = sceneWords(line);
		if (words.empty()) continue;
		const std::string& kind = words[0];
		if (kind == "person")
		{
			parsePerson(b.scene, words, err);
			continue;
		}
		std::vector<double> v;
		for (size_t k = 1; k < words.size(); ++k) v.push_back(parseNumber(words[k], err));
		if (!addWallItem(b, kind, v, err) && !addFurnitureItem(b, kind, v, err))
			err.fail("unknown item '" + kind +
					 "' (expected wall, polyline, room, box, circle, chair, table or person)");
	}
	classifyJunctions(b.scene);
	return std::move(b.scene);
}

TScene loadSceneFile(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot open scene file");
	std::stringstream ss;
	ss << f.rdbuf();
	return parseSceneText(ss.str(), path);
}

TOccupancyRaster loadOccupancyImage(const std::string& path, double resolution_m, double x0_m, double y0_m,
									double occupiedBelow)
{
	if (!(resolution_m > 0)) throw std::runtime_error(path + ": resolution must be > 0");
	mrpt::img::CImage img;
	if (!img.loadFromFile(path, 0 /* gray */)) throw std::runtime_error(path + ": cannot read image");
	TOccupancyRaster r;
	r.x0_m = x0_m;
	r.y0_m = y0_m;
	r.resolution_m = resolution_m;
	r.width = static_cast<int>(img.getWidth());
	r.height = static_cast<int>(img.getHeight());
	r.occupied.assign(static_cast<size_t>(r.width) * r.height, 0);
	for (int j = 0; j < r.height; ++j)
		for (int i = 0; i < r.width; ++i)
		{
			const int row = r.height - 1 - j;  // image row 0 is the top (largest y)
			const double gray = *img(i, row) / 255.0;
			r.occupied[static_cast<size_t>(j) * r.width + i] = gray < occupiedBelow ? 1 : 0;
		}
	return r;
}

TOccupancyRaster loadGridMapFile(const std::string& path, double occupiedAbove)
{
	mrpt::io::CFileGZInputStream in;
	if (!in.open(path)) throw std::runtime_error(path + ": cannot open grid map");
	mrpt::maps::COccupancyGridMap2D grid;
	try
	{
		auto arch = mrpt::serialization::archiveFrom(in);
		arch >> grid;
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(path + ": not an MRPT COccupancyGridMap2D file (" + e.what() + ")");
	}
	TOccupancyRaster r;
	r.resolution_m = grid.getResolution();
	r.x0_m = grid.getXMin();
	r.y0_m = grid.getYMin();
	r.width = static_cast<int>(grid.getSizeX());
	r.height = static_cast<int>(grid.getSizeY());
	r.occupied.assign(static_cast<size_t>(r.width) * r.height, 0);
	for (int j = 0; j < r.height; ++j)
		for (int i = 0; i < r.width; ++i)
			r.occupied[static_cast<size_t>(j) * r.width + i] = (1.0 - grid.getCell(i, j)) > occupiedAbove ? 1 : 0;
	return r;
}

}  // namespace hslam::sim
