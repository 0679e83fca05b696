#include <hslam/vision/foe.h>

#include <cmath>
#include <limits>
#include <random>

namespace hslam::vision
{
namespace
{
struct TLine
{
	double a = 0, b = 0, c = 0;  //!< a x0 + b y0 = c, (a, b) unit
	size_t index = 0;
	const TFlowVector* f = nullptr;
};

/** Normalised line constraint of a vector: v x0 - u y0 = v x - u y. */
TLine lineOf(const TFlowVector& f, size_t index)
{
	const cv::Point2f d = f.flow();
	const double n = std::hypot(d.x, d.y);
	return {d.y / n, -d.x / n, (d.y * f.p0.x - d.x * f.p0.y) / n, index, &f};
}

/** +1 if the vector points away from (x0, y0), -1 if towards it. */
int radialSign(const TFlowVector& f, double x0, double y0)
{
	const cv::Point2f d = f.flow();
	return (f.p0.x - x0) * d.x + (f.p0.y - y0) * d.y >= 0 ? 1 : -1;
}

/** Inliers of an FOE hypothesis with the majority radial sign: the line passes
 * within ransac_inlier_px of it, plus what end-point noise of
 * ransac_inlier_noise_px turns the line by at the FOE's distance (D / |flow|). */
std::vector<const TLine*> inliersOf(const std::vector<TLine>& lines, double x0, double y0, const TFoeOptions& o,
									int& sign)
{
	std::vector<const TLine*> out[2];
	for (const auto& l : lines)
	{
		const double lever = std::hypot(l.f->p0.x - x0, l.f->p0.y - y0) / cv::norm(l.f->flow());
		if (std::abs(l.a * x0 + l.b * y0 - l.c) < o.ransac_inlier_px + o.ransac_inlier_noise_px * lever)
			out[radialSign(*l.f, x0, y0) > 0 ? 0 : 1].push_back(&l);
	}
	sign = out[0].size() >= out[1].size() ? 1 : -1;
	return sign > 0 ? out[0] : out[1];
}

/** Least squares with cv::solve(DECOMP_SVD); also the normal matrix eigenvalues and residual sigma. */
bool solveLines(const std::vector<const TLine*>& lines, double& x0, double& y0, double& conditioning, double& std_px)
{
	const int n = static_cast<int>(lines.size());
	cv::Mat A(n, 2, CV_64F), b(n, 1, CV_64F), x;
	for (int i = 0; i < n; ++i)
	{
		A.at<double>(i, 0) = lines[i]->a;
		A.at<double>(i, 1) = lines[i]->b;
		b.at<double>(i) = lines[i]->c;
	}
	if (!cv::solve(A, b, x, cv::DECOMP_SVD)) return false;
	x0 = x.at<double>(0);
	y0 = x.at<double>(1);
	cv::Mat N = A.t() * A, eig;
	cv::eigen(N, eig);
	const double lmax = eig.at<double>(0), lmin = eig.at<double>(1);
	conditioning = lmax > 0 ? std::sqrt(std::max(0.0, lmin) / lmax) : 0.0;
	const double rss = cv::norm(A * x - b, cv::NORM_L2SQR);
	const double sigma2 = n > 2 ? rss / (n - 2) : rss;
	cv::Mat Ninv;
	if (lmin <= 1e-12 || cv::invert(N, Ninv, cv::DECOMP_SVD) == 0) return false;
	std_px = std::sqrt(sigma2 * (Ninv.at<double>(0, 0) + Ninv.at<double>(1, 1)));
	return std::isfinite(x0) && std::isfinite(y0);
}

/** Maximum-likelihood refinement for isotropic end-point noise: iteratively
 * reweighted least squares on the same lines, each weighted by |flow| / D
 * (D = distance of the vector from the current FOE), so that its residual is
 * the distance of the vector's end point from the radial line through the FOE
 * (px at the vector, not at the FOE), with a Huber weight beyond huber_px.
 * Unweighted, a short vector far from the FOE counts as much as a long one
 * near it although its line is D / |flow| times less certain there. */
void refineMaximumLikelihood(const std::vector<const TLine*>& lines, double huber_px, int iterations, double& x0,
							 double& y0)
{
	for (int it = 0; it < iterations; ++it)
	{
		cv::Matx22d N = cv::Matx22d::zeros();
		cv::Vec2d r(0, 0);
		for (const TLine* l : lines)
		{
			const double s = cv::norm(l->f->flow()) / std::max(1.0, std::hypot(l->f->p0.x - x0, l->f->p0.y - y0));
			const double endPoint = std::abs(l->a * x0 + l->b * y0 - l->c) * s;
			const double w = s * s * (endPoint > huber_px ? huber_px / endPoint : 1.0);
			N(0, 0) += w * l->a * l->a;
			N(0, 1) += w * l->a * l->b;
			N(1, 1) += w * l->b * l->b;
			r[0] += w * l->a * l->c;
			r[1] += w * l->b * l->c;
		}
		N(1, 0) = N(0, 1);
		if (cv::determinant(N) <= 1e-12 * (N(0, 0) + N(1, 1)) * (N(0, 0) + N(1, 1))) return;
		const cv::Vec2d x = N.inv() * r;
		if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return;
		x0 = x[0];
		y0 = x[1];
	}
}

/** Best RANSAC hypothesis (two lines intersected); false if none. */
bool ransacFoe(const std::vector<TLine>& lines, const TFoeOptions& o, double& x0, double& y0)
{
	std::mt19937_64 rng(static_cast<uint64_t>(o.seed));
	std::uniform_int_distribution<size_t> pick(0, lines.size() - 1);
	size_t best = 0;
	for (int it = 0; it < o.ransac_iterations; ++it)
	{
		const TLine& l1 = lines[pick(rng)];
		const TLine& l2 = lines[pick(rng)];
		const double det = l1.a * l2.b - l1.b * l2.a;
		if (std::abs(det) < 1e-3) continue;  // (near-)parallel lines
		const double x = (l1.c * l2.b - l1.b * l2.c) / det, y = (l1.a * l2.c - l1.c * l2.a) / det;
		int sign = 1;
		const size_t n = inliersOf(lines, x, y, o, sign).size();
		if (n > best)
		{
			best = n;
			x0 = x;
			y0 = y;
		}
	}
	return best >= 2;
}
}  // namespace

double distanceToFlowLine(const TFlowVector& f, double x0, double y0)
{
	const cv::Point2f d = f.flow();
	if (d.x == 0 && d.y == 0) return std::numeric_limits<double>::infinity();
	const TLine l = lineOf(f, 0);
	return std::abs(l.a * x0 + l.b * y0 - l.c);
}

TFoeEstimate estimateFoe(const std::vector<TFlowVector>& residual, const TFoeOptions& o)
{
	TFoeEstimate out;
	out.inlier.assign(residual.size(), 0);
	std::vector<TLine> lines;
	for (size_t i = 0; i < residual.size(); ++i)
		if (cv::norm(residual[i].flow()) >= std::max(o.minFlow_px(), 1e-6)) lines.push_back(lineOf(residual[i], i));
	out.used = lines.size();
	if (static_cast<int>(lines.size()) < o.min_vectors) return out;
	double x0 = 0, y0 = 0;
	if (!ransacFoe(lines, o, x0, y0)) return out;
	int sign = 1;
	double conditioning = 0, std_px = 0;
	std::vector<const TLine*> inl;
	for (int refine = 0; refine < 2; ++refine)  // refit, re-select, refit
	{
		inl = inliersOf(lines, x0, y0, o, sign);
		if (static_cast<int>(inl.size()) < std::max(2, o.min_vectors / 2)) return out;
		if (!solveLines(inl, x0, y0, conditioning, std_px)) return out;
	}
	if (o.ml_iterations > 0)
	{
		refineMaximumLikelihood(inl, o.ml_huber_px, o.ml_iterations, x0, y0);
		inl = inliersOf(lines, x0, y0, o, sign);
		if (static_cast<int>(inl.size()) < std::max(2, o.min_vectors / 2)) return out;
		refineMaximumLikelihood(inl, o.ml_huber_px, o.ml_iterations, x0, y0);
	}
	inl = inliersOf(lines, x0, y0, o, sign);
	for (const TLine* l : inl) out.inlier[l->index] = 1;
	out.valid = true;
	out.x_px = x0;
	out.y_px = y0;
	out.expanding = sign > 0;
	out.std_px = std_px;
	out.confidence = static_cast<double>(inl.size()) / static_cast<double>(lines.size()) * conditioning;
	return out;
}

}  // namespace hslam::vision
