#include <hslam/sonar/CTbfCornerDetector.h>
#include <hslam/sonar/tbf_geometry.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::sonar
{
using mrpt::math::TPoint2D;

namespace
{
double offAxis(const TPoint2D& p, const mrpt::math::TPose2D& sensor)
{
	return std::abs(mrpt::math::wrapToPi(std::atan2(p.y - sensor.y, p.x - sensor.x) - sensor.phi));
}

double dist(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

CTbfCornerDetector::CTbfCornerDetector(const TOptions& options) : m_options(options) {}

void CTbfCornerDetector::clear()
{
	m_window.clear();
	m_nextColumn = 0;
	m_havePose = false;
	m_intersections.clear();
	m_corners.clear();
	m_members.clear();
}

bool CTbfCornerDetector::process(const mrpt::poses::CPose2D& robotPose, const mrpt::obs::CObservationRange& obs)
{
	if (m_havePose &&
		std::hypot(robotPose.x() - m_lastColumnPose.x, robotPose.y() - m_lastColumnPose.y) < m_options.column_spacing_m)
		return false;
	std::vector<TTbfReading> column;
	for (const auto& m : obs.sensedData)
	{
		const double r = m.sensedDistance;
		if (!std::isfinite(r) || r < m_options.min_range_m || r > m_options.max_range_m) continue;
		TTbfReading reading;
		reading.sensor = (robotPose + mrpt::poses::CPose2D(m.sensorPose.x, m.sensorPose.y, m.sensorPose.yaw)).asTPose();
		reading.range_m = r;
		reading.cone_aperture_rad =
			obs.sensorConeApperture > 0 ? obs.sensorConeApperture : m_options.default_cone_aperture_rad;
		reading.sonar = m.sensorID;
		column.push_back(reading);
	}
	m_havePose = true;
	m_lastColumnPose = robotPose.asTPose();
	addColumn(std::move(column));
	return true;
}

bool CTbfCornerDetector::triangulate(const TTbfReading& a, const TTbfReading& b, TTbfIntersection& out) const
{
	if (std::abs(a.range_m - b.range_m) > m_options.range_agreement_m) return false;
	const TPoint2D sa(a.sensor.x, a.sensor.y), sb(b.sensor.x, b.sensor.y);
	if (dist(sa, sb) < m_options.min_baseline_m) return false;
	const auto points = circleCircleIntersection(sa, a.range_m, sb, b.range_m);
	if (!points) return false;
	// Of the two solutions keep the one inside both cones (the other is the
	// mirror image across the baseline, behind one of the sensors).
	bool found = false;
	double bestOff = 1e9;
	for (const TPoint2D& p : *points)
	{
		const double offA = offAxis(p, a.sensor), offB = offAxis(p, b.sensor);
		const double k = 0.5 * m_options.cone_fraction;
		if (offA > k * a.cone_aperture_rad || offB > k * b.cone_aperture_rad) continue;
		if (offA + offB < bestOff) bestOff = offA + offB, out.point = p, found = true;
	}
	if (!found) return false;
	const double ux = sa.x - out.point.x, uy = sa.y - out.point.y, vx = sb.x - out.point.x, vy = sb.y - out.point.y;
	const double c = (ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy));
	out.crossing_angle_rad = std::acos(std::clamp(c, -1.0, 1.0));
	out.stable = out.crossing_angle_rad >= m_options.min_intersection_angle_rad;
	return true;
}

void CTbfCornerDetector::addColumn(std::vector<TTbfReading> readings)
{
	const int column = m_nextColumn++;
	for (auto& r : readings) r.column = column;

	for (const TTbfReading& a : readings)
	{
		// Intersections of this reading with every older reading of the window.
		std::vector<TPoint2D> accepted;
		for (const auto& older : m_window)
			for (const TTbfReading& b : older)
			{
				TTbfIntersection x;
				if (!triangulate(a, b, x)) continue;
				m_intersections.push_back(x);
				if (m_options.use_stability_filter && !x.stable) continue;
				accepted.push_back(x.point);
			}
		if (accepted.empty()) continue;
		// Hypothesis counter n: the largest set of intersections agreeing
		// within hypothesis_radius_m (around one of them), averaged.
		size_t bestCount = 0;
		TPoint2D bestMean;
		for (const TPoint2D& centre : accepted)
		{
			size_t count = 0;
			TPoint2D sum(0, 0);
			for (const TPoint2D& q : accepted)
				if (dist(q, centre) <= m_options.hypothesis_radius_m) ++count, sum.x += q.x, sum.y += q.y;
			if (count > bestCount) bestCount = count, bestMean = TPoint2D(sum.x / count, sum.y / count);
		}
		if (static_cast<int>(bestCount) >= m_options.min_hypotheses)
			addHypothesis(bestMean, static_cast<int>(bestCount));
	}

	if (m_intersections.size() > kMaxKeptIntersections)  // bounded memory on long runs
		m_intersections.erase(m_intersections.begin(),
							  m_intersections.end() - static_cast<std::ptrdiff_t>(kMaxKeptIntersections / 2));
	m_window.push_back(std::move(readings));
	while (static_cast<int>(m_window.size()) > m_options.window_columns) m_window.pop_front();
}

void CTbfCornerDetector::addHypothesis(const TPoint2D& p, int count)
{
	size_t target = m_corners.size();
	if (m_options.use_clustering)
	{
		double best = m_options.cluster_radius_m;
		for (size_t i = 0; i < m_corners.size(); ++i)
		{
			const double d = dist(m_corners[i].point, p);
			if (d <= best) best = d, target = i;
		}
	}
	if (target == m_corners.size())
	{
		m_corners.emplace_back();
		m_members.emplace_back();
	}
	auto& members = m_members[target];
	members.emplace_back(p, count);

	// Support-weighted mean and scatter of the members, plus the floor.
	double w = 0, mx = 0, my = 0;
	for (const auto& [q, n] : members) w += n, mx += n * q.x, my += n * q.y;
	mx /= w, my /= w;
	double sxx = 0, sxy = 0, syy = 0;
	for (const auto& [q, n] : members)
		sxx += n * (q.x - mx) * (q.x - mx), sxy += n * (q.x - mx) * (q.y - my), syy += n * (q.y - my) * (q.y - my);
	const double floor2 = m_options.min_std_m * m_options.min_std_m;
	TTbfCorner& c = m_corners[target];
	c.point = TPoint2D(mx, my);
	c.cov(0, 0) = sxx / w + floor2;
	c.cov(0, 1) = c.cov(1, 0) = sxy / w;
	c.cov(1, 1) = syy / w + floor2;
	c.support = static_cast<int>(w);
	c.hypotheses = static_cast<int>(members.size());
}

std::vector<TTbfCorner> CTbfCornerDetector::corners(int minSupport) const
{
	std::vector<TTbfCorner> out;
	for (const auto& c : m_corners)
		if (c.support >= minSupport) out.push_back(c);
	return out;
}

}  // namespace hslam::sonar
