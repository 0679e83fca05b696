/* hslam: point-to-point ICP refinement through MRPT's mrpt::slam::CICP, the
 * combination of feature and point matching the thesis proposes as future
 * work (4.5.5, 5.2): used when the line matcher is weak (corridors, clutter)
 * or always, seeded by the line (or odometry) estimate.
 *
 * Multi-start: ICP only converges from seeds inside its basin; a heading
 * error of 10-20 deg (seen on real logs after sharp turns) is outside it. When
 * the first result pairs fewer than restart_below_goodness of the points, or
 * fits the reference worse than restart_below_fit (alignment_fit.h: a wrong
 * basin can pair most points), or pairs fewer than min_good_points
 * (restart_below_good_points: a few points pair perfectly in several
 * basins), ICP is restarted from seeds rotated by +-1 and +-2 steps (step = the seed's
 * heading standard deviation, clamped to [restart_min_step, restart_max_step])
 * and, among the results paired nearly as well as the best, the one closest
 * to the prior (Mahalanobis distance) is kept.
 *
 * MRPT's ICP covariance is computed from the point residuals and is usually
 * overconfident on laser data; it is floored here and further adapted online
 * by fusion::CAdaptiveMeasurementNoise. */
#pragma once

#include <hslam/common/CTaskPool.h>
#include <hslam/matching/CPointToPointIcp.h>
#include <hslam/matching/competing_basins.h>
#include <hslam/matching/icp_covariance.h>
#include <hslam/matching/match_result.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <memory>

namespace hslam::matching
{
class CIcpMatcher
{
   public:
	struct TOptions
	{
		/** "mrpt": mrpt::slam::CICP on a CSimplePointsMap reference; "cached":
		 * CPointToPointIcp (the same classic algorithm, exact nearest
		 * neighbours cached between iterations; with stage_step_fraction > 0
		 * its coarse stages end early) on a CPointIndex2D. The defaults here
		 * are config_ini/hslam-default.ini's (a key left out of an INI means
		 * the shipped default; test ConfigRoundTrip.AKeyLeftOutTakesTheShippedDefault). */
		std::string engine = "cached";
		int cached_neighbours = 4;  //!< candidates kept per scan point (engine = cached)
		double stage_step_fraction = 0.01;  //!< engine = cached: coarse stages end early (0 = MRPT's rule)
		/** The scan's points seen at grazing incidence are not aligned (the
		 * keyframes keep them as reference): pointsOffGrazingIncidence() in
		 * scan_points.h. 0 = off. */
		double max_incidence_rad = 0;
		std::string algorithm = "classic";  //!< MRPT ICP_algorithm: "classic" or "levenberg_marquardt"
		int max_iterations = 80;
		double threshold_dist_m = 0.5;  //!< initial pairing distance (MRPT thresholdDist)
		double threshold_ang_rad = 5.0 * M_PI / 180.0;  //!< pairing distance growth with range (MRPT thresholdAng)
		double alfa = 0.6;  //!< threshold shrink factor after each convergence (MRPT ALFA)
		double smallest_threshold_dist_m = 0.05;  //!< final pairing distance (MRPT smallestThresholdDist)
		/** A pairing threshold is kept until one iteration moves the pose
		 * less than this (MRPT minAbsStep_trans / minAbsStep_rot). */
		double min_step_m = 1e-6;
		double min_step_rad = 1e-6;
		bool only_unique_robust = true;  //!< unique correspondences in both directions
		int decimation = 1;  //!< use every k-th point of the scan (MRPT corresponding_points_decimation)
		double min_goodness = 0.5;  //!< below: weak match (fraction of points paired at the end)
		double fail_goodness = 0.2;  //!< below: failed
		/** A match pairing fewer scan points than this is weak at best, however
		 * large its goodness: a handful of returns (a short-range scanner in an
		 * open hall: two pillars and a crate corner) pair "all" their points in
		 * many places. 0 = by goodness only. */
		int min_good_points = 50;
		double restart_below_goodness = 0.7;  //!< multi-start when the first goodness is lower; 0 = never
		/** ...or when its fit (seed_fit_sigma_m) is lower; 0 = by goodness only. */
		double restart_below_fit = 0.7;
		/** ...or when it pairs fewer than min_good_points scan points: few
		 * points pair perfectly in several basins. */
		bool restart_below_good_points = true;
		double restart_goodness_tolerance = 0.05;  //!< results this close to the best goodness compete on prior distance
		/** Point-to-line steps after point-to-point ICP (engine = cached;
		 * icp_covariance.h refinedAlongNormals); 0 = none. */
		int point_to_line_steps = 0;
		double restart_min_step_rad = 3.0 * M_PI / 180.0;
		double restart_max_step_rad = 15.0 * M_PI / 180.0;
		/** The +-2-step seeds are skipped when the first result and both
		 * +-1-step results lie within this distance and angle of each other
		 * (one basin); 0 m = always all four seeds. */
		double restart_same_basin_m = 0.02;
		double restart_same_basin_rad = 0.5 * M_PI / 180.0;
		/** Sigma (m) of the fit that chooses between the results of several
		 * seeds (alignment_fit.h); 0 = by goodness, a later seed winning only
		 * by more than restart_goodness_tolerance. */
		double seed_fit_sigma_m = 0.05;
		/** The fit's distance is to the nearest reference segment at most
		 * this long (alignment_fit.h); 0 = to the nearest point. */
		double seed_fit_max_segment_m = 0.0;
		/** A match checking odometry's claim that the robot stood still (a
		 * timed match after no travel, CScanMatchingPoseEstimator::
		 * icpForThisMatch) uses these instead of
		 * point_to_line_steps and seed_fit_max_segment_m: its reference
		 * scan was, if the claim is true, taken from the same pose, and
		 * point-to-point measures then favour zero motion (alignment_fit.h). */
		int standstill_point_to_line_steps = 10;
		double standstill_fit_max_segment_m = 0.5;
		/** Results of other seeds that fit about as well widen the chosen
		 * one's covariance (competing_basins.h). */
		TCompetingBasinOptions competing;
		std::string covariance = "geometric";  //!< "geometric" (icp_covariance.h) or "mrpt" (CICP's own)
		TGeometricCovarianceOptions geometric = frontEndGeometric();
		double min_xy_std_m = 0.02;  //!< covariance floor (laser noise, map blur)
		double min_theta_std_rad = 0.5 * M_PI / 180.0;

