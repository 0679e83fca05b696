#include <hslam/fusion/CAdaptiveMeasurementNoise.h>

#include <algorithm>
#include <cmath>

namespace hslam::fusion
{
CAdaptiveMeasurementNoise::CAdaptiveMeasurementNoise(const TOptions& options)
	: m_options(options), m_scale(std::max(1.0, options.min_scale))
{
	m_scale = std::clamp(m_scale, m_options.min_scale, m_options.max_scale);
}

Eigen::Matrix3d CAdaptiveMeasurementNoise::effectiveCovariance(const Eigen::Matrix3d& claimed, bool weak) const
{
	return claimed * (m_options.enabled ? m_scale : 1.0) * (weak ? m_options.weak_match_factor : 1.0);
}

void CAdaptiveMeasurementNoise::observeNis(double nis)
{
	if (!m_options.enabled || !std::isfinite(nis)) return;
	const double ratio = std::max(nis, 1e-6) / 3.0;  // expected NIS of 3 dof
	m_scale = std::clamp(m_scale * std::pow(ratio, m_options.rate), m_options.min_scale, m_options.max_scale);
}

}  // namespace hslam::fusion
