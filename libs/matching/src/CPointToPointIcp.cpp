/* hslam: classic point-to-point ICP with cached exact nearest neighbours
 * (see CPointToPointIcp.h). */
#include <hslam/matching/CPointToPointIcp.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::matching
{
namespace
{
/** Per scan point: the reference candidates of its last tree query. */
class CNeighbourCache
{
   public:
	CNeighbourCache(const CPointIndex2D& reference, size_t points, int k)
		: m_ref(reference), m_k(static_cast<size_t>(std::max(1, k))), m_qx(points), m_qy(points),
		  m_radius(points, -1.0f), m_idx(points * m_k), m_count(points, 0)
	{
	}

	/** Exact nearest reference point of scan point i, now at (x, y). */
	uint32_t nearest(size_t i, float x, float y, float& d2, CPointToPointIcp::TResult& stats)
	{
		if (m_radius[i] >= 0)
		{
			const float moved = std::hypot(x - m_qx[i], y - m_qy[i]);
			uint32_t best = 0;
			float bestD2 = std::numeric_limits<float>::max();
			for (size_t j = 0; j < m_count[i]; ++j)
			{
				const uint32_t c = m_idx[i * m_k + j];
				const float dx = m_ref.x(c) - x, dy = m_ref.y(c) - y, dd = dx * dx + dy * dy;
				if (dd < bestD2) bestD2 = dd, best = c;
			}
			// No uncached point is nearer than radius - moved (triangle inequality).
			if (m_count[i] > 0 && std::sqrt(bestD2) <= m_radius[i] - moved)
			{
				++stats.cached_answers;
				d2 = bestD2;
				return best;
			}
		}
		++stats.tree_queries;
		float dist2[16];
		const size_t k = std::min<size_t>(m_k, 16);
		m_count[i] = m_ref.nearest(x, y, k, &m_idx[i * m_k], dist2);
		m_qx[i] = x, m_qy[i] = y;
		m_radius[i] = m_count[i] < k ? std::numeric_limits<float>::max() : std::sqrt(dist2[m_count[i] - 1]);
		d2 = m_count[i] > 0 ? dist2[0] : std::numeric_limits<float>::max();
		return m_count[i] > 0 ? m_idx[i * m_k] : 0;
	}

   private:
	const CPointIndex2D& m_ref;
	size_t m_k;
	std::vector<float> m_qx, m_qy, m_radius;
	std::vector<uint32_t> m_idx;
	std::vector<size_t> m_count;
};

struct TPair
{
	uint32_t ref;
	uint32_t scan;
	float d2;
};

struct TThresholds
{
	double dist_m, ang_rad;
	int offset;
};

/** Pairs of the scan at `pose` (MRPT determineMatching2D semantics); returns
 * the fraction of scan points with a pair before the unique filter. */
double pairPoints(const float* xs, const float* ys, size_t n, const mrpt::poses::CPose2D& pose, const TThresholds& t, int decimation, CNeighbourCache& cache,
				  std::vector<TPair>& pairs, CPointToPointIcp::TResult& stats)
{
	pairs.clear();
	const float c = static_cast<float>(std::cos(pose.phi())), s = static_cast<float>(std::sin(pose.phi()));
	const float px = static_cast<float>(pose.x()), py = static_cast<float>(pose.y());
	size_t withPair = 0;
	for (size_t i = static_cast<size_t>(t.offset); i < n; i += static_cast<size_t>(decimation))
	{
		const float x = px + c * xs[i] - s * ys[i], y = py + s * xs[i] + c * ys[i];
		float d2 = 0;
		const uint32_t r = cache.nearest(i, x, y, d2, stats);
		const double limit = t.ang_rad * std::hypot(x - px, y - py) + t.dist_m;
		if (d2 < limit * limit) pairs.push_back({r, static_cast<uint32_t>(i), d2}), ++withPair;
	}
	return static_cast<double>(decimation) * static_cast<double>(withPair) / static_cast<double>(n);
}

/** Keeps, for every reference point, only its closest pair. */
void keepUniquePairs(std::vector<TPair>& pairs)
{
	std::sort(pairs.begin(), pairs.end(),
			  [](const TPair& a, const TPair& b) { return a.ref != b.ref ? a.ref < b.ref : a.d2 < b.d2; });
	pairs.erase(std::unique(pairs.begin(), pairs.end(), [](const TPair& a, const TPair& b) { return a.ref == b.ref; }),
				pairs.end());
}

/** Closed-form least-squares SE(2) taking the scan points onto their pairs. */
mrpt::poses::CPose2D fitPose(const CPointIndex2D& ref, const float* xs, const float* ys, const std::vector<TPair>& pairs)
{
	double mrx = 0, mry = 0, msx = 0, msy = 0;
	for (const auto& p : pairs) mrx += ref.x(p.ref), mry += ref.y(p.ref), msx += xs[p.scan], msy += ys[p.scan];
	const double n = static_cast<double>(pairs.size());
	mrx /= n, mry /= n, msx /= n, msy /= n;
	double dot = 0, cross = 0;
	for (const auto& p : pairs)
	{
		const double ax = ref.x(p.ref) - mrx, ay = ref.y(p.ref) - mry, bx = xs[p.scan] - msx, by = ys[p.scan] - msy;
		dot += ax * bx + ay * by;
		cross += ay * bx - ax * by;
	}
	const double phi = std::atan2(cross, dot), c = std::cos(phi), s = std::sin(phi);
	return {mrx - (c * msx - s * msy), mry - (s * msx + c * msy), phi};
}

bool stoppedMoving(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double stepM, double stepRad)
{
	return !(std::abs(a.x() - b.x()) > stepM || std::abs(a.y() - b.y()) > stepM ||
			 std::abs(mrpt::math::wrapToPi(a.phi() - b.phi())) > stepRad);
}
}  // namespace

CPointToPointIcp::TResult CPointToPointIcp::align(const CPointIndex2D& reference, const float* xs, const float* ys,
												  size_t n, const mrpt::poses::CPose2D& seed) const
{
	const TOptions& o = m_options;
	TResult result;
	result.pose = seed;
	if (reference.empty() || n == 0) return result;
	CNeighbourCache cache(reference, n, o.cached_neighbours);
	TThresholds t{o.threshold_dist_m, o.threshold_ang_rad, 0};
	std::vector<TPair> pairs;
	mrpt::poses::CPose2D last;
	bool keepApproaching = true;
	do
	{
		result.goodness = pairPoints(xs, ys, n, result.pose, t, o.decimation, cache, pairs, result);
		if (pairs.empty())
			keepApproaching = false;
		else
		{
			if (o.only_unique_robust) keepUniquePairs(pairs);
			result.pose = fitPose(reference, xs, ys, pairs);
			if (stoppedMoving(last, result.pose, o.min_step_m, o.min_step_rad))
			{
				t.dist_m *= o.alfa, t.ang_rad *= o.alfa;
				if (t.dist_m < o.smallest_threshold_dist_m) keepApproaching = false;
				if (++t.offset >= o.decimation) t.offset = 0;
			}
			last = result.pose;
		}
		++result.iterations;
		if (result.iterations >= o.max_iterations && t.dist_m > o.smallest_threshold_dist_m) t.dist_m *= o.alfa;
	} while ((keepApproaching && result.iterations < o.max_iterations) ||
			 (result.iterations >= o.max_iterations && t.dist_m > o.smallest_threshold_dist_m));
	return result;
}

}  // namespace hslam::matching
