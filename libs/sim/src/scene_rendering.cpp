/* hslam sim: world rasterisation and overview picture. */
#include <hslam/sim/scene_rendering.h>

#include <algorithm>
#include <cmath>

namespace hslam::sim
{
mrpt::maps::COccupancyGridMap2D rasterizeWorld(const CWorld& world, double res, double margin)
{
	const TWorldBounds b = world.bounds();
	mrpt::maps::COccupancyGridMap2D grid(static_cast<float>(b.min_x - margin), static_cast<float>(b.max_x + margin),
										 static_cast<float>(b.min_y - margin), static_cast<float>(b.max_y + margin),
										 static_cast<float>(res));
	grid.fill(1.0f);
	auto occupy = [&](double x, double y) {
		const int cx = grid.x2idx(x), cy = grid.y2idx(y);
		if (cx >= 0 && cy >= 0 && cx < static_cast<int>(grid.getSizeX()) && cy < static_cast<int>(grid.getSizeY()))
			grid.setCell(cx, cy, 0.0f);
	};
	for (const auto& s : world.segments())
	{
		const double len = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
		const int n = std::max(1, static_cast<int>(std::ceil(len / (0.25 * res))));
		for (int k = 0; k <= n; ++k)
			occupy(s.a.x + (s.b.x - s.a.x) * k / n, s.a.y + (s.b.y - s.a.y) * k / n);
	}
	for (const auto& c : world.circles())
	{
		occupy(c.centre.x, c.centre.y);
		const int r = static_cast<int>(std::ceil(c.radius_m / res)) + 1;
		for (int dj = -r; dj <= r; ++dj)
			for (int di = -r; di <= r; ++di)
			{
				const double x = c.centre.x + di * res, y = c.centre.y + dj * res;
				const double cx = grid.idx2x(grid.x2idx(x)), cy = grid.idx2y(grid.y2idx(y));
				// nearest point of the cell to the circle centre
				const double nx = std::clamp(c.centre.x, cx - 0.5 * res, cx + 0.5 * res);
				const double ny = std::clamp(c.centre.y, cy - 0.5 * res, cy + 0.5 * res);
				if (std::hypot(nx - c.centre.x, ny - c.centre.y) < c.radius_m) occupy(x, y);
			}
	}
	const TOccupancyRaster& r = world.raster();
	for (int j = 0; j < r.height; ++j)
		for (int i = 0; i < r.width; ++i)
			if (r.isOccupiedCell(i, j))
				occupy(r.x0_m + (i + 0.5) * r.resolution_m, r.y0_m + (j + 0.5) * r.resolution_m);
	return grid;
}

namespace
{
struct TFrame
{
	double x0, y1, scale;  //!< world left, world top, pixels per metre
	double col(double x) const { return (x - x0) * scale; }
	double row(double y) const { return (y1 - y) * scale; }
};

template <class P>
void drawPolyline(mrpt::img::CImage& img, const TFrame& f, const std::vector<P>& pts, const mrpt::img::TColor& colour,
				  unsigned width)
{
	for (size_t k = 1; k < pts.size(); ++k)
		img.line(static_cast<int>(f.col(pts[k - 1].x)), static_cast<int>(f.row(pts[k - 1].y)),
				 static_cast<int>(f.col(pts[k].x)), static_cast<int>(f.row(pts[k].y)), colour, width);
}
}  // namespace

mrpt::img::CImage renderOverview(const mrpt::maps::COccupancyGridMap2D& grid, const TOverviewTracks& tracks,
								 int maxSidePx)
{
	const double wM = grid.getXMax() - grid.getXMin(), hM = grid.getYMax() - grid.getYMin();
	const double scale = maxSidePx / std::max(wM, hM);
	const int w = std::max(1, static_cast<int>(std::lround(wM * scale)));
	const int h = std::max(1, static_cast<int>(std::lround(hM * scale)));
	const TFrame f{grid.getXMin(), grid.getYMax(), scale};
	mrpt::img::CImage img(w, h, mrpt::img::CH_RGB);
	img.filledRectangle(0, 0, w - 1, h - 1, mrpt::img::TColor(255, 255, 255));
	const double res = grid.getResolution();
	for (unsigned cy = 0; cy < grid.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < grid.getSizeX(); ++cx)
		{
			const float p = grid.getCell(cx, cy);
			if (p > 0.9f) continue;
			const uint8_t g = static_cast<uint8_t>(255.0f * p);
			const double x = grid.idx2x(cx), y = grid.idx2y(cy);
			img.filledRectangle(static_cast<int>(f.col(x - 0.5 * res)), static_cast<int>(f.row(y + 0.5 * res)),
								static_cast<int>(f.col(x + 0.5 * res)), static_cast<int>(f.row(y - 0.5 * res)),
								mrpt::img::TColor(g, g, g));
		}
	const mrpt::img::TColor personColours[] = {{0, 160, 0}, {255, 140, 0}, {150, 60, 200}, {0, 150, 150}};
	for (size_t k = 0; k < tracks.people.size(); ++k)
		drawPolyline(img, f, tracks.people[k], personColours[k % 4], 1);
	drawPolyline(img, f, tracks.odometry_path, mrpt::img::TColor(60, 90, 255), 1);
	drawPolyline(img, f, tracks.true_path, mrpt::img::TColor(220, 0, 0), 2);
	for (const auto& c : tracks.corners)
	{
		if (c.kind == ECornerKind::end) continue;
		const int x = static_cast<int>(f.col(c.point.x)), y = static_cast<int>(f.row(c.point.y));
		img.rectangle(x - 3, y - 3, x + 3, y + 3,
					  c.kind == ECornerKind::concave ? mrpt::img::TColor(220, 0, 220) : mrpt::img::TColor(0, 200, 220),
					  1);
	}
	if (!tracks.true_path.empty())
	{
		const auto& s = tracks.true_path.front();
		img.drawCircle(static_cast<int>(f.col(s.x)), static_cast<int>(f.row(s.y)), 6, mrpt::img::TColor(220, 0, 0), 2);
	}
	return img;
}

}  // namespace hslam::sim
