/* hslam: the extractor factory (see CLineExtractor.h). */
#include <hslam/common/options_io.h>
#include <hslam/features/CDerivativeLineExtractor.h>
#include <hslam/features/CIepLineExtractor.h>
#include <hslam/features/CLineExtractor.h>
#include <hslam/features/CRansacLineExtractor.h>

namespace hslam::features
{
namespace
{
template <class TExtractor>
std::unique_ptr<CLineExtractor> build(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	typename TExtractor::TOptions options;
	hslam::common::loadOptions(options, cfg, section);
	return std::make_unique<TExtractor>(options);
}
}  // namespace

std::vector<std::string> lineExtractorMethods() { return {"derivative", "iep", "ransac"}; }

std::string lineExtractorSection(const std::string& method) { return "line_extraction_" + method; }

std::unique_ptr<CLineExtractor> createLineExtractor(const std::string& method,
													 const mrpt::config::CConfigFileBase& cfg,
													 const std::string& section)
{
	if (method == "derivative") return build<CDerivativeLineExtractor>(cfg, section);
	if (method == "iep") return build<CIepLineExtractor>(cfg, section);
	if (method == "ransac") return build<CRansacLineExtractor>(cfg, section);
	throw hslam::common::config_error("line extraction method '" + method +
									  "' is unknown (available: derivative, iep, ransac)");
}

}  // namespace hslam::features