		/** The front-end's geometric covariance: information per length of
		 * wall, and directions constrained by fewer than 15 % of the points
		 * left to the prediction (the library's own defaults keep both off). */
		static TGeometricCovarianceOptions frontEndGeometric()
		{
			TGeometricCovarianceOptions g;
			g.full_weight_spacing_m = 0.05;
			g.degenerate_min_fraction = 0.15;
			return g;
		}

		template <class V>
		void visit(V& v)
		{
			v.choice("engine", engine, {"mrpt", "cached"});
			v.integer("cached_neighbours", cached_neighbours, 1, 16);
			v.real("stage_step_fraction", stage_step_fraction, 0.0, 1.0);
			v.degrees("max_incidence_deg", max_incidence_rad, 0.0, 89.0);
			v.choice("algorithm", algorithm, {"classic", "levenberg_marquardt"});
			v.integer("max_iterations", max_iterations, 1, 1000);
			v.real("threshold_dist_m", threshold_dist_m, 0.01, 10.0);
			v.degrees("threshold_ang_deg", threshold_ang_rad, 0.0, 45.0);
			v.real("alfa", alfa, 0.05, 0.99);
			v.real("smallest_threshold_dist_m", smallest_threshold_dist_m, 0.001, 5.0);
			v.real("min_step_m", min_step_m, 0.0, 0.1);
			v.degrees("min_step_deg", min_step_rad, 0.0, 5.0);
			v.flag("only_unique_robust", only_unique_robust);
			v.integer("decimation", decimation, 1, 100);
			v.real("min_goodness", min_goodness, 0.0, 1.0);
			v.real("fail_goodness", fail_goodness, 0.0, 1.0);
			v.integer("min_good_points", min_good_points, 0, 100000);
			v.real("restart_below_goodness", restart_below_goodness, 0.0, 1.0);
			v.real("restart_below_fit", restart_below_fit, 0.0, 1.0);
			v.flag("restart_below_good_points", restart_below_good_points);
			v.integer("point_to_line_steps", point_to_line_steps, 0, 50);
			v.real("restart_goodness_tolerance", restart_goodness_tolerance, 0.0, 1.0);
			v.degrees("restart_min_step_deg", restart_min_step_rad, 0.1, 90.0);
			v.degrees("restart_max_step_deg", restart_max_step_rad, 0.1, 90.0);
			v.real("restart_same_basin_m", restart_same_basin_m, 0.0, 1.0);
			v.degrees("restart_same_basin_deg", restart_same_basin_rad, 0.0, 45.0);
			v.real("seed_fit_sigma_m", seed_fit_sigma_m, 0.0, 1.0);
			v.real("seed_fit_max_segment_m", seed_fit_max_segment_m, 0.0, 10.0);
			v.integer("standstill_point_to_line_steps", standstill_point_to_line_steps, 0, 50);
			v.real("standstill_fit_max_segment_m", standstill_fit_max_segment_m, 0.0, 10.0);
			v.real("competing_fit_ratio", competing.fit_ratio, 0.0, 1.0);
			v.real("competing_min_chi2", competing.min_distance_chi2, 0.0, 1000.0);
			v.choice("covariance", covariance, {"geometric", "mrpt"});
			v.integer("covariance_normal_neighbours", geometric.normal_neighbours, 3, 50);
			v.real("covariance_max_match_distance_m", geometric.max_match_distance_m, 0.01, 5.0);
			v.real("covariance_min_sigma_m", geometric.min_sigma_m, 1e-4, 1.0);
			v.real("covariance_correlation_factor", geometric.correlation_factor, 1.0, 1000.0);
			v.real("covariance_full_weight_spacing_m", geometric.full_weight_spacing_m, 0.0, 1.0);
			v.real("covariance_degenerate_min_fraction", geometric.degenerate_min_fraction, 0.0, 1.0);
			v.real("min_xy_std_m", min_xy_std_m, 1e-4, 1.0);
			v.degrees("min_theta_std_deg", min_theta_std_rad, 0.001, 10.0);
		}
	};

