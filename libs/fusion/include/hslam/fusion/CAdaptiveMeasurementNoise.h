/* hslam: online adaptation of the scan-match measurement covariance, the
 * thesis' future work (5.2: "adapt the measurement covariance"): a matcher
 * whose claimed covariance is consistently too optimistic (its innovations
 * are larger than its covariance says) is trusted less, one that is right is
 * trusted as claimed.
 *
 * The claimed covariance R is multiplied by a scale s and by a quality factor
 * (weak matches count less). After each update s moves in log space towards
 * the ratio NIS / 3 (3 = expected NIS of a consistent 3-dof measurement):
 *     log s <- log s + rate * log(NIS / 3),  clamped to [min_scale, max_scale].
 * (MRPT's ICP covariance, for example, is known to be overconfident.) */
#pragma once

#include <Eigen/Core>

namespace hslam::fusion
{
class CAdaptiveMeasurementNoise
{
   public:
	struct TOptions
	{
		bool enabled = true;  //!< false: R is used as claimed (times the quality factor)
		double rate = 0.1;  //!< adaptation gain per update (0..1)
		double min_scale = 1.0;  //!< never trust a matcher more than it claims
		double max_scale = 100.0;
		double weak_match_factor = 10.0;  //!< R multiplier for matches flagged weak

		template <class V>
		void visit(V& v)
		{
			v.flag("adaptive_enabled", enabled);
			v.real("adaptive_rate", rate, 0.0, 1.0);
			v.real("adaptive_min_scale", min_scale, 1e-3, 1e6);
			v.real("adaptive_max_scale", max_scale, 1e-3, 1e6);
			v.real("weak_match_factor", weak_match_factor, 1.0, 1e6);
		}
	};

	CAdaptiveMeasurementNoise() : CAdaptiveMeasurementNoise(TOptions()) {}
	explicit CAdaptiveMeasurementNoise(const TOptions& options);

	/** Covariance to use for a match claiming `claimed`. */
	Eigen::Matrix3d effectiveCovariance(const Eigen::Matrix3d& claimed, bool weak) const;
	/** Feeds back the NIS of an update made with effectiveCovariance(). */
	void observeNis(double nis);
	double scale() const { return m_scale; }

   private:
	TOptions m_options;
	double m_scale;
};

}  // namespace hslam::fusion
