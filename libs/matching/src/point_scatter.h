/* hslam matching (private): the scatter of a few points about their
 * centroid, the PCA behind every local normal fit in this library. */
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>

namespace hslam::matching::detail
{
/** Eigen-decomposition of the scatter matrix of n points (point(j), j < n,
 * an Eigen::Vector2d) about their centroid: eigenvalues ascending, so
 * eigenvectors().col(0) is the normal of a line through them. */
template <class PointAt>
Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> scatterOf(size_t n, PointAt point)
{
	Eigen::Vector2d mean = Eigen::Vector2d::Zero();
	for (size_t j = 0; j < n; ++j) mean += point(j);
	mean /= static_cast<double>(n);
	Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
	for (size_t j = 0; j < n; ++j)
	{
		const Eigen::Vector2d d = point(j) - mean;
		scatter += d * d.transpose();
	}
	return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter);
}

}  // namespace hslam::matching::detail
