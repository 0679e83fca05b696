/* hslam nav: target list parsing. */
#include <hslam/common/parse_number.h>
#include <hslam/nav/CTargetSequence.h>

#include <sstream>
#include <stdexcept>

namespace hslam::nav
{
std::vector<mrpt::math::TPoint2D> parseTargetList(const std::string& text, const std::string& what)
{
	std::vector<mrpt::math::TPoint2D> out;
	std::stringstream all(text);
	std::string item;
	for (int n = 1; std::getline(all, item, ';'); ++n)
	{
		if (common::trim(item).empty()) continue;
		std::stringstream ss(item);
		std::string xs, ys, extra;
		ss >> xs >> ys >> extra;
		const auto x = common::tryParseDouble(xs), y = common::tryParseDouble(ys);
		if (!x || !y || !extra.empty())
			throw std::runtime_error(what + ": target " + std::to_string(n) + " must be 'x y' (m), got '" +
									 common::trim(item) + "'");
		out.push_back({*x, *y});
	}
	return out;
}
}  // namespace hslam::nav
