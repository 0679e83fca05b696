/* The one definition of each map-versus-reference figure (map_scoring.h), on
 * hand-counted cells. */
#include <gtest/gtest.h>
#include <hslam/benchdata/map_scoring.h>

#include <map>
#include <utility>

using namespace hslam::benchdata;
using hslam::maps::TGlobalCell;

namespace
{
TCellClassOf classes(const std::map<std::pair<int, int>, ECellClass>& known)
{
	return [known](const TGlobalCell& c) {
		const auto it = known.find({c.gx, c.gy});
		return it == known.end() ? ECellClass::unknown : it->second;
	};
}
constexpr auto occ = ECellClass::occupied;
constexpr auto fre = ECellClass::free;
}  // namespace

TEST(MapScoring, ClassesUseTheMarginAroundOneHalf)
{
	EXPECT_EQ(classifyOccupancy(0.51), ECellClass::unknown);
	EXPECT_EQ(classifyOccupancy(0.511), ECellClass::occupied);
	EXPECT_EQ(classifyOccupancy(0.49), ECellClass::unknown);
	EXPECT_EQ(classifyOccupancy(0.489), ECellClass::free);
}

TEST(MapScoring, HandCountedFigures)
{
	// Ours: walls at (0,0) and (5,5), free (1,0), (2,0). Reference: walls at
	// (1,1) (one cell from ours) and (9,9) (nothing of ours near), free (1,0),
	// (2,0), (3,0).
	const auto ours = classes({{{0, 0}, occ}, {{5, 5}, occ}, {{1, 0}, fre}, {{2, 0}, fre}});
	const auto reference = classes({{{1, 1}, occ}, {{9, 9}, occ}, {{1, 0}, fre}, {{2, 0}, fre}, {{3, 0}, fre}});
	const TMapScore s = scoreMap(ours, reference, {0, 9, 0, 9});
	EXPECT_EQ(s.compared, 7u);  // (0,0) (5,5) (1,0) (2,0) (1,1) (9,9) (3,0)
	EXPECT_EQ(s.agreed, 2u);  // the two free cells
	EXPECT_EQ(s.ours_known, 4u);
	EXPECT_EQ(s.ours_occupied, 2u);
	EXPECT_EQ(s.false_occupied, 1u);  // (5,5); (0,0) has (1,1) within one cell
	EXPECT_EQ(s.reference_occupied, 2u);
	EXPECT_EQ(s.reference_occupied_found, 1u);  // (1,1) by (0,0)
	EXPECT_DOUBLE_EQ(s.agreement(), 2.0 / 7.0);
	EXPECT_DOUBLE_EQ(s.agreementOfOursKnown(), 0.5);
	EXPECT_DOUBLE_EQ(s.wallsFound(), 0.5);
	const auto falseCells = falseOccupiedCells(ours, reference, {0, 9, 0, 9});
	ASSERT_EQ(falseCells.size(), 1u);
	EXPECT_EQ(falseCells[0], (TGlobalCell{5, 5}));
	// Outside the scored area nothing counts, but a neighbour outside it is looked at.
	const TMapScore inner = scoreMap(ours, reference, {0, 0, 0, 0});
	EXPECT_EQ(inner.compared, 1u);
	EXPECT_EQ(inner.false_occupied, 0u);
}

TEST(MapScoring, AnEmptyComparisonScoresOne)
{
	const TMapScore s = scoreMap(classes({}), classes({}), {0, 4, 0, 4});
	EXPECT_EQ(s.compared, 0u);
	EXPECT_DOUBLE_EQ(s.agreement(), 1.0);
	EXPECT_DOUBLE_EQ(s.wallsFound(), 1.0);
}
