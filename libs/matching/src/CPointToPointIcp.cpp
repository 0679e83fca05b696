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
		  m_radius(points, -1.0f), m_nearest(points, 0.0f), m_idx(points * m_k), m_count(points, 0)
	{
	}

	/** Nearest reference point of scan point i, now at (x, y): exact when
	 * it is within limit_m; otherwise d2 may be any value >= limit_m^2 (the
	 * point is unpaired either way). */
	uint32_t nearest(size_t i, float x, float y, float limit_m, float& d2, CPointToPointIcp::TResult& stats)
	{
		if (m_radius[i] >= 0)
		{
			const float dx = x - m_qx[i], dy = y - m_qy[i];
			const float moved = std::sqrt(dx * dx + dy * dy);
			// Nothing was within nearest_m of the last query point, so nothing
			// is within nearest_m - moved now (triangle inequality): when that
			// is at least the pairing limit, the point is unpaired.
			if (m_nearest[i] - moved >= limit_m)
			{
				++stats.cached_answers;
				d2 = limit_m * limit_m;
				return 0;
			}
			uint32_t best = 0;
			float bestD2 = std::numeric_limits<float>::max();
			for (size_t j = 0; j < m_count[i]; ++j)
			{
				const uint32_t c = m_idx[i * m_k + j];
				const float ex = m_ref.x(c) - x, ey = m_ref.y(c) - y, dd = ex * ex + ey * ey;
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
		// Only points within the pairing limit matter now: the search stops
		// once they have all been seen, and the cache keeps what is known.
		float exact_m = 0;
		m_count[i] = m_ref.nearestWithin(x, y, k, limit_m, &m_idx[i * m_k], dist2, exact_m);
		m_qx[i] = x, m_qy[i] = y;
		const float kth_m = m_count[i] < k ? std::numeric_limits<float>::max() : std::sqrt(dist2[m_count[i] - 1]);
		// every reference point within m_radius of the query is cached
		m_radius[i] = std::min(kth_m, exact_m);
		// nothing is nearer than m_nearest (exact when below exact_m)
		m_nearest[i] = std::min(m_count[i] > 0 ? std::sqrt(dist2[0]) : std::numeric_limits<float>::max(), exact_m);
		// beyond exact_m (>= limit_m) the point is unpaired whatever d2 says
		d2 = m_count[i] > 0 ? dist2[0] : std::numeric_limits<float>::max();
		return m_count[i] > 0 ? m_idx[i * m_k] : 0;
	}

   private:
	const CPointIndex2D& m_ref;
	size_t m_k;
	std::vector<float> m_qx, m_qy, m_radius, m_nearest;
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

/** Pairs of the scan at `pose` (MRPT determineMatching2D semantics; a
 * point's pairing distance grows with its range, ranges_m[i]); returns the
 * fraction of scan points with a pair before the unique filter. */
double pairPoints(const float* xs, const float* ys, const float* ranges_m, size_t n, const mrpt::poses::CPose2D& pose,
				  const TThresholds& t, int decimation, CNeighbourCache& cache, std::vector<TPair>& pairs,
				  CPointToPointIcp::TResult& stats)
{
	pairs.clear();
	const float c = static_cast<float>(std::cos(pose.phi())), s = static_cast<float>(std::sin(pose.phi()));
	const float px = static_cast<float>(pose.x()), py = static_cast<float>(pose.y());
	size_t withPair = 0;
	for (size_t i = static_cast<size_t>(t.offset); i < n; i += static_cast<size_t>(decimation))
	{
		const float x = px + c * xs[i] - s * ys[i], y = py + s * xs[i] + c * ys[i];
		const float limit = static_cast<float>(t.ang_rad * ranges_m[i] + t.dist_m);
		float d2 = 0;
		const uint32_t r = cache.nearest(i, x, y, limit, d2, stats);
		if (d2 < limit * limit) pairs.push_back({r, static_cast<uint32_t>(i), d2}), ++withPair;
	}
	return static_cast<double>(decimation) * static_cast<double>(withPair) / static_cast<double>(n);
}

/** Keeps, for every reference point, only its closest pair (in O(pairs):
 * slotOfRef, one entry per reference point, is left all-empty again). */
void keepUniquePairs(std::vector<TPair>& pairs, std::vector<uint32_t>& slotOfRef)
{
	constexpr uint32_t kEmpty = std::numeric_limits<uint32_t>::max();
	size_t kept = 0;
	for (const TPair& p : pairs)
	{
		uint32_t& slot = slotOfRef[p.ref];
		if (slot == kEmpty)
			slot = static_cast<uint32_t>(kept), pairs[kept++] = p;
		else if (p.d2 < pairs[slot].d2)
			pairs[slot] = p;
	}
	pairs.resize(kept);
	for (const TPair& p : pairs) slotOfRef[p.ref] = kEmpty;
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

struct TStepLimits
{
	double m, rad;
};

/** Step below which the current pairing stage ends. A stage that is not the
 * last one only has to bring the pose near its fixed point (the next,
 * tighter pairing refines it): stage_step_fraction x its pairing distance,
 * the same number in radians for the rotation (1 rad counted as 1 m: 5 mm
 * and 0.29 deg at the first stage). The last stage keeps MRPT's limits. */
TStepLimits stageStepLimits(const CPointToPointIcp::TOptions& o, const TThresholds& t)
{
	const bool lastStage = t.dist_m * o.alfa < o.smallest_threshold_dist_m;
	const double early = lastStage ? 0.0 : o.stage_step_fraction * t.dist_m;
	return {std::max(o.min_step_m, early), std::max(o.min_step_rad, early)};
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
	std::vector<uint32_t> slotOfRef(o.only_unique_robust ? reference.size() : 0, std::numeric_limits<uint32_t>::max());
	std::vector<float> ranges_m(n);
	for (size_t i = 0; i < n; ++i) ranges_m[i] = std::hypot(xs[i], ys[i]);
	mrpt::poses::CPose2D last;
	bool keepApproaching = true;
	do
	{
		result.goodness = pairPoints(xs, ys, ranges_m.data(), n, result.pose, t, o.decimation, cache, pairs, result);
		if (pairs.empty())
			keepApproaching = false;
		else
		{
			if (o.only_unique_robust) keepUniquePairs(pairs, slotOfRef);
			result.pose = fitPose(reference, xs, ys, pairs);
			const TStepLimits step = stageStepLimits(o, t);
			if (stoppedMoving(last, result.pose, step.m, step.rad))
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
