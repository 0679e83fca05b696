/* hslam vision: focus of expansion (FOE) from residual flow (thesis 4.8.1 ii,
 * 4.8.2 iv).
 *
 * Two estimators on the same vectors (those longer than the noise threshold:
 * the thesis measured 0.2 px of flow at rest and kept vectors longer than
 * 10 x that):
 *  - voteFoe: the thesis's counting scheme. The image is cut into columns (10
 *    of 64 px at 640 x 480); every vector adds +500 to its column if it points
 *    right, -500 if left, 0 if vertical; the FOE x is the middle of the column
 *    where the column sums cross zero (the one of the two nearest zero). The
 *    same on rows gives y (the thesis found y "close to the centre" and left
 *    it). Resolution: one column.
 *  - estimateFoe: least squares in x and y. A residual vector (u, v) at (x, y)
 *    lies on a line through the FOE (x0, y0): v x0 - u y0 = v x - u y. Each
 *    row is divided by the vector's length so its residual is the distance of
 *    the FOE from the vector's line (px). RANSAC (pairs of lines, inliers
 *    within ransac_inlier_px + ransac_inlier_noise_px x D / |flow|, where D
 *    is the vector's distance from the FOE: end-point noise of that size
 *    turns a short vector's line far from the FOE by that much; and pointing
 *    away from the FOE, or all towards it when the camera backs up) then
 *    cv::solve(DECOMP_SVD) on the inliers, then ml_iterations refits with
 *    each line weighted by |flow| / D, so that its residual is the end
 *    point's distance from the radial line through the FOE (the likelihood
 *    under end-point noise; Huber beyond ml_huber_px).
 *    Confidence = inlier fraction x sqrt(lambda_min / lambda_max) of the
 *    normal matrix (0 when all lines are parallel, i.e. the FOE is unobservable). */
#pragma once

#include <hslam/vision/optical_flow.h>

#include <cstdint>
#include <vector>

namespace hslam::vision
{
struct TFoeOptions  //!< [vision] keys of the FOE estimators
{
	double noise_floor_px = 0.2;  //!< flow magnitude at rest (thesis 4.8.2 iv, at 640 x 480)
	double noise_factor = 10;  //!< vectors shorter than noise_factor x noise_floor_px are not used
	int vote_columns = 10;  //!< thesis: 10 columns of 64 px
	int vote_rows = 10;
	double vote_value = 500;  //!< thesis: +-500 per vector
	int ransac_iterations = 200;
	double ransac_inlier_px = 3.0;  //!< distance of the FOE from a vector's line ...
	double ransac_inlier_noise_px = 0.3;  //!< ... plus this end-point noise x (distance to the FOE / vector length)
	int ml_iterations = 10;  //!< end-point-weighted refits after RANSAC (0 = off: plain least squares)
	double ml_huber_px = 0.05;  //!< end-point distance beyond which a vector's weight falls (Huber)
	int min_vectors = 8;  //!< fewer usable vectors: no FOE
	int seed = 1;  //!< RANSAC sampling (deterministic)

	double minFlow_px() const { return noise_floor_px * noise_factor; }

	template <class V>
	void visit(V& v)
	{
		v.real("noise_floor_px", noise_floor_px, 0.0, 10.0);
		v.real("noise_factor", noise_factor, 0.0, 100.0);
		v.integer("vote_columns", vote_columns, 2, 100);
		v.integer("vote_rows", vote_rows, 2, 100);
		v.real("vote_value", vote_value, 1.0, 1e6);
		v.integer("ransac_iterations", ransac_iterations, 1, 100000);
		v.real("ransac_inlier_px", ransac_inlier_px, 0.01, 100.0);
		v.real("ransac_inlier_noise_px", ransac_inlier_noise_px, 0.0, 10.0);
		v.integer("ml_iterations", ml_iterations, 0, 100);
		v.real("ml_huber_px", ml_huber_px, 0.001, 10.0);
		v.integer("min_vectors", min_vectors, 2, 10000);
		v.integer("foe_seed", seed, 0, 1 << 30);
	}
};

struct TFoeEstimate
{
	bool valid = false;
	double x_px = 0, y_px = 0;
	double confidence = 0;  //!< [0, 1]
	double std_px = 0;  //!< 1-sigma of the FOE from the line residuals (sqrt of the covariance trace)
	bool expanding = true;  //!< false: vectors point towards the FOE (camera backing up)
	size_t used = 0;  //!< vectors above the noise threshold
	std::vector<uint8_t> inlier;  //!< per input vector (0 for those below the threshold)
};

struct TFoeVote
{
	bool valid_x = false, valid_y = false;
	double x_px = 0, y_px = 0;
	std::vector<double> column_sums, row_sums;
};

/** Least-squares / RANSAC FOE of residual vectors in an image of width x height. */
TFoeEstimate estimateFoe(const std::vector<TFlowVector>& residual, const TFoeOptions& options);

/** The thesis's column (and row) vote. */
TFoeVote voteFoe(const std::vector<TFlowVector>& residual, int width, int height, const TFoeOptions& options);

/** Distance (px) of point (x0, y0) from the line of a vector; inf for a zero vector. */
double distanceToFlowLine(const TFlowVector& f, double x0, double y0);

}  // namespace hslam::vision
