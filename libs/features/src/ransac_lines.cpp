/* hslam features (internal): detectRansacLines (see ransac_lines.h). */
#include "ransac_lines.h"

#include <mrpt/math/CMatrixDynamic.h>
#include <mrpt/math/ransac.h>

#include <exception>

namespace hslam::features::detail
{
namespace
{
using TPoints = mrpt::math::CMatrixDynamic<double>;  //!< 2 x N: row 0 x, row 1 y
using TModel = mrpt::math::CMatrixDynamic<double>;  //!< 1 x 3: line coefficients a, b, c

mrpt::math::TPoint2D pointAt(const TPoints& points, size_t i) { return {points(0, i), points(1, i)}; }

/** The line through the two sampled points (none if they coincide). */
void fitLine(const TPoints& points, const std::vector<size_t>& sample, std::vector<TModel>& models)
{
	models.clear();
	try
	{
		const mrpt::math::TLine2D line(pointAt(points, sample[0]), pointAt(points, sample[1]));
		TModel model(1, 3);
		for (int k = 0; k < 3; ++k) model(0, k) = line.coefs[k];
		models.push_back(model);
	}
	catch (const std::exception&)
	{
		// Coincident points: no model from this sample.
	}
}

/** Points closer than the threshold to the (only) model. */
void inliersOf(const TPoints& points, const std::vector<TModel>& models, double threshold_m, unsigned int& best,
			   std::vector<size_t>& inliers)
{
	inliers.clear();
	best = 0;
	if (models.empty()) return;
	const mrpt::math::TLine2D line(models[0](0, 0), models[0](0, 1), models[0](0, 2));
	for (size_t i = 0; i < static_cast<size_t>(points.cols()); ++i)
		if (line.distance(pointAt(points, i)) < threshold_m) inliers.push_back(i);
}

bool neverDegenerate(const TPoints&, const std::vector<size_t>&) { return false; }
}  // namespace

std::vector<std::pair<size_t, mrpt::math::TLine2D>> detectRansacLines(const mrpt::math::CVectorDynamic<double>& xs,
																	   const mrpt::math::CVectorDynamic<double>& ys,
																	   double threshold_m, size_t minInliers,
																	   mrpt::system::VerbosityLevel verbosity)
{
	std::vector<std::pair<size_t, mrpt::math::TLine2D>> lines;
	if (xs.size() == 0) return lines;
	TPoints remaining(2, xs.size());
	remaining.setRow(0, xs);
	remaining.setRow(1, ys);
	while (remaining.cols() >= 2)
	{
		mrpt::math::RANSAC_Template<double> ransac;
		ransac.setVerbosityLevel(verbosity);
		std::vector<size_t> inliers;
		TModel model;
		ransac.execute(remaining, fitLine, inliersOf, neverDegenerate, threshold_m, 2, inliers, model, 0.99999);
		if (inliers.size() < minInliers) break;
		lines.emplace_back(inliers.size(), mrpt::math::TLine2D(model(0, 0), model(0, 1), model(0, 2)));
		lines.back().second.unitarize();
		remaining.removeColumns(inliers);
	}
	return lines;
}

}  // namespace hslam::features::detail
