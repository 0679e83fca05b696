#include <hslam/dynamic/CDynamicObjectFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace hslam::dynamic
{
size_t TDynamicFrame::dynamicBeams() const
{
	return static_cast<size_t>(std::count(beam_is_dynamic.begin(), beam_is_dynamic.end(), true));
}

namespace
{
maps::CTiledOccupancyGrid::TOptions seenGridOptions(const CDynamicObjectFilter::TOptions& o)
{
	maps::CTiledOccupancyGrid::TOptions g;
	g.resolution_m = o.free_space_resolution_m;
	return g;
}

/** Person tracks: with person_needs_dynamic_leg at least one observation
 * backed by a dynamic leg track is needed (passed as motion evidence). */
CKalmanTracker::TOptions personTrackerOptions(const CDynamicObjectFilter::TOptions& o)
{
	CKalmanTracker::TOptions t = o.tracker;
	if (o.person_needs_dynamic_leg) t.confirm_free_hits = std::max(1, t.confirm_free_hits);
	return t;
}

maps::CLaserGridInserter::TOptions seenInserterOptions(const CDynamicObjectFilter::TOptions& o)
{
	maps::CLaserGridInserter::TOptions l;
	l.max_range_m = o.free_space_max_range_m;
	l.insert_free_beyond_range = true;
	return l;
}

CStaticEvidenceGrid::TOptions staticGridOptions(const CDynamicObjectFilter::TOptions& o)
{
	CStaticEvidenceGrid::TOptions g = o.static_grid;
	// Only end points where legs are looked for (plus the search radius) matter.
	g.max_range_m = o.detector.max_range_m + o.static_grid.radius_m + o.detector.max_segment_length_m;
	return g;
}
}  // namespace

CDynamicObjectFilter::CDynamicObjectFilter(const TOptions& options) : CDynamicObjectFilter(options, nullptr) {}

CDynamicObjectFilter::CDynamicObjectFilter(const TOptions& options, std::shared_ptr<const CLegClassifier> classifier)
	: m_options(options),
	  m_detector(classifier ? CLegDetector(options.detector, std::move(classifier)) : CLegDetector(options.detector)),
	  m_legs(options.tracker),
	  m_persons(personTrackerOptions(options)),
	  m_seen(seenGridOptions(options)),
	  m_seenInserter(seenInserterOptions(options)),
	  m_static(staticGridOptions(options)),
	  m_cues(options.camera_cues)
{
}

void CDynamicObjectFilter::markCameraCueEvidence(double t_s)
{
	for (auto& leg : m_frame.legs)
	{
		leg.camera_cue = m_cues.supports(std::atan2(leg.segment.y_m, leg.segment.x_m), t_s);
		if (leg.camera_cue) leg.in_free_space = true;
	}
}

bool CDynamicObjectFilter::seenFreeBefore(const mrpt::math::TPoint2D& leg, const mrpt::poses::CPose2D& sensorPose) const
{
	const double dx = leg.x - sensorPose.x(), dy = leg.y - sensorPose.y(), r = std::hypot(dx, dy);
	if (r < 1e-6) return false;
	const double k = m_options.free_space_behind_m / r;
	const auto c = m_seen.geometry().cellOf(leg.x + k * dx, leg.y + k * dy);
	return m_seen.isObserved(c) && m_seen.occupancyProbability(c) < m_options.free_space_threshold;
}

double CDynamicObjectFilter::maskRadius(const TTrack& t) const
{
	// A person is a disc around its track: both legs (each at most half the
	// pairing distance from the midpoint, plus a leg radius = mask_radius_m)
	// where the track is believed to be (its position standard deviation,
	// which grows while the track is missed).
	const double sigma = std::sqrt(0.5 * std::max(0.0, t.P(0, 0) + t.P(1, 1)));
	return m_options.mask_radius_m + m_options.mask_sigma * sigma;
}

void CDynamicObjectFilter::pairLegs(const std::vector<mrpt::math::TPoint2D>& legs,
									std::vector<TTrackObservation>& persons, std::vector<int>& personOfLeg) const
{
	personOfLeg.assign(legs.size(), -1);
	persons.clear();
	std::vector<std::tuple<double, size_t, size_t>> pairs;
	for (size_t a = 0; a < legs.size(); ++a)
		for (size_t b = a + 1; b < legs.size(); ++b)
		{
			const double d = std::hypot(legs[a].x - legs[b].x, legs[a].y - legs[b].y);
			if (d <= m_options.pair_max_distance_m) pairs.emplace_back(d, a, b);
		}
	std::sort(pairs.begin(), pairs.end());
	for (const auto& [d, a, b] : pairs)
	{
		if (personOfLeg[a] >= 0 || personOfLeg[b] >= 0) continue;
		personOfLeg[a] = personOfLeg[b] = static_cast<int>(persons.size());
		persons.emplace_back();
		persons.back().position_m = {0.5 * (legs[a].x + legs[b].x), 0.5 * (legs[a].y + legs[b].y)};
	}
	for (size_t a = 0; a < legs.size(); ++a)
		if (personOfLeg[a] < 0)
		{
			personOfLeg[a] = static_cast<int>(persons.size());
			persons.emplace_back();
			persons.back().position_m = legs[a];
		}
}

void CDynamicObjectFilter::updatePersonTracks(const std::vector<mrpt::math::TPoint2D>& legsWorld,
											  const mrpt::poses::CPose2D& sensorPose, double t_s, bool useEvidence)
{
	constexpr double kNever = std::numeric_limits<double>::infinity();
	std::vector<TTrackObservation> persons;
	std::vector<int> personOfLeg;
	pairLegs(legsWorld, persons, personOfLeg);
	// Person evidence: one of its legs is where free space was and, with
	// person_needs_dynamic_leg, on a leg track confirmed dynamic itself (a
	// pair of static legs changes its midpoint when the pairing changes).
	// Without evidence asked for, every person has it (the rule is waived).
	const bool usePersonEvidence = useEvidence || m_options.person_needs_dynamic_leg;
	std::vector<double> legsOfPerson(persons.size(), 0.0);
	for (auto& p : persons)
	{
		p.motion_evidence = false;  // every person has a leg
		p.static_since_s = -kNever;  // all its legs on static structure
		p.leg_probability = 0.0;
	}
	for (size_t i = 0; i < m_frame.legs.size(); ++i)
	{
		const TLegObservation& leg = m_frame.legs[i];
		const size_t p = static_cast<size_t>(personOfLeg[i]);
		persons[p].leg_probability += leg.segment.leg_probability;
		legsOfPerson[p] += 1;
		persons[p].static_since_s = std::max(persons[p].static_since_s, leg.static_since_s);
		const TTrack* legTrack = m_legs.find(leg.leg_track);
		const bool legDynamic = legTrack && legTrack->state == ETrackState::dynamic;
		if ((!useEvidence || leg.in_free_space) && (!m_options.person_needs_dynamic_leg || legDynamic))
			persons[p].motion_evidence = true;
	}
	for (size_t p = 0; p < persons.size(); ++p)
	{
		persons[p].leg_probability /= std::max(1.0, legsOfPerson[p]);
		if (!usePersonEvidence) persons[p].motion_evidence = true;
	}
	const std::vector<int> personIds = m_persons.update(persons, sensorPose, t_s);
	for (size_t i = 0; i < m_frame.legs.size(); ++i)
	{
		TLegObservation& leg = m_frame.legs[i];
		leg.person_track = personIds[static_cast<size_t>(personOfLeg[i])];
		const TTrack* legTrack = m_legs.find(leg.leg_track);
		const TTrack* person = m_persons.find(leg.person_track);
		leg.is_dynamic = (legTrack && legTrack->state == ETrackState::dynamic) ||
						 (person && person->state == ETrackState::dynamic);
	}
}

std::vector<TTrackObservation> CDynamicObjectFilter::legObservations(const std::vector<mrpt::math::TPoint2D>& legsWorld,
																	 const mrpt::poses::CPose2D& sensorPose, double t_s,
																	 bool useEvidence)
{
	for (size_t i = 0; i < legsWorld.size(); ++i) m_frame.legs[i].in_free_space = seenFreeBefore(legsWorld[i], sensorPose);
	if (m_options.camera_cues.enabled) markCameraCueEvidence(t_s);
	std::vector<TTrackObservation> observations(legsWorld.size());
	for (size_t i = 0; i < legsWorld.size(); ++i)
	{
		TLegObservation& leg = m_frame.legs[i];
		if (m_options.static_evidence) leg.static_since_s = m_static.staticSince(legsWorld[i], t_s);
		observations[i] = {legsWorld[i], !useEvidence || leg.in_free_space, leg.static_since_s,
						   leg.segment.leg_probability};
	}
	return observations;
}

const TDynamicFrame& CDynamicObjectFilter::process(const mrpt::obs::CObservation2DRangeScan& scan,
												   const mrpt::poses::CPose2D& robotPose, double t_s)
{
	m_frame = TDynamicFrame();
	m_frame.scan_index = m_scans++;
	m_frame.pending_since_scan = m_frame.scan_index + 1;
	m_frame.t_s = t_s;
	m_frame.robot_pose = robotPose;
	std::vector<mrpt::math::TPoint2D> legsWorld;
	for (const auto& segment : m_detector.detect(scan))
	{
		m_frame.legs.push_back({segment});
		mrpt::math::TPoint2D w;
		robotPose.composePoint(segment.x_m, segment.y_m, w.x, w.y);
		legsWorld.push_back(w);
	}
	const mrpt::poses::CPose2D sensorPose = robotPose + mrpt::poses::CPose2D(scan.sensorPose);
	const bool useEvidence = m_options.tracker.confirm_free_hits > 0;
	const std::vector<int> legIds = m_legs.update(legObservations(legsWorld, sensorPose, t_s, useEvidence), sensorPose, t_s);
	for (size_t i = 0; i < legIds.size(); ++i) m_frame.legs[i].leg_track = legIds[i];
	updatePersonTracks(legsWorld, sensorPose, t_s, useEvidence);
	m_frame.leg_tracks = m_legs.tracks();
	m_frame.person_tracks = m_persons.tracks();
	buildMask(scan, robotPose);
	if (m_options.retro_clear_max_points > 0) collectLateExclusions(scan, robotPose);
	if (useEvidence) m_seenInserter.insert(m_seen, robotPose, scan, &m_frame.beam_is_dynamic);
	if (m_options.static_evidence) m_static.insert(scan, robotPose, t_s, &m_frame.beam_is_dynamic);
	return m_frame;
}

void CDynamicObjectFilter::collectLateExclusions(const mrpt::obs::CObservation2DRangeScan& scan,
												 const mrpt::poses::CPose2D& robotPose)
{
	// 1. Persons confirmed by now: release what they left in the map before.
	for (const auto& t : m_frame.person_tracks)
	{
		const auto it = m_pendingHits.find(t.id);
		if (t.state != ETrackState::dynamic || it == m_pendingHits.end()) continue;
		m_frame.retro_clear_beams.insert(m_frame.retro_clear_beams.end(), it->second.begin(), it->second.end());
		m_pendingHits.erase(it);
	}
	// 2. Beams inserted as occupied now that would have been masked if their
	// person were confirmed: its leg segments, and for a tentative person
	// the beams ending within mask_radius_m of it. Each beam counts once.
	const size_t n = scan.getScanSize();
	std::vector<int> personOfBeam(n, -1);
	for (const auto& leg : m_frame.legs)
		if (!leg.is_dynamic)
			for (size_t b = leg.segment.first_beam; b <= leg.segment.last_beam; ++b) personOfBeam[b] = leg.person_track;
	struct TDisc
	{
		int id;
		mrpt::math::TPoint2D centre;  // robot frame
		double r2;
	};
	std::vector<TDisc> tentative;
	for (const auto& t : m_frame.person_tracks)
		if (t.state == ETrackState::tentative && t.observation >= 0)
			tentative.push_back({t.id, robotPose.inverseComposePoint(t.position()), std::pow(maskRadius(t), 2)});
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	const size_t cap = static_cast<size_t>(m_options.retro_clear_max_points);
	for (size_t b = 0; b < n; ++b)
	{
		const double r = scan.getScanRange(b);
		if (m_frame.beam_is_dynamic[b] || !scan.getScanRangeValidity(b) || !std::isfinite(r)) continue;
		const double a = beamBearing(scan, b);
		const double x = sx + r * std::cos(a), y = sy + r * std::sin(a);
		for (size_t k = 0; k < tentative.size() && personOfBeam[b] < 0; ++k)
		{
			const auto& p = tentative[k].centre;
			if ((x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) <= tentative[k].r2) personOfBeam[b] = tentative[k].id;
		}
		if (personOfBeam[b] < 0) continue;
		auto& pending = m_pendingHits[personOfBeam[b]];
		pending.push_back({m_frame.scan_index, b});
		if (pending.size() > cap) pending.erase(pending.begin());
	}
	for (auto it = m_pendingHits.begin(); it != m_pendingHits.end();)
		it = m_persons.find(it->first) ? std::next(it) : m_pendingHits.erase(it);
	for (const auto& [id, pending] : m_pendingHits)
		if (!pending.empty()) m_frame.pending_since_scan = std::min(m_frame.pending_since_scan, pending.front().scan);
}

void CDynamicObjectFilter::buildMask(const mrpt::obs::CObservation2DRangeScan& scan,
									 const mrpt::poses::CPose2D& robotPose)
{
	const size_t n = scan.getScanSize();
	auto& mask = m_frame.beam_is_dynamic;
	mask.assign(n, false);
	const size_t margin = static_cast<size_t>(m_options.mask_margin_beams);
	for (const auto& leg : m_frame.legs)
	{
		if (!leg.is_dynamic) continue;
		const auto& l = leg.segment;
		const size_t from = l.first_beam >= margin ? l.first_beam - margin : 0;
		const size_t to = std::min(n - 1, l.last_beam + margin);
		for (size_t b = from; b <= to; ++b) mask[b] = true;
	}
	// Beams ending near a dynamic person (robot frame positions of the tracks).
	std::vector<std::pair<mrpt::math::TPoint2D, double>> persons;  // robot-frame centre, radius^2
	for (const auto& t : m_frame.person_tracks)
		if (t.state == ETrackState::dynamic && m_options.mask_radius_m > 0)
			persons.push_back({robotPose.inverseComposePoint(t.position()), std::pow(maskRadius(t), 2)});
	if (persons.empty()) return;
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	for (size_t b = 0; b < n; ++b)
	{
		const double r = scan.getScanRange(b);
		if (mask[b] || !scan.getScanRangeValidity(b) || !std::isfinite(r)) continue;
		const double a = beamBearing(scan, b);
		const double x = sx + r * std::cos(a), y = sy + r * std::sin(a);
		for (const auto& [p, r2] : persons)
			if ((x - p.x) * (x - p.x) + (y - p.y) * (y - p.y) <= r2)
			{
				mask[b] = true;
				break;
			}
	}
}

}  // namespace hslam::dynamic
