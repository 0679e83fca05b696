/* hslam-navigate: CNavigationLog (see its header). */
#include "CNavigationLog.h"

#include <hslam/sim/scene_rendering.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hslam::apps
{
CNavigationLog::CNavigationLog(const std::string& dir)
	: m_dir(dir), m_rawlog((std::filesystem::path(dir) / "navigation.rawlog").string())
{
	m_map.setSize(-10, 10, -10, 10, 0.05f);
	m_map.insertionOptions.maxDistanceInsertion = 6.0f;
}

void CNavigationLog::observation(const mrpt::obs::CObservation& obs) { m_rawlog.write(obs); }

void CNavigationLog::mapScan(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& pose)
{
	const mrpt::poses::CPose3D robot{mrpt::poses::CPose2D(pose)};
	m_map.insertObservation(scan, robot);  // the grid grows as needed
}

void CNavigationLog::finish()
{
	m_rawlog.close();
	const auto dir = std::filesystem::path(m_dir);
	std::ofstream csv(dir / "path.csv");
	csv << "t_s,x_m,y_m,phi_deg,v_cmd_mps,w_cmd_deg_s,state,nearest_m,targets_reached,layer\n";
	for (const auto& s : m_samples)
		csv << s.t_s << "," << s.pose.x << "," << s.pose.y << "," << s.pose.phi * 180 / M_PI << "," << s.v_cmd_mps << ","
			<< s.w_cmd_rad_s * 180 / M_PI << "," << s.state << "," << s.nearest_m << "," << s.targets_reached << "," << s.layer << "\n";
	if (!csv) throw std::runtime_error((dir / "path.csv").string() + ": write failed");
	m_map.saveAsBitmapFile((dir / "live_map.png").string());
	mrpt::io::CFileGZOutputStream gz((dir / "live_map.gridmap.gz").string());
	auto arch = mrpt::serialization::archiveFrom(gz);
	arch << m_map;
}

namespace
{
/** Blue (slow) -> green -> red (fast) for speed / maxSpeed. */
mrpt::img::TColor speedColour(double f)
{
	f = std::clamp(f, 0.0, 1.0);
	const auto c = [](double x) { return static_cast<uint8_t>(std::clamp(x, 0.0, 1.0) * 255); };
	return f < 0.5 ? mrpt::img::TColor(0, c(2 * f), c(1 - 2 * f)) : mrpt::img::TColor(c(2 * f - 1), c(2 - 2 * f), 0);
}
}  // namespace

mrpt::img::CImage CNavigationLog::renderPath(const mrpt::maps::COccupancyGridMap2D& bg,
											 const std::vector<mrpt::math::TPoint2D>& targets, int maxSidePx) const
{
	auto img = sim::renderOverview(bg, sim::TOverviewTracks(), maxSidePx);
	const double scale = maxSidePx / std::max(bg.getXMax() - bg.getXMin(), bg.getYMax() - bg.getYMin());
	auto col = [&](double x) { return static_cast<int>((x - bg.getXMin()) * scale); };
	auto row = [&](double y) { return static_cast<int>((bg.getYMax() - y) * scale); };
	double vmax = 1e-3;
	for (const auto& s : m_samples) vmax = std::max(vmax, std::abs(s.v_cmd_mps));
	double nextDot = 0;
	for (size_t i = 1; i < m_samples.size(); ++i)
	{
		const auto &a = m_samples[i - 1].pose, &b = m_samples[i].pose;
		const auto colour = speedColour(std::abs(m_samples[i].v_cmd_mps) / vmax);
		img.line(col(a.x), row(a.y), col(b.x), row(b.y), colour, 2);
		if (m_samples[i].t_s >= nextDot)  // one dot per second: the spacing shows the speed (thesis fig. 67)
		{
			img.drawCircle(col(b.x), row(b.y), 3, colour, 1);
			nextDot = m_samples[i].t_s + 1.0;
		}
	}
	if (!m_samples.empty())
	{
		const auto& s = m_samples.front().pose;
		img.drawCircle(col(s.x), row(s.y), 8, mrpt::img::TColor(0, 0, 0), 2);
		img.line(col(s.x), row(s.y), col(s.x + 0.4 * std::cos(s.phi)), row(s.y + 0.4 * std::sin(s.phi)),
				 mrpt::img::TColor(0, 0, 0), 2);
	}
	for (size_t k = 0; k < targets.size(); ++k)
	{
		const int x = col(targets[k].x), y = row(targets[k].y);
		img.line(x - 8, y - 8, x + 8, y + 8, mrpt::img::TColor(200, 0, 200), 2);
		img.line(x - 8, y + 8, x + 8, y - 8, mrpt::img::TColor(200, 0, 200), 2);
		img.textOut(x + 10, y - 6, "T" + std::to_string(k + 1), mrpt::img::TColor(200, 0, 200));
	}
	img.textOut(8, 8, "speed: blue slow .. red " + std::to_string(static_cast<int>(vmax * 1000)) + " mm/s; dot = 1 s",
				mrpt::img::TColor(0, 0, 0));
	return img;
}

}  // namespace hslam::apps
