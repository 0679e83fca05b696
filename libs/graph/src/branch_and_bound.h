/* hslam graph (private): the branch-and-bound search of
 * CCorrelativeScanMatcher over discretised rotations and integer cell offsets
 * (Hess et al. 2016, algorithm 3). */
#pragma once

#include <hslam/graph/CMultiResolutionGrid.h>

#include <functional>
#include <vector>

namespace hslam::graph::detail
{
/** The query rotated by one angle of the window, as cells of the grid. */
struct TRotatedQuery
{
	double yaw_rad = 0;  //!< absolute yaw of this rotation
	std::vector<int> cx, cy;  //!< cell of every query point at zero offset
};

/** Fills a rotation's cells when the search first reads them: a search for
 * the best pose expands every rotation group, an existence search (stopping
 * at the first leaf above its bound) few of them. */
using TRotationFiller = std::function<void(TRotatedQuery&)>;

/** A node of the search: rotation index, offset of the first cell of its
 * block, level (block of 2^level x 2^level offsets) and its score bound. */
struct TCandidate
{
	int rotation = 0, dx = 0, dy = 0, level = 0;
	float score = 0;
};

struct TSearchResult
{
	bool found = false;
	TCandidate best;
	size_t nodesScored = 0;
};

/** Finds the leaf (level 0) of highest score above minScore over offsets in
 * [-windowCells, windowCells]^2 for every rotation; leaves for which
 * `excluded(rotation, dx, dy)` is true are skipped. The excluded offsets of
 * one rotation must form a convex set and the excluded rotations of one
 * offset an interval: a node whose corner leaves at its first and last
 * rotation are all excluded is pruned whole. With firstAbove, the first leaf
 * found above minScore is returned (an existence test). */
TSearchResult branchAndBound(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations,
							 int windowCells, float minScore, const std::function<bool(int, int, int)>& excluded,
							 bool firstAbove = false);

/** The same search over rotations given by their yaw only: `fill` computes a
 * rotation's cells (from its yaw) the first time the search reads them. */
TSearchResult branchAndBound(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations,
							 const TRotationFiller& fill, int windowCells, float minScore,
							 const std::function<bool(int, int, int)>& excluded, bool firstAbove = false);

}  // namespace hslam::graph::detail
