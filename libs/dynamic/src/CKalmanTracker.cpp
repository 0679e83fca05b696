#include <hslam/dynamic/CKalmanTracker.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hslam::dynamic
{
const char* toString(ETrackState s)
{
	switch (s)
	{
		case ETrackState::tentative: return "tentative";
		case ETrackState::dynamic: return "dynamic";
		case ETrackState::ghost: return "ghost";
	}
	return "?";
}

const TTrack* CKalmanTracker::find(int id) const
{
	for (const auto& t : m_tracks)
		if (t.id == id) return &t;
	return nullptr;
}

void CKalmanTracker::predict(TTrack& t, double t_s) const
{
	const double dt = std::max(0.0, t_s - t.t_last_s);
	t.t_last_s = std::max(t.t_last_s, t_s);
	if (dt <= 0) return;
	Eigen::Matrix4d F = Eigen::Matrix4d::Identity();
	F(0, 2) = F(1, 3) = dt;
	// Discrete white-noise acceleration, per axis [dt^4/4 dt^3/2; dt^3/2 dt^2] q.
	const double q = m_options.accel_noise_mps2 * m_options.accel_noise_mps2;
	Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();
	for (int a = 0; a < 2; ++a)
	{
		Q(a, a) = 0.25 * dt * dt * dt * dt * q;
		Q(a, a + 2) = Q(a + 2, a) = 0.5 * dt * dt * dt * q;
		Q(a + 2, a + 2) = dt * dt * q;
	}
	t.x = F * t.x;
	t.P = F * t.P * F.transpose() + Q;
}

void CKalmanTracker::correct(TTrack& t, const mrpt::math::TPoint2D& z) const
{
	Eigen::Matrix<double, 2, 4> H = Eigen::Matrix<double, 2, 4>::Zero();
	H(0, 0) = H(1, 1) = 1;
	const double r2 = m_options.measurement_noise_m * m_options.measurement_noise_m;
	const Eigen::Matrix2d S = H * t.P * H.transpose() + r2 * Eigen::Matrix2d::Identity();
	const Eigen::Matrix<double, 4, 2> K = t.P * H.transpose() * S.inverse();
	const Eigen::Vector2d innovation(z.x - t.x[0], z.y - t.x[1]);
	t.x += K * innovation;
	t.P = (Eigen::Matrix4d::Identity() - K * H) * t.P;
	const double v = t.speed_mps();  // a leg in swing can look fast; cap at a plausible speed
	if (v > m_options.max_speed_mps)
	{
		t.x[2] *= m_options.max_speed_mps / v;
		t.x[3] *= m_options.max_speed_mps / v;
	}
}

bool CKalmanTracker::inGate(const TTrack& t, const mrpt::math::TPoint2D& z, const mrpt::poses::CPose2D& sensorPose,
							double t_s) const
{
	// Polar coordinates of the prediction and of the observation in the
	// current sensor frame: eq. 88-89 with the full pose change.
	const auto p = sensorPose.inverseComposePoint(mrpt::math::TPoint2D(t.x[0], t.x[1]));
	const auto o = sensorPose.inverseComposePoint(z);
	const double rp = std::hypot(p.x, p.y), ro = std::hypot(o.x, o.y);
	const double dth = std::abs(mrpt::math::wrapToPi(std::atan2(o.y, o.x) - std::atan2(p.y, p.x)));
	if (m_options.gate_speed_mps > 0)
	{
		// Metric gate (beyond the thesis): how far a leg can be from its
		// constant-velocity prediction after the time since it was last seen,
		// the same in range and across, whatever the distance to the sensor.
		const double g = m_options.gate_speed_mps * std::max(t_s - t.t_seen_s, 1e-3);
		return std::abs(ro - rp) <= g && ro * dth <= g;
	}
	const double widen = 1.0 + t.misses;
	if (std::abs(ro - rp) > m_options.gate_range_m * widen) return false;
	const double gate = std::max(m_options.gate_bearing_rad, m_options.gate_min_cross_m / std::max(ro, 0.05));
	return dth <= gate * widen;
}

void CKalmanTracker::updatePolar(TTrack& t, const mrpt::poses::CPose2D& sensorPose) const
{
	const double dx = t.x[0] - sensorPose.x(), dy = t.x[1] - sensorPose.y();
	t.range_m = std::hypot(dx, dy);
	t.bearing_rad = mrpt::math::wrapToPi(std::atan2(dy, dx) - sensorPose.phi());
	if (t.range_m < 1e-9) return;
	const double ux = dx / t.range_m, uy = dy / t.range_m;
	t.v_radial_mps = t.x[2] * ux + t.x[3] * uy;
	t.v_angular_radps = (-t.x[2] * uy + t.x[3] * ux) / t.range_m;
}

TTrack CKalmanTracker::newTrack(const mrpt::math::TPoint2D& z, const mrpt::poses::CPose2D& sensorPose, double t_s)
{
	TTrack t;
	t.id = m_nextId++;
	t.x << z.x, z.y, 0, 0;
	const double r2 = m_options.measurement_noise_m * m_options.measurement_noise_m;
	const double v2 = 0.25 * m_options.max_speed_mps * m_options.max_speed_mps;
	t.P = Eigen::Vector4d(r2, r2, v2, v2).asDiagonal();
	t.t_last_s = t.t_seen_s = t.t_birth_s = t_s;
	t.hits = 1;
	t.birth_m = z;
	t.sensor_birth_m = sensorPose.inverseComposePoint(z);
	return t;
}

bool CKalmanTracker::significantSpeed(const TTrack& t) const
{
	// Speed squared in units of its own covariance (Mahalanobis distance of
	// the velocity from zero): pose noise and detector jitter give a speed
	// the filter itself deems uncertain; a walking person a sustained one.
	const Eigen::Vector2d v(t.x[2], t.x[3]);
	const Eigen::Matrix2d Pv = t.P.bottomRightCorner<2, 2>();
	const double sigma2 = m_options.confirm_speed_sigma * m_options.confirm_speed_sigma;
	return v.norm() >= m_options.confirm_speed_mps && v.dot(Pv.ldlt().solve(v)) >= sigma2;
}

bool CKalmanTracker::meetsConfirmation(const TTrack& t) const
{
	const auto& o = m_options;
	// Moved in the world (not static) AND relative to the sensor (not a part
	// of the robot or something it carries, which moves with it).
	const bool relative = !o.confirm_relative_motion || t.sensor_travel_m >= o.confirm_travel_m;
	// Static-world evidence (CStaticEvidenceGrid): never on an observation
	// lying on established static structure, nor while too many of the
	// track's observations lay on structure that stood there before the
	// track was born (a track hopping between chair legs, or jumping off them
	// when the pose slips). Structure established later may be the track's
	// own object standing still (a person waiting), which may walk off.
	if (t.on_static || t.static_hits > o.confirm_max_static_fraction * t.hits) return false;
	// Shape evidence over the track's life (CLegClassifier probabilities).
	if (t.leg_probability_sum < o.confirm_min_leg_probability * t.hits) return false;
	return t.travel_m >= o.confirm_travel_m && relative && t.hits >= o.confirm_hits &&
		   t.free_hits >= o.confirm_free_hits && t.moving_frames >= o.confirm_moving_frames;
}

void CKalmanTracker::registerHit(TTrack& t, const TTrackObservation& obs, const mrpt::poses::CPose2D& sensorPose) const
{
	const mrpt::math::TPoint2D& z = obs.position_m;
	++t.hits;
	t.leg_probability_sum += obs.leg_probability;
	t.on_static = std::isfinite(obs.static_since_s);
	t.static_hits += obs.static_since_s <= t.t_birth_s;
	t.misses = 0;
	t.free_hits += obs.motion_evidence;
	t.travel_m = std::max(t.travel_m, std::hypot(z.x - t.birth_m.x, z.y - t.birth_m.y));
	const auto zs = sensorPose.inverseComposePoint(z);
	t.sensor_travel_m = std::max(t.sensor_travel_m, std::hypot(zs.x - t.sensor_birth_m.x, zs.y - t.sensor_birth_m.y));
	t.moving_frames = significantSpeed(t) ? t.moving_frames + 1 : 0;
	if (meetsConfirmation(t))
		t.state = ETrackState::dynamic;
	else if (t.state == ETrackState::tentative && t.hits >= m_options.ghost_after_frames)
		t.state = ETrackState::ghost;
}

void CKalmanTracker::takeOverFromMemory(double t_s, std::vector<int>& owner)
{
	// A younger track (not a ghost) near where a remembered one would be now
	// is the same object
	// (the observation jumped out of the old track's gate, e.g. a person seen
	// by one leg, then by both): it takes over the remembered identity.
	for (auto m = m_memory.begin(); m != m_memory.end();)
	{
		const TTrack& old = m->track;
		const double dt = std::min(t_s - m->t_lost_s, 1.0);
		TTrack* heir = nullptr;
		double bestD = m_options.memory_gate_m;
		for (auto& t : m_tracks)
		{
			if (t.state == ETrackState::ghost || t.id < old.id)
				continue;
			const double d = std::min(std::hypot(t.x[0] - old.x[0], t.x[1] - old.x[1]),
									  std::hypot(t.x[0] - old.x[0] - old.x[2] * dt, t.x[1] - old.x[1] - old.x[3] * dt));
			if (d <= bestD) bestD = d, heir = &t;
		}
		if (!heir)
		{
			++m;
			continue;
		}
		std::replace(owner.begin(), owner.end(), heir->id, old.id);
		heir->id = old.id;
		// The identity is taken over at once; the dynamic state only when the
		// heir itself passes the confirmation rule with the world travel of
		// the old track (clutter next to a lost person must not inherit it).
		heir->birth_m = old.birth_m;
		heir->travel_m = std::max(heir->travel_m, old.travel_m);
		if (meetsConfirmation(*heir)) heir->state = ETrackState::dynamic;
		++m_reidentified;
		m = m_memory.erase(m);
	}
}

std::vector<int> CKalmanTracker::associate(const std::vector<TTrackObservation>& observations,
										   const mrpt::poses::CPose2D& sensorPose, double t_s,
										   std::vector<bool>& trackUsed)
{
	std::vector<std::tuple<double, size_t, size_t>> pairs;  // distance, track, observation
	for (size_t ti = 0; ti < m_tracks.size(); ++ti)
		for (size_t oi = 0; oi < observations.size(); ++oi)
		{
			const auto& z = observations[oi].position_m;
			if (inGate(m_tracks[ti], z, sensorPose, t_s))
				pairs.emplace_back(std::hypot(z.x - m_tracks[ti].x[0], z.y - m_tracks[ti].x[1]), ti, oi);
		}
	std::sort(pairs.begin(), pairs.end());
	std::vector<int> owner(observations.size(), -1);
	trackUsed.assign(m_tracks.size(), false);
	for (auto& t : m_tracks) t.observation = -1;
	for (const auto& [d, ti, oi] : pairs)
	{
		if (trackUsed[ti] || owner[oi] >= 0) continue;
		trackUsed[ti] = true;
		TTrack& t = m_tracks[ti];
		owner[oi] = t.id;
		t.observation = static_cast<int>(oi);
		t.t_seen_s = t_s;
		correct(t, observations[oi].position_m);
		registerHit(t, observations[oi], sensorPose);
	}
	return owner;
}

void CKalmanTracker::dropMissedTracks(const std::vector<bool>& trackUsed)
{
	std::vector<TTrack> kept;
	for (size_t ti = 0; ti < m_tracks.size(); ++ti)
	{
		TTrack& t = m_tracks[ti];
		if (!trackUsed[ti] && ++t.misses >= m_options.max_misses)
		{
			if (t.state == ETrackState::dynamic) m_memory.push_back({t, t.t_seen_s});
			continue;
		}
		kept.push_back(t);
	}
	m_tracks.swap(kept);
}

std::vector<CKalmanTracker::TMemory>::iterator CKalmanTracker::rememberedNear(const mrpt::math::TPoint2D& z, double t_s)
{
	auto best = m_memory.end();
	double bestD = m_options.memory_gate_m;
	for (auto m = m_memory.begin(); m != m_memory.end(); ++m)
	{
		const TTrack& old = m->track;
		const double dt = std::min(t_s - m->t_lost_s, 1.0);  // extrapolate at most 1 s
		const double dLast = std::hypot(z.x - old.x[0], z.y - old.x[1]);
		const double dCv = std::hypot(z.x - old.x[0] - old.x[2] * dt, z.y - old.x[1] - old.x[3] * dt);
		const double d = std::min(dLast, dCv);
		if (d <= bestD)
		{
			bestD = d;
			best = m;
		}
	}
	return best;
}

TTrack CKalmanTracker::startTrack(const TTrackObservation& z, const mrpt::poses::CPose2D& sensorPose, double t_s)
{
	const auto best = rememberedNear(z.position_m, t_s);
	TTrack t = newTrack(z.position_m, sensorPose, t_s);
	t.free_hits = z.motion_evidence;
	t.on_static = std::isfinite(z.static_since_s);
	t.static_hits = z.static_since_s <= t_s;
	t.leg_probability_sum = z.leg_probability;
	if (best == m_memory.end()) return t;
	--m_nextId;  // the remembered id is reused
	const TTrack& old = best->track;
	t.id = old.id;
	// Identity comes back at once; the dynamic state when the new track
	// passes the confirmation rule with the old track's world travel
	// and counts (at once for the thesis rule; with the relative-motion
	// test once it has moved relative to the sensor; else clutter next
	// to a lost person, or the robot's own body, would inherit it).
	t.birth_m = old.birth_m;
	t.travel_m = old.travel_m;
	t.hits = old.hits + 1;
	t.leg_probability_sum = old.leg_probability_sum + z.leg_probability;
	t.free_hits = old.free_hits + z.motion_evidence;
	t.t_birth_s = old.t_birth_s;  // the same object: its static-world record too
	t.static_hits = old.static_hits + (z.static_since_s <= t.t_birth_s);
	if (z.motion_evidence && meetsConfirmation(t)) t.state = ETrackState::dynamic;
	m_memory.erase(best);
	++m_reidentified;
	return t;
}

std::vector<int> CKalmanTracker::update(const std::vector<TTrackObservation>& observations,
										const mrpt::poses::CPose2D& sensorPose, double t_s)
{
	for (auto& t : m_tracks) predict(t, t_s);
	std::vector<bool> trackUsed;
	std::vector<int> owner = associate(observations, sensorPose, t_s, trackUsed);
	dropMissedTracks(trackUsed);
	takeOverFromMemory(t_s, owner);
	m_memory.erase(std::remove_if(m_memory.begin(), m_memory.end(),
								  [&](const TMemory& m) { return t_s - m.t_lost_s > m_options.memory_s; }),
				   m_memory.end());
	// New tracks, or re-identified remembered ones.
	for (size_t oi = 0; oi < observations.size(); ++oi)
	{
		if (owner[oi] >= 0) continue;
		TTrack t = startTrack(observations[oi], sensorPose, t_s);
		owner[oi] = t.id;
		t.observation = static_cast<int>(oi);
		m_tracks.push_back(t);
	}
	for (auto& t : m_tracks) updatePolar(t, sensorPose);
	return owner;
}

}  // namespace hslam::dynamic
