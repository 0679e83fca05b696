#include <hslam/matching/CIcpMatcher.h>
#include <hslam/matching/alignment_fit.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CICP.h>

#include <algorithm>
#include <cmath>
#include <mrpt/math/wrap2pi.h>
#include <Eigen/LU>
#include <vector>

namespace hslam::matching
{
namespace
{
mrpt::slam::CICP::TConfigParams toMrpt(const CIcpMatcher::TOptions& o)
{
	mrpt::slam::CICP::TConfigParams p;
	p.ICP_algorithm = o.algorithm == "classic" ? mrpt::slam::icpClassic : mrpt::slam::icpLevenbergMarquardt;
	p.maxIterations = static_cast<unsigned>(o.max_iterations);
	p.thresholdDist = o.threshold_dist_m;
	p.thresholdAng = o.threshold_ang_rad;
	p.ALFA = o.alfa;
	p.smallestThresholdDist = o.smallest_threshold_dist_m;
	p.minAbsStep_trans = static_cast<float>(o.min_step_m);
	p.minAbsStep_rot = static_cast<float>(o.min_step_rad);
	p.onlyUniqueRobust = o.only_unique_robust;
	p.corresponding_points_decimation = static_cast<uint32_t>(o.decimation);
	// MRPT's own (finite-difference) covariance is only wanted when it is the
	// one reported; the geometric one replaces it otherwise (finished()).
	p.skip_cov_calculation = o.covariance != "mrpt";
	return p;
}

CPointToPointIcp::TOptions toCached(const CIcpMatcher::TOptions& o)
{
	CPointToPointIcp::TOptions c;
	c.max_iterations = o.max_iterations;
	c.threshold_dist_m = o.threshold_dist_m;
	c.threshold_ang_rad = o.threshold_ang_rad;
	c.alfa = o.alfa;
	c.smallest_threshold_dist_m = o.smallest_threshold_dist_m;
	c.min_step_m = o.min_step_m;
	c.min_step_rad = o.min_step_rad;
	c.only_unique_robust = o.only_unique_robust;
	c.decimation = o.decimation;
	c.cached_neighbours = o.cached_neighbours;
	c.stage_step_fraction = o.stage_step_fraction;
	return c;
}
}  // namespace

CIcpMatcher::CIcpMatcher(const TOptions& options) : m_options(options), m_cached(toCached(options)) {}

namespace
{
/** True when every result lies within (max_m, max_rad) of the first. */
bool allInOneBasin(const std::vector<TPoseMatch>& results, double max_m, double max_rad)
{
	const auto& first = results.front().pose;
	for (const auto& r : results)
		if (std::hypot(r.pose.x() - first.x(), r.pose.y() - first.y()) > max_m ||
			std::abs(mrpt::math::wrapToPi(r.pose.phi() - first.phi())) > max_rad)
			return false;
	return true;
}
}  // namespace

template <class AlignAt>
TPoseMatch CIcpMatcher::bestOfRestarts(AlignAt alignAt, const mrpt::poses::CPose2D& initialGuess,
									   const Eigen::Matrix3d& initialCov, bool pairsSideBySide) const
{
	TPoseMatch best = alignAt(initialGuess);
	best.seeds_aligned = 1;
	// A first result pairing most points can still be a wrong basin that
	// fits badly (csail, t = 328 s: 78 deg turned in 1 s, odometry said 108;
	// ICP ended 1.9 m and 25 deg off, goodness 0.82, fit 0.51; the restart
	// from 30 deg back fitted 0.84 at the right pose).
	const bool lowFit = restartsOnFit() && best.fit < m_options.restart_below_fit;
	// A result pairing few points (below min_good_points) is no evidence of
	// one basin either, however many of them it pairs: a scanner that sees two
	// pillars pairs "all" its points in several places.
	const bool fewPoints = m_options.restart_below_good_points && pairsTooFewPoints(best);
	if (best.score >= m_options.restart_below_goodness && !lowFit && !fewPoints) return best;
	const double step = std::clamp(std::sqrt(std::max(0.0, initialCov(2, 2))), m_options.restart_min_step_rad,
								   m_options.restart_max_step_rad);
	// Among results paired about as well as the best one (within
	// restart_goodness_tolerance), keep the one closest to the prior
	// (Mahalanobis): a wrong basin can pair marginally more points.
	std::vector<TPoseMatch> candidates{best};
	// the seeds turned by +steps and -steps, side by side when allowed (same order either way)
	const auto alignTurnedPair = [&](double steps)
	{
		TPoseMatch turned[2];
		const auto alignOne = [&](size_t k)
		{ turned[k] = alignAt(initialGuess + mrpt::poses::CPose2D(0, 0, (k == 0 ? steps : -steps) * step)); };
		if (pairsSideBySide && m_restartPool) m_restartPool->run(2, alignOne);
		else alignOne(0), alignOne(1);
		candidates.push_back(turned[0]), candidates.push_back(turned[1]);
	};
	alignTurnedPair(1);
	// The +-1 seeds landing where the first result did (most restarts: aces,
	// 178 of 202 changed the result by < 2 cm / 0.5 deg) say the basin is
	// wide; the +-2 seeds would land there too.
	const bool oneBasin = m_options.restart_same_basin_m > 0 &&
		allInOneBasin(candidates, m_options.restart_same_basin_m, m_options.restart_same_basin_rad);
	if (!oneBasin) alignTurnedPair(2);
	double bestScore = 0;
	for (const auto& c : candidates) bestScore = std::max(bestScore, c.score);
	const Eigen::Matrix3d priorInfo = (initialCov + Eigen::Matrix3d::Identity() * 1e-9).inverse();
	double bestDistance = 1e300;
	for (const auto& c : candidates)
	{
		if (c.score < bestScore - m_options.restart_goodness_tolerance) continue;
		const Eigen::Vector3d d(c.pose.x() - initialGuess.x(), c.pose.y() - initialGuess.y(),
								mrpt::math::wrapToPi(c.pose.phi() - initialGuess.phi()));
		const double distance = d.dot(priorInfo * d);
		if (distance < bestDistance) bestDistance = distance, best = c;
	}
	best.seeds_aligned = candidates.size();
	return best;
}

TPoseMatch CIcpMatcher::match(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
							  const mrpt::poses::CPose2D& initialGuess, const Eigen::Matrix3d& initialCov) const
{
	if (reference.size() < 10 || current.size() < 10)
	{
		TPoseMatch failed;
		failed.method = "icp";
		return failed;  // too few points
	}
	const auto alignAt = [&](const mrpt::poses::CPose2D& seed)
	{
		TPoseMatch m = alignOnce(reference, current, seed, initialCov);
		if (restartsOnFit()) m.fit = fit(reference, current, m.pose);
		return m;
	};
	// MRPT's CICP builds the reference's k-d tree on first use: not side by side
	return finished(bestOfRestarts(alignAt, initialGuess, initialCov, false), reference, current);
}

TPoseMatch CIcpMatcher::match(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
							  const mrpt::poses::CPose2D& initialGuess, const Eigen::Matrix3d& initialCov) const
{
	TPoseMatch failed;
	failed.method = "icp";
	if (reference.size() < 10 || current.size() < 10) return failed;  // too few points
	const float* xs = current.getPointsBufferRef_x().data();
	const float* ys = current.getPointsBufferRef_y().data();
	const auto alignAt = [&](const mrpt::poses::CPose2D& seed)
	{
		const auto r = m_cached.align(reference, xs, ys, current.size(), seed);
		TPoseMatch m = failed;
		m.pose = r.pose;
		m.score = r.goodness;
		m.correspondences = static_cast<size_t>(std::lround(r.goodness * current.size()));
		if (restartsOnFit()) m.fit = fit(reference, current, m.pose);
		return m;
	};
	TPoseMatch best = bestOfRestarts(alignAt, initialGuess, initialCov, true);
	const bool refined = m_options.point_to_line_steps > 0;
	if (refined)
		best.pose = refinedAlongNormals(reference, current, best.pose, m_options.geometric, m_options.point_to_line_steps);
	best.covariance = geometricAlignmentCovariance(reference, current, best.pose, m_options.geometric);
	if (refined || !restartsOnFit())  // else alignAt computed it at this pose
		best.fit = fit(reference, current, best.pose);
	return withQuality(best);
}

TPoseMatch CIcpMatcher::alignOnce(const mrpt::maps::CSimplePointsMap& reference,
								  const mrpt::maps::CSimplePointsMap& current, const mrpt::poses::CPose2D& initialGuess,
								  const Eigen::Matrix3d& initialCov) const
{
	TPoseMatch result;
	result.method = "icp";
	mrpt::slam::CICP icp(toMrpt(m_options));
	mrpt::math::CMatrixDouble33 cov0;
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) cov0(r, c) = initialCov(r, c);
	const mrpt::poses::CPosePDFGaussian seed(initialGuess, cov0);
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.AlignPDF(&reference, &current, seed, info);
	mrpt::poses::CPosePDFGaussian gaussian;
	gaussian.copyFrom(*pdf);
	result.pose = gaussian.mean;
	result.score = info.goodness;

