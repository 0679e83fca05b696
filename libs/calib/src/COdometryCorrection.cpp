/* hslam calib: COdometryCorrection (thesis 4.1, eq. 25-28). */
#include <hslam/calib/COdometryCorrection.h>

#include <cmath>

namespace hslam::calib
{
mrpt::poses::CPose2D arcIncrement(double ds, double dphi)
{
	// Chord 2 (ds/dphi) sin(dphi/2) along the mean heading dphi/2.
	const double chord = std::abs(dphi) > 1e-9 ? 2.0 * ds / dphi * std::sin(0.5 * dphi) : ds;
	return mrpt::poses::CPose2D(chord * std::cos(0.5 * dphi), chord * std::sin(0.5 * dphi), dphi);
}

void COdometryCorrection::correctWheelTravel(double dL, double dR, double& ds, double& dphi) const
{
	const double b = m_opts.nominal_wheelbase_m;
	if (!m_opts.enabled)
	{
		ds = 0.5 * (dL + dR);
		dphi = (dR - dL) / b;
		return;
	}
	const double cL = m_opts.left_factor * dL, cR = m_opts.right_factor * dR;
	ds = 0.5 * (cL + cR);
	dphi = (cR - cL) / (m_opts.wheelbase_ratio * b);
}

mrpt::poses::CPose2D COdometryCorrection::correctIncrement(const mrpt::poses::CPose2D& inc) const
{
	if (!m_opts.enabled) return inc;
	// Invert the arc: chord c at mean heading dphi/2 -> arc length ds.
	const double dphi = inc.phi();
	const double chord = std::hypot(inc.x(), inc.y());
	const double sign = inc.x() * std::cos(0.5 * dphi) + inc.y() * std::sin(0.5 * dphi) < 0 ? -1.0 : 1.0;
	const double ds = std::abs(dphi) > 1e-9 ? sign * chord * (0.5 * dphi) / std::sin(0.5 * dphi) : sign * chord;
	const double b = m_opts.nominal_wheelbase_m;
	double ds2 = 0, dphi2 = 0;
	correctWheelTravel(ds - 0.5 * dphi * b, ds + 0.5 * dphi * b, ds2, dphi2);
	return arcIncrement(ds2, dphi2);
}

}  // namespace hslam::calib
