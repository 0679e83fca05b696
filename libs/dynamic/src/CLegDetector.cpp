#include <hslam/dynamic/CLegDetector.h>
#include <hslam/common/range_data.h>
#include <hslam/dynamic/leg_features.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hslam::dynamic
{
namespace
{
struct TBeam
{
	bool valid = false;
	double r = 0, x = 0, y = 0;
};

/** Beam end points in the robot frame (sensor offset and yaw applied). */
std::vector<TBeam> beamsOf(const mrpt::obs::CObservation2DRangeScan& scan)
{
	std::vector<TBeam> beams(scan.getScanSize());
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	for (size_t i = 0; i < beams.size(); ++i)
	{
		const double r = scan.getScanRange(i);
		if (!scan.getScanRangeValidity(i) || !std::isfinite(r) || r <= 0) continue;
		const double a = beamBearing(scan, i);
		beams[i] = {true, r, sx + r * std::cos(a), sy + r * std::sin(a)};
	}
	return beams;
}

/** True if the beam beside the segment end `edge` is farther by `jump` or empty. */
bool standsInFront(const std::vector<TBeam>& beams, size_t edge, long outside, double jump)
{
	if (outside < 0 || outside >= static_cast<long>(beams.size())) return true;
	const TBeam& o = beams[static_cast<size_t>(outside)];
	return !o.valid || o.r >= beams[edge].r + jump;
}

/** True if the segment end `edge` continues into the neighbour beam (the
 * segment was cut by the length limit, not ended by a jump or a gap). */
bool isCut(const std::vector<TBeam>& beams, size_t edge, long outside, double maxJump)
{
	if (outside < 0 || outside >= static_cast<long>(beams.size())) return false;
	const TBeam& o = beams[static_cast<size_t>(outside)];
	return o.valid && std::abs(o.r - beams[edge].r) < maxJump;
}

/** A segment of beams [first, last] whose end points are `pts` (in beam order). */
TLegSegment describe(const std::vector<mrpt::math::TPoint2D>& pts, size_t first, size_t last, double sx, double sy)
{
	TLegSegment s;
	s.first_beam = first;
	s.last_beam = last;
	for (const auto& p : pts)
	{
		s.x_m += p.x;
		s.y_m += p.y;
	}
	const double n = static_cast<double>(pts.size());
	s.x_m /= n;
	s.y_m /= n;
	s.range_m = std::hypot(s.x_m - sx, s.y_m - sy);
	s.bearing_rad = std::atan2(s.y_m - sy, s.x_m - sx);
	const auto &a = pts.front(), &b = pts.back();
	s.width_m = std::hypot(b.x - a.x, b.y - a.y);
	// Depth: largest distance of a point in front of the chord (towards the
	// sensor at the origin). Signed distance with the sensor side positive.
	if (s.width_m > 1e-9)
	{
		double nx = -(b.y - a.y) / s.width_m, ny = (b.x - a.x) / s.width_m;
		if (nx * (sx - a.x) + ny * (sy - a.y) < 0)
		{
			nx = -nx;
			ny = -ny;
		}
		for (const auto& p : pts) s.depth_m = std::max(s.depth_m, nx * (p.x - a.x) + ny * (p.y - a.y));
	}
	return s;
}

std::vector<mrpt::math::TPoint2D> pointsOf(const std::vector<TBeam>& beams, size_t first, size_t last)
{
	std::vector<mrpt::math::TPoint2D> pts;
	for (size_t i = first; i <= last; ++i) pts.push_back({beams[i].x, beams[i].y});
	return pts;
}
}  // namespace

const char* toString(ELegReject r)
{
	switch (r)
	{
		case ELegReject::accepted: return "accepted";
		case ELegReject::too_few_beams: return "too_few_beams";
		case ELegReject::too_many_beams: return "too_many_beams";
		case ELegReject::no_dip_edge: return "no_dip_edge";
		case ELegReject::width: return "width";
		case ELegReject::depth: return "depth";
		case ELegReject::cut_by_length: return "cut_by_length";
		case ELegReject::classifier: return "classifier";
	}
	return "?";
}

double angularStep(const mrpt::obs::CObservation2DRangeScan& scan)
{
	const size_t n = scan.getScanSize();
	return n > 1 ? scan.aperture / static_cast<double>(n - 1) : scan.aperture;
}

double beamBearing(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	// MRPT: beams evenly spread over the aperture, centred on the sensor x axis,
	// then turned by the mount (sensorPose: its yaw is used by the legs
	// dataset to represent asymmetric scans; a roll of 180 deg mirrors them).
	const double step = angularStep(scan);
	const double local = scan.rightToLeft ? -0.5 * scan.aperture + step * static_cast<double>(i)
										  : 0.5 * scan.aperture - step * static_cast<double>(i);
	return common::scanMount(scan.sensorPose).bearing(local);
}

namespace
{
std::shared_ptr<const CLegClassifier> loadClassifier(const std::string& path)
{
	if (path.empty()) return nullptr;
	return std::make_shared<const CLegClassifier>(CLegClassifier::load(path));
}
}  // namespace

CLegDetector::CLegDetector(const TOptions& options) : CLegDetector(options, loadClassifier(options.classifier_model))
{
}

CLegDetector::CLegDetector(const TOptions& options, std::shared_ptr<const CLegClassifier> classifier)
	: m_options(options), m_classifier(std::move(classifier))
{
	// Clusters are formed from beams a little beyond the range limit so one
	// straddling it is whole; it is kept if its centroid is within the limit.
	m_options.clustering.max_range_m = options.max_range_m + options.clustering.cluster_distance_m;
	std::istringstream in(options.find_interv_bands_m);
	double v;
	while (in >> v)
	{
		if (!(v > 0) || (!m_bandLimits_m.empty() && v <= m_bandLimits_m.back()))
			throw std::invalid_argument("find_interv_bands_m = '" + options.find_interv_bands_m +
										"': needs increasing positive ranges (m)");
		m_bandLimits_m.push_back(v);
	}
	if (!in.eof())
		throw std::invalid_argument("find_interv_bands_m = '" + options.find_interv_bands_m +
									"': not a list of numbers");
	while (!m_bandLimits_m.empty() && m_bandLimits_m.back() >= options.max_range_m) m_bandLimits_m.pop_back();
	m_bandLimits_m.push_back(options.max_range_m);
}

int CLegDetector::findInterv(double range_m, double angularStep_rad) const
{
	// The far limit of the band holding range_m; beyond max_range_m the range itself.
	double bandEnd = range_m;
	for (double limit : m_bandLimits_m)
		if (range_m < limit)
		{
			bandEnd = limit;
			break;
		}
	const double beams = m_options.min_leg_width_m / (bandEnd * angularStep_rad);
	return std::max(m_options.min_beams, static_cast<int>(std::floor(beams + 1e-9)));
}

int CLegDetector::maxBeams(double range_m, double angularStep_rad) const
{
	if (m_options.max_leg_width_m <= 0) return std::numeric_limits<int>::max();
	// The near limit of the band holding range_m (0 for the first band: no
	// bound there; beyond max_range_m the range itself).
	double bandStart = 0;
	for (double limit : m_bandLimits_m)
	{
		if (range_m < limit) break;
		bandStart = limit;
	}
	if (range_m >= m_bandLimits_m.back()) bandStart = range_m;
	if (bandStart <= 0) return std::numeric_limits<int>::max();
	return static_cast<int>(std::ceil(m_options.max_leg_width_m / (bandStart * angularStep_rad) - 1e-9)) + 2;
}

std::vector<TSegmentCandidate> CLegDetector::candidates(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	return m_classifier ? classifiedCandidates(scan) : ruleCandidates(scan);
}

std::vector<TSegmentCandidate> CLegDetector::classifiedCandidates(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	std::vector<TSegmentCandidate> out;
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	const auto clusters = clusterScan(scan, m_options.clustering);
	for (size_t k = 0; k < clusters.size(); ++k)
	{
		const auto& cluster = clusters[k];
		TSegmentCandidate c;
		c.segment = describe(cluster.points, cluster.firstBeam(), cluster.lastBeam(), sx, sy);
		if (c.segment.range_m >= m_options.max_range_m) continue;
		c.segment.leg_probability = m_classifier->probability(legFeatures(clusters, k, scan));
		if (c.segment.leg_probability < m_options.classifier_threshold) c.verdict = ELegReject::classifier;
		out.push_back(c);
	}
	return out;
}

std::vector<TSegmentCandidate> CLegDetector::ruleCandidates(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	const auto beams = beamsOf(scan);
	const double step = angularStep(scan);
	const auto& o = m_options;
	std::vector<TSegmentCandidate> out;
	size_t i = 0;
	while (i < beams.size())
	{
		if (!beams[i].valid || beams[i].r > o.max_range_m)
		{
			++i;
			continue;
		}
		size_t last = i;
		while (last + 1 < beams.size())
		{
			const TBeam& next = beams[last + 1];
			if (!next.valid || std::abs(next.r - beams[last].r) >= o.max_range_jump_m ||
				std::hypot(next.x - beams[i].x, next.y - beams[i].y) >= o.max_segment_length_m)
				break;
			++last;
		}
		TSegmentCandidate c;
		c.segment = describe(pointsOf(beams, i, last), i, last, scan.sensorPose.x(), scan.sensorPose.y());
		const int edges = static_cast<int>(standsInFront(beams, i, static_cast<long>(i) - 1, o.edge_jump_m)) +
						  static_cast<int>(standsInFront(beams, last, static_cast<long>(last) + 1, o.edge_jump_m));
		if (static_cast<int>(c.segment.beams()) < findInterv(beams[i].r, step))
			c.verdict = ELegReject::too_few_beams;
		else if (static_cast<int>(c.segment.beams()) > maxBeams(beams[i].r, step))
			c.verdict = ELegReject::too_many_beams;
		else if (edges < o.min_dip_edges)
			c.verdict = ELegReject::no_dip_edge;
		else if (c.segment.width_m < o.min_width_m || c.segment.width_m > o.max_width_m)
			c.verdict = ELegReject::width;
		else if (c.segment.depth_m < o.min_depth_m || c.segment.depth_m > o.max_depth_m)
			c.verdict = ELegReject::depth;
		else if (o.require_isolated && (isCut(beams, i, static_cast<long>(i) - 1, o.max_range_jump_m) ||
										isCut(beams, last, static_cast<long>(last) + 1, o.max_range_jump_m)))
			c.verdict = ELegReject::cut_by_length;
		out.push_back(c);
		i = last + 1;
	}
	return out;
}

std::vector<TLegSegment> CLegDetector::detect(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	std::vector<TLegSegment> legs;
	for (const auto& c : candidates(scan))
		if (c.verdict == ELegReject::accepted) legs.push_back(c.segment);
	return legs;
}

}  // namespace hslam::dynamic