	result.correspondences = static_cast<size_t>(std::lround(info.goodness * current.size()));
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) result.covariance(r, c) = gaussian.cov(r, c);
	return result;
}

TPoseMatch CIcpMatcher::finished(TPoseMatch result, const mrpt::maps::CSimplePointsMap& reference,
								 const mrpt::maps::CSimplePointsMap& current) const
{
	// The geometric covariance (kNN normals of every point) is computed once,
	// for the chosen result, not for every restart.
	if (m_options.covariance == "geometric")
		result.covariance = geometricAlignmentCovariance(reference, current, result.pose, m_options.geometric);
	result.fit = fit(reference, current, result.pose);
	return withQuality(std::move(result));
}

double CIcpMatcher::fit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
						const mrpt::poses::CPose2D& pose) const
{
	return alignmentFit(reference, current, pose, m_options.seed_fit_sigma_m, m_options.seed_fit_max_segment_m);
}

double CIcpMatcher::fit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
						const mrpt::poses::CPose2D& pose) const
{
	return alignmentFit(reference, current, pose, m_options.seed_fit_sigma_m, m_options.seed_fit_max_segment_m);
}

bool CIcpMatcher::pairsTooFewPoints(const TPoseMatch& result) const
{
	return result.correspondences < static_cast<size_t>(m_options.min_good_points);
}

bool CIcpMatcher::restartsOnFit() const { return m_options.restart_below_fit > 0 && m_options.seed_fit_sigma_m > 0; }

TPoseMatch CIcpMatcher::withQuality(TPoseMatch result) const
{
	result.covariance(0, 0) += m_options.min_xy_std_m * m_options.min_xy_std_m;
	result.covariance(1, 1) += m_options.min_xy_std_m * m_options.min_xy_std_m;
	result.covariance(2, 2) += m_options.min_theta_std_rad * m_options.min_theta_std_rad;
	if (!result.covariance.allFinite()) return result;
	result.quality = result.score < m_options.fail_goodness  ? EMatchQuality::failed
					 : result.score < m_options.min_goodness ? EMatchQuality::weak
															 : EMatchQuality::good;
	if (result.quality == EMatchQuality::good && pairsTooFewPoints(result)) result.quality = EMatchQuality::weak;
	return result;
}

}  // namespace hslam::matching
