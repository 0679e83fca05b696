/* hslam-bench nav --trace (see bench_nav_trace.h). */
#include "bench_nav_trace.h"

#include <hslam/sim/scene_rendering.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace hslam::bench
{
namespace
{
mrpt::img::TColor layerColour(nav::ENavLayer l)
{
	switch (l)
	{
		case nav::ENavLayer::target: return {0, 170, 0};
		case nav::ENavLayer::sector: return {0, 0, 255};
		case nav::ENavLayer::side: return {255, 140, 0};
		case nav::ENavLayer::forward_turning: return {255, 0, 0};
		case nav::ENavLayer::boundary: return {160, 0, 200};
		default: return {90, 90, 90};
	}
}
}  // namespace

void writeNavTrace(const std::string& dir, const std::string& name, const sim::TScene& scene,
				   const sim::TNavScenario& s, const sim::TClosedLoopResult& r,
				   const std::vector<TNavTraceStep>& steps)
{
	std::filesystem::create_directories(dir);
	const auto bg = sim::rasterizeWorld(scene.world, 0.05, 0.5);
	const int side = 900;
	auto img = sim::renderOverview(bg, sim::TOverviewTracks(), side);
	const double scale = side / std::max(bg.getXMax() - bg.getXMin(), bg.getYMax() - bg.getYMin());
	auto col = [&](double x) { return static_cast<int>((x - bg.getXMin()) * scale); };
	auto row = [&](double y) { return static_cast<int>((bg.getYMax() - y) * scale); };
	if (!steps.empty())
	{
		double nextDot = 0;
		for (size_t i = 1; i < steps.size(); ++i)
		{
			const auto &a = steps[i - 1].pose, &b = steps[i].pose;
			const auto c = layerColour(steps[i].cmd.layer);
			img.line(col(a.x), row(a.y), col(b.x), row(b.y), c, 2);
			if (steps[i].t_s >= nextDot) img.drawCircle(col(b.x), row(b.y), 2, c, 1), nextDot = steps[i].t_s + 1.0;
		}
		img.textOut(8, 8, "green target, blue sector, orange side, red forward turning, purple boundary; dot = 1 s",
					mrpt::img::TColor(0, 0, 0));
		std::ofstream csv(std::filesystem::path(dir) / (name + ".csv"));
		csv << "t_s,x_m,y_m,phi_deg,v_cmd_mps,w_cmd_deg_s,state,layer,turn_in_place,nearest_m\n";
		for (const auto& st : steps)
			csv << st.t_s << "," << st.pose.x << "," << st.pose.y << "," << st.pose.phi * 180 / M_PI << ","
				<< st.cmd.v_mps << "," << st.cmd.w_rad_s * 180 / M_PI << "," << nav::navStateName(st.cmd.state) << ","
				<< nav::navLayerName(st.cmd.layer) << "," << st.cmd.turn_in_place << "," << st.cmd.nearest_m << "\n";
	}
	else
	{
		for (size_t i = 1; i < r.path.size(); ++i)
		{
			const auto &a = r.path[i - 1].pose, &b = r.path[i].pose;
			img.line(col(a.x), row(a.y), col(b.x), row(b.y), mrpt::img::TColor(0, 0, 255), 2);
		}
	}
	const auto& st = s.start;
	img.drawCircle(col(st.x), row(st.y), 8, mrpt::img::TColor(0, 0, 0), 2);
	img.line(col(st.x), row(st.y), col(st.x + 0.4 * std::cos(st.phi)), row(st.y + 0.4 * std::sin(st.phi)),
			 mrpt::img::TColor(0, 0, 0), 2);
	for (const auto& t : s.targets)
	{
		const int x = col(t.x), y = row(t.y);
		img.line(x - 8, y - 8, x + 8, y + 8, mrpt::img::TColor(200, 0, 200), 2);
		img.line(x - 8, y + 8, x + 8, y - 8, mrpt::img::TColor(200, 0, 200), 2);
	}
	img.saveToFile((std::filesystem::path(dir) / (name + ".png")).string());
}
}  // namespace hslam::bench
