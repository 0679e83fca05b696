/* hslam: one interface for the three laser line extractors compared in thesis
 * Table 3 (4.4.2 i derivative segmentation, 4.4.3 i iterative end point fit /
 * split-and-merge, 4.4.3 ii RANSAC via MRPT), so that `[line_extraction]
 * method` in the INI selects any of them. */
#pragma once

#include <hslam/common/range_data.h>
#include <hslam/features/line_segment.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::features
{
class CLineExtractor
{
   public:
	virtual ~CLineExtractor() = default;
	/** "derivative", "iep" or "ransac". */
	virtual std::string name() const = 0;
	/** Lines of one scan, in the robot frame (the scan's sensorPose applied),
	 * ordered by first_beam. Invalid beams (validity flag off, NaN, <= 0, or
	 * at/after the scanner's maxRange) are never part of a line. */
	virtual TLineSegmentList extract(const common::TRangeData& scan) const = 0;
	/** Convenience for tools and tests: builds the scan's range data first. */
	TLineSegmentList extract(const mrpt::obs::CObservation2DRangeScan& scan) const
	{
		return extract(common::makeRangeData(scan));
	}
	/** Writes every option into `section` (the inverse of loading them
	 * there), so a run's config_used.ini holds the extractor's settings. */
	virtual void saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const = 0;
};

/** The method names createLineExtractor() accepts: derivative, iep, ransac. */
std::vector<std::string> lineExtractorMethods();

/** Conventional INI section of a method's options: "line_extraction_<method>"
 * (the `method` key itself lives in [line_extraction], read by the caller). */
std::string lineExtractorSection(const std::string& method);

/** Builds the extractor named `method` with its options read from INI section
 * `section` of `cfg` (unknown keys and out-of-range values throw
 * hslam::common::config_error; so does an unknown
 * method). Usually section = lineExtractorSection(method). */
std::unique_ptr<CLineExtractor> createLineExtractor(const std::string& method,
													 const mrpt::config::CConfigFileBase& cfg,
													 const std::string& section);

}  // namespace hslam::features
