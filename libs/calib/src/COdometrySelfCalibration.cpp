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
	// until the heading terms are applied, the heading model is the nominal one
	const bool heading = m_state.heading_applied;
	const double headingResidual =
		y - ((heading ? m_state.heading_scale : 1.0) * turn + (heading ? m_state.curvature_bias_rad_per_m : 0.0) * s);
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
	m_sumMatchedSquared += w * matched * matched;
	++m_intervalsSinceRebase;
	m_travelSinceRebase_m += std::abs(s);
	m_hh += w * turn * turn, m_hs += w * turn * s, m_ss += w * s * s;
	m_hy += w * turn * y, m_sy += w * s * y, m_yy += w * y * y;
	m_state.travel_m += std::abs(s);
	++m_state.intervals;
	refit();
	rebaseIfDue();
}

double COdometrySelfCalibration::distanceScaleError() const
{
	const double P = m_opts.prior_travel_m;
	const double a = (m_sumMatchedDistance + P) / (m_sumOdometryDistance + P);  // relative to the base scale
	const double ssr =
		std::max(0.0, m_sumMatchedSquared - 2 * a * m_sumMatchedDistance + a * a * m_sumOdometryDistance);
	const double sigma2 = ssr / std::max<double>(1.0, static_cast<double>(m_intervalsSinceRebase) - 1.0);
	return m_baseScale * std::sqrt(sigma2 / (m_sumOdometryDistance + P));
}

void COdometrySelfCalibration::fitHeading()
{
	auto& st = m_state;
	const double P = m_opts.prior_travel_m;
	// The prior's weight on b: P metres of wheel travel spent turning on
	// the spot is 2P/b rad, whose weighted square sum is 4P/b^2.
	const double Pb = 4.0 * P / (m_wheelbase_m * m_wheelbase_m);
	const double A = m_hh + Pb, B = m_hs, C = m_ss + P, det = A * C - B * B;
	const double rb = m_hy + Pb, rc = m_sy;
	const double b = (C * rb - B * rc) / det, c = (A * rc - B * rb) / det;
	st.heading_scale = std::clamp(b, 1.0 - m_opts.max_scale_error, 1.0 + m_opts.max_scale_error);
	st.curvature_bias_rad_per_m = c;
	// Standard errors from the residuals (weights 1 / travel: the heading
	// error per unit weight is the odometry's random walk per metre).
	const double ssr = std::max(0.0, m_yy - 2 * b * m_hy - 2 * c * m_sy + b * b * m_hh + 2 * b * c * m_hs + c * c * m_ss);
	const double sigma2 = ssr / std::max<double>(1.0, static_cast<double>(st.intervals) - 2.0);
	const double k = m_opts.min_heading_significance;
	const bool scaleOff = std::abs(b - 1.0) > std::max(m_opts.min_heading_scale_error, k * std::sqrt(sigma2 * C / det));
	const bool curved = std::abs(c) > std::max(m_opts.min_curvature_rad_per_m, k * std::sqrt(sigma2 * A / det));
	if (scaleOff || curved) st.heading_applied = true;  // and stays so
}

void COdometrySelfCalibration::rebaseIfDue()
{
	if (m_opts.rebase_travel_m <= 0 || !m_state.distance_applied || m_travelSinceRebase_m < m_opts.rebase_travel_m)
		return;
	// the prior now holds the fit at the scale reached (continuous: the
	// scale is unchanged until new intervals arrive)
	m_baseScale = m_state.distance_scale;
	m_sumMatchedDistance = m_sumOdometryDistance = m_sumMatchedSquared = 0;
	m_intervalsSinceRebase = 0;
	m_travelSinceRebase_m = 0;
	++m_state.rebases;
}

void COdometrySelfCalibration::refit()
{
	const double P = m_opts.prior_travel_m;
	const double lo = 1.0 - m_opts.max_scale_error, hi = 1.0 + m_opts.max_scale_error;
	auto& st = m_state;
	st.distance_scale = std::clamp(m_baseScale * (m_sumMatchedDistance + P) / (m_sumOdometryDistance + P), lo, hi);
	if (m_opts.estimate_heading) fitHeading();
	// The fit as UMBmark factors (thesis eq. 25-28): with a = (c_L + c_R) / 2
	// and d = (c_R - c_L) / 2, COdometryCorrection turns a heading change into
	// dphi' = (a / Eb) dphi + (2 d / (Eb b)) ds, so Eb = a / b_fit and
	// d = c Eb b / 2.
	// Each part is applied once its fit leaves its band, and stays so.
	if (std::abs(st.distance_scale - 1.0) > std::max(m_opts.min_scale_error, m_opts.min_scale_significance * distanceScaleError()))
		st.distance_applied = true;
	const double a = st.distance_applied ? st.distance_scale : 1.0;
	const double b = st.heading_applied ? st.heading_scale : 1.0;
	const double c = st.heading_applied ? st.curvature_bias_rad_per_m : 0.0;
	auto& corr = st.correction;
	corr.enabled = st.distance_applied || st.heading_applied;
	corr.nominal_wheelbase_m = m_wheelbase_m;
	corr.wheelbase_ratio = std::clamp(a / b, lo, hi);
	const double d = c * corr.wheelbase_ratio * m_wheelbase_m / 2.0;
	corr.left_factor = std::clamp(a - d, lo, hi);
	corr.right_factor = std::clamp(a + d, lo, hi);
}

}  // namespace hslam::calib