	CIcpMatcher() : CIcpMatcher(TOptions()) {}
	explicit CIcpMatcher(const TOptions& options);

	/** Pose of the `current` points (robot frame) in the frame of `reference`,
	 * starting from `initialGuess` with uncertainty `initialCov`. */
	TPoseMatch match(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
					 const mrpt::poses::CPose2D& initialGuess, const Eigen::Matrix3d& initialCov) const;

	/** The same with the reference in a CPointIndex2D (engine = cached;
	 * classic algorithm only). */
	TPoseMatch match(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
					 const mrpt::poses::CPose2D& initialGuess, const Eigen::Matrix3d& initialCov) const;

	/** alignmentFit of `current` at `pose` with this matcher's fit options
	 * (seed_fit_sigma_m, seed_fit_max_segment_m). */
	double fit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
			   const mrpt::poses::CPose2D& pose) const;
	double fit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
			   const mrpt::poses::CPose2D& pose) const;

	const TOptions& options() const { return m_options; }

	/** Threads on which the restarts' +-k seed pairs run side by side
	 * (engine = cached: the two alignments only read the reference). The
	 * candidates keep their order, so the result is the one-thread one.
	 * Null (the default): one after the other. Shared by copies. */
	void setRestartPool(std::shared_ptr<common::CTaskPool> pool) { m_restartPool = std::move(pool); }

   private:
	/** Whether a first result is also restarted on its fit (restart_below_fit, seed_fit_sigma_m > 0). */
	bool restartsOnFit() const;
	/** Fewer paired points than min_good_points: weak at best, and restarted
	 * (restart_below_good_points) however well they pair. */
	bool pairsTooFewPoints(const TPoseMatch& result) const;
	/** The first alignment, or the best of the restarts around the prior. */
	template <class AlignAt>
	TPoseMatch bestOfRestarts(AlignAt alignAt, const mrpt::poses::CPose2D& initialGuess,
							  const Eigen::Matrix3d& initialCov, bool pairsSideBySide) const;
	/** The chosen result's floors and quality (its covariance already set). */
	TPoseMatch withQuality(TPoseMatch result) const;
	/** One MRPT ICP run: pose, score and MRPT's covariance (no floors, no quality yet). */
	TPoseMatch alignOnce(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
						 const mrpt::poses::CPose2D& seed, const Eigen::Matrix3d& seedCov) const;
	/** The chosen result's covariance (geometric or MRPT's), floors and quality. */
	TPoseMatch finished(TPoseMatch result, const mrpt::maps::CSimplePointsMap& reference,
						const mrpt::maps::CSimplePointsMap& current) const;

	TOptions m_options;
	CPointToPointIcp m_cached;
	std::shared_ptr<common::CTaskPool> m_restartPool;
};

}  // namespace hslam::matching
