/* hslam calib: COdometrySelfCalibration (see the header for the model). */
#include <hslam/calib/COdometrySelfCalibration.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>

namespace hslam::calib
{
COdometrySelfCalibration::COdometrySelfCalibration(const TOdometrySelfCalibration& options, double nominalWheelbase_m)
	: m_opts(options), m_wheelbase_m(nominalWheelbase_m)
{
	m_state.correction.nominal_wheelbase_m = nominalWheelbase_m;
}

mrpt::poses::CPose2D COdometrySelfCalibration::correct(const mrpt::poses::CPose2D& odometry) const
{
	if (!m_opts.enabled || !m_state.correction.enabled) return odometry;
	return COdometryCorrection(m_state.correction).correctIncrement(odometry);
}

void COdometrySelfCalibration::observe(const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& fused)
{
	if (!m_opts.enabled) return;
	const double chord_m = std::hypot(odometry.x(), odometry.y());
	const double s = odometry.x() < 0 ? -chord_m : chord_m;  // signed odometric distance
	const double turn = odometry.phi();
	if (std::abs(s) > m_opts.max_interval_m) return;
	const double travel_m = std::abs(s) + 0.5 * m_wheelbase_m * std::abs(turn);  // mean wheel travel
	if (travel_m < 1e-3) return;
	// The fused distance, signed like s where it agrees with the odometry's direction.
	const double along = fused.x() * odometry.x() + fused.y() * odometry.y();
	const double matched = (along < 0 ? -1.0 : 1.0) * (s < 0 ? -1.0 : 1.0) * std::hypot(fused.x(), fused.y());
	const double y = mrpt::math::wrapToPi(fused.phi());
	const double distanceResidual = matched - m_state.distance_scale * s;
	const double headingResidual =
		y - (m_state.heading_scale * turn + m_state.curvature_bias_rad_per_m * s);
	if (std::abs(distanceResidual) > m_opts.max_distance_residual * std::abs(s) + 0.02 ||
		std::abs(headingResidual) > m_opts.max_heading_residual_rad)
	{
		++m_state.outliers;
		return;
	}
	const double w = 1.0 / travel_m;  // odometry error grows like a random walk in travel
	const double based = m_baseScale * s;
	m_sumMatchedDistance += w * matched * based;
	m_sumOdometryDistance += w * based * based;
	m_travelSinceRebase_m += std::abs(s);
	m_hh += w * turn * turn, m_hs += w * turn * s, m_ss += w * s * s;
	m_hy += w * turn * y, m_sy += w * s * y;
	m_state.travel_m += std::abs(s);
	++m_state.intervals;
	refit();
	rebaseIfDue();
}

void COdometrySelfCalibration::rebaseIfDue()
{
	if (m_opts.rebase_travel_m <= 0 || !m_state.correction.enabled || m_travelSinceRebase_m < m_opts.rebase_travel_m)
		return;
	// the prior now holds the fit at the scale reached (continuous: the
	// scale is unchanged until new intervals arrive)
	m_baseScale = m_state.distance_scale;
	m_sumMatchedDistance = m_sumOdometryDistance = 0;
	m_travelSinceRebase_m = 0;
	++m_state.rebases;
}

void COdometrySelfCalibration::refit()
{
	const double P = m_opts.prior_travel_m;
	const double lo = 1.0 - m_opts.max_scale_error, hi = 1.0 + m_opts.max_scale_error;
	auto& st = m_state;
	st.distance_scale = std::clamp(m_baseScale * (m_sumMatchedDistance + P) / (m_sumOdometryDistance + P), lo, hi);
	if (m_opts.estimate_heading)
	{
		// The prior's weight on b: P metres of wheel travel spent turning on
		// the spot is 2P/b rad, whose weighted square sum is 4P/b^2.
		const double Pb = 4.0 * P / (m_wheelbase_m * m_wheelbase_m);
		const double A = m_hh + Pb, B = m_hs, C = m_ss + P, det = A * C - B * B;
		const double rb = m_hy + Pb, rc = m_sy;
		st.heading_scale = std::clamp((C * rb - B * rc) / det, lo, hi);
		st.curvature_bias_rad_per_m = (A * rc - B * rb) / det;
	}
	// The fit as UMBmark factors (thesis eq. 25-28): with a = (c_L + c_R) / 2
	// and d = (c_R - c_L) / 2, COdometryCorrection turns a heading change into
	// dphi' = (a / Eb) dphi + (2 d / (Eb b)) ds, so Eb = a / b_fit and
	// d = c Eb b / 2.
	auto& corr = st.correction;
	if (std::abs(st.distance_scale - 1.0) > m_opts.min_scale_error) corr.enabled = true;  // and stays so
	corr.nominal_wheelbase_m = m_wheelbase_m;
	corr.wheelbase_ratio = std::clamp(st.distance_scale / st.heading_scale, lo, hi);
	const double d = st.curvature_bias_rad_per_m * corr.wheelbase_ratio * m_wheelbase_m / 2.0;
	corr.left_factor = std::clamp(st.distance_scale - d, lo, hi);
	corr.right_factor = std::clamp(st.distance_scale + d, lo, hi);
}

}  // namespace hslam::calib
