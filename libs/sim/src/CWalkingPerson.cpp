/* hslam sim: CWalkingPerson gait model. */
#include <hslam/sim/CWalkingPerson.h>

#include <cmath>
#include <stdexcept>

namespace hslam::sim
{
using mrpt::math::TPoint2D;
using mrpt::math::TVector2D;

CWalkingPerson::CWalkingPerson(TPersonSpec spec) : m_spec(std::move(spec))
{
	if (m_spec.waypoints.size() < 2)
		throw std::invalid_argument("person " + std::to_string(m_spec.id) + ": needs at least 2 waypoints");
	if (!(m_spec.speed_mps > 0) || !(m_spec.leg_radius_m > 0) || !(m_spec.step_length_m > 0))
		throw std::invalid_argument("person " + std::to_string(m_spec.id) +
									": speed, leg radius and step length must be > 0");
	m_path = m_spec.waypoints;
	if (m_spec.loop)
		m_path.push_back(m_spec.waypoints.front());
	else
		for (size_t k = m_spec.waypoints.size() - 1; k-- > 0;) m_path.push_back(m_spec.waypoints[k]);
	m_cumulative.assign(1, 0.0);
	for (size_t k = 1; k < m_path.size(); ++k)
		m_cumulative.push_back(m_cumulative.back() +
							   std::hypot(m_path[k].x - m_path[k - 1].x, m_path[k].y - m_path[k - 1].y));
	m_length = m_cumulative.back();
	if (!(m_length > 0)) throw std::invalid_argument("person " + std::to_string(m_spec.id) + ": path has zero length");
}

void CWalkingPerson::pointAt(double s, TPoint2D& p, TVector2D& tangent) const
{
	if (s < 0 && !m_spec.loop)
	{
		// Behind the start of an open path (the trailing leg at t = 0): extend the first piece backwards.
		const TPoint2D& a = m_path[0];
		const TPoint2D& b = m_path[1];
		const double piece = std::max(1e-12, m_cumulative[1]);
		tangent = TVector2D{(b.x - a.x) / piece, (b.y - a.y) / piece};
		p = TPoint2D{a.x + s * tangent.x, a.y + s * tangent.y};
		return;
	}
	s = std::fmod(s, m_length);
	if (s < 0) s += m_length;
	size_t k = 1;
	while (k + 1 < m_cumulative.size() && m_cumulative[k] < s) ++k;
	// Skip zero-length pieces (repeated waypoints).
	while (k + 1 < m_cumulative.size() && m_cumulative[k] - m_cumulative[k - 1] <= 0) ++k;
	const double piece = m_cumulative[k] - m_cumulative[k - 1];
	const double u = piece > 0 ? std::clamp((s - m_cumulative[k - 1]) / piece, 0.0, 1.0) : 0.0;
	const TPoint2D& a = m_path[k - 1];
	const TPoint2D& b = m_path[k];
	p = TPoint2D{a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)};
	tangent = piece > 0 ? TVector2D{(b.x - a.x) / piece, (b.y - a.y) / piece} : TVector2D{1, 0};
}

TPersonState CWalkingPerson::stateAt(double t_s) const
{
	TPersonState st;
	st.id = m_spec.id;
	const double walking_s = std::max(0.0, t_s - m_spec.start_delay_s);
	const double s = m_spec.speed_mps * walking_s;  // body arc length
	TVector2D tangent;
	pointAt(s, st.body, tangent);
	st.heading_rad = std::atan2(tangent.y, tangent.x);

	const double l = m_spec.step_length_m;
	const long k = static_cast<long>(std::floor(s / l));  // half-cycle index
	const double u = s / l - static_cast<double>(k);  // phase within the half-cycle, [0, 1)
	const int stanceLeg = static_cast<int>(k % 2);
	const double sStance = (static_cast<double>(k) + 0.5) * l;  // footprint under the stance leg
	const double sSwing = (static_cast<double>(k) - 0.5 + 2.0 * u) * l;  // from behind to ahead at 2v
	const bool moving = t_s > m_spec.start_delay_s;
	for (int leg = 0; leg < 2; ++leg)
	{
		const bool stance = !moving || leg == stanceLeg;
		const double sLeg = (leg == stanceLeg) ? sStance : sSwing;
		TPoint2D p;
		TVector2D tg;
		pointAt(sLeg, p, tg);
		const double side = leg == 0 ? 1.0 : -1.0;  // leg 0 on the left of the walking direction
		st.legs[leg] = TPoint2D{p.x - side * m_spec.hip_half_width_m * tg.y, p.y + side * m_spec.hip_half_width_m * tg.x};
		st.stance[leg] = stance;
	}
	return st;
}

std::vector<TCircle> CWalkingPerson::legCirclesAt(double t_s) const
{
	const TPersonState st = stateAt(t_s);
	std::vector<TCircle> out;
	for (int leg = 0; leg < 2; ++leg)
		out.push_back(TCircle{st.legs[leg], m_spec.leg_radius_m, TObjectTag{EObjectKind::person_leg, m_spec.id, leg}});
	return out;
}

}  // namespace hslam::sim
