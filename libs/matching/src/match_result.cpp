#include <hslam/matching/match_result.h>

namespace hslam::matching
{
const char* toString(EMatchQuality quality)
{
	switch (quality)
	{
		case EMatchQuality::good: return "good";
		case EMatchQuality::weak: return "weak";
		case EMatchQuality::failed: return "failed";
	}
	return "?";
}
}  // namespace hslam::matching
