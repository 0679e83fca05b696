/* hslam: closed-form SE(2) point-set alignment. */
#include <hslam/eval/se2_alignment.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hslam::eval
{
using mrpt::math::TPoint2D;

namespace
{
TPoint2D centroid(const std::vector<TPoint2D>& points)
{
	TPoint2D c(0, 0);
	for (const auto& p : points) c += p;
	return c / static_cast<double>(points.size());
}

}  // namespace

mrpt::poses::CPose2D alignPointsSE2(const std::vector<TPoint2D>& from, const std::vector<TPoint2D>& to)
{
	if (from.empty() || from.size() != to.size())
		throw std::invalid_argument("alignPointsSE2: need two non-empty point lists of equal size, got " +
									std::to_string(from.size()) + " and " + std::to_string(to.size()));
	const TPoint2D fromCentre = centroid(from), toCentre = centroid(to);
	double sumDot = 0, sumCross = 0;
	for (size_t k = 0; k < from.size(); ++k)
	{
		const TPoint2D a = from[k] - fromCentre, b = to[k] - toCentre;
		sumDot += a.x * b.x + a.y * b.y;
		sumCross += a.x * b.y - a.y * b.x;
	}
	const double phi = std::atan2(sumCross, sumDot);
	const double c = std::cos(phi), s = std::sin(phi);
	return mrpt::poses::CPose2D(toCentre.x - (c * fromCentre.x - s * fromCentre.y),
								toCentre.y - (s * fromCentre.x + c * fromCentre.y), phi);
}

}  // namespace hslam::eval
