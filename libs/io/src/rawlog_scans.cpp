#include <hslam/io/rawlog_scans.h>

namespace hslam::io
{
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> readRangeScans(const std::string& rawlogPath)
{
	CRawlogReader reader(rawlogPath);
	TRawlogEntry entry;
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	while (reader.next(entry))
	{
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(entry.observation))
			scans.push_back(s);
		if (entry.frame)
			for (const auto& o : *entry.frame)
				if (auto s2 = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) scans.push_back(s2);
	}
	return scans;
}

std::vector<TRawlogEntry> readRawlogEntries(const std::string& rawlogPath)
{
	CRawlogReader reader(rawlogPath);
	std::vector<TRawlogEntry> entries;
	for (TRawlogEntry e; reader.next(e);) entries.push_back(e);
	return entries;
}

}  // namespace hslam::io
