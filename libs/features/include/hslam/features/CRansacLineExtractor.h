/* hslam: RANSAC line extraction by MRPT (RANSAC_Template, as mrpt::math::ransac_detect_2D_lines),
 * the second comparison method of thesis 4.4.3 iii (table 3; thesis
 * settings: inlier distance 50 mm, >= 5 inliers).
 *
 * MRPT returns infinite lines (and their inlier counts), found one after the
 * other, each removing its inliers. They are turned into segments here: the
 * valid points are given to the nearest line within distance_threshold_m
 * (MRPT gives each point to the first line found, so a corner point could go
 * to the wrong wall); each line's points, in beam order, are cut where
 * two consecutive ones are more than max_point_gap_m apart (so one infinite
 * line through two separate walls, or through a wall and a stray point on
 * its extension, does not become one segment); each piece is refitted by TLS
 * (eq. 57-64) and kept if it has >= min_points points and >= min_length_m.
 *
 * MRPT draws its random samples from mrpt::random::getRandomGenerator(), a
 * process-wide generator: results vary from call to call unless the caller
 * seeds it (tests and the bench do). */
#pragma once

#include <hslam/features/CLineExtractor.h>

namespace hslam::features
{
class CRansacLineExtractor : public CLineExtractor
{
   public:
	struct TOptions
	{
		double distance_threshold_m = 0.05;  //!< inlier distance (thesis 50 mm)
		int min_inliers = 5;  //!< MRPT's minimum inliers per infinite line (thesis 5)
		double max_point_gap_m = 0.5;  //!< consecutive inliers farther apart split a segment
		int min_points = 5;
		double min_length_m = 0.2;
		/** MRPT's RANSAC (a COutputLogger) prints one INFO line per line it
		 * looks for; if set, its verbosity is LVL_ERROR (nothing else is touched). */
		bool silence_mrpt_log = true;

		template <class V>
		void visit(V& v)
		{
			v.real("distance_threshold_m", distance_threshold_m, 0.001, 1.0);
			v.integer("min_inliers", min_inliers, 2, 10000);
			v.real("max_point_gap_m", max_point_gap_m, 0.01, 100.0);
			v.integer("min_points", min_points, 2, 10000);
			v.real("min_length_m", min_length_m, 0.0, 100.0);
			v.flag("silence_mrpt_log", silence_mrpt_log);
		}
	};

	CRansacLineExtractor() : CRansacLineExtractor(TOptions()) {}
	explicit CRansacLineExtractor(const TOptions& options) : m_options(options) {}

	std::string name() const override { return "ransac"; }
	using CLineExtractor::extract;
	TLineSegmentList extract(const common::TRangeData& scan) const override;
	void saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const override;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace hslam::features
