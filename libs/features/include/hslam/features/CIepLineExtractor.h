/* hslam: iterative end point fit / split-and-merge line extraction, the
 * first comparison method of thesis 4.4.3 i (table 3).
 *
 * Per run of consecutive valid beams (invalid beams end a run): split where
 * two neighbouring points are more than max_point_gap_m apart; then, while a
 * point lies farther than split_distance_m from the chord joining the first
 * and last point of its set (thesis: 100 mm), split the set at that point
 * (steps 1-6); move boundary points to the line they fit best; merge
 * neighbouring sets whose TLS fits differ by less than merge_angle_deg and
 * whose merged fit stays within split_distance_m, unless the facing ends are
 * more than max_point_gap_m apart (step 7, "merge collinear sets"); fit each
 * set by TLS (eq. 57-64) and keep sets with >= min_points points and
 * >= min_length_m. The thesis notes that IEP drew lines across step gaps and
 * proposed a minimum point count against it: that is min_points here, and
 * the gap split removes the cause. */
#pragma once

#include <hslam/features/CLineExtractor.h>

namespace hslam::features
{
class CIepLineExtractor : public CLineExtractor
{
   public:
	struct TOptions
	{
		double split_distance_m = 0.1;  //!< chord distance that splits a set (thesis 100 mm)
		double merge_angle_rad = 10.0 * M_PI / 180;  //!< collinear-merge direction limit
		double max_point_gap_m = 0.5;  //!< neighbouring points farther apart are never one line
		int min_points = 5;
		double min_length_m = 0.2;

		template <class V>
		void visit(V& v)
		{
			v.real("split_distance_m", split_distance_m, 0.001, 1.0);
			v.degrees("merge_angle_deg", merge_angle_rad, 0.0, 45.0);
			v.real("max_point_gap_m", max_point_gap_m, 0.01, 100.0);
			v.integer("min_points", min_points, 2, 10000);
			v.real("min_length_m", min_length_m, 0.0, 100.0);
		}
	};

	CIepLineExtractor() : CIepLineExtractor(TOptions()) {}
	explicit CIepLineExtractor(const TOptions& options) : m_options(options) {}

	std::string name() const override { return "iep"; }
	using CLineExtractor::extract;
	TLineSegmentList extract(const common::TRangeData& scan) const override;
	void saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const override;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace hslam::features
