/* hslam: one definition of every map-versus-reference figure, used by every
 * benchmark suite and test that scores a map (hslam-bench grid, grid-range,
 * sonar, sonar-batch, legs, legs-sim). The reference is a ground-truth map, a
 * peer's map (MRPT's COccupancyGridMap2D on the same scans) or a map of the
 * static structure alone.
 *
 * Cell class: occupied if the occupancy probability is above 0.5 + margin,
 * free if below 0.5 - margin, unknown otherwise or if the cell was never
 * observed (margin kClassMargin = 0.01).
 * Over a scored area (a rectangle of our cells):
 *   compared        cells known in either map;
 *   agreement       compared cells with the same class in both / compared;
 *   agree(known)    compared cells with the same class in both / cells known
 *                   in ours (how right what the map claims is);
 *   false occupied  cells occupied in ours with no reference-occupied cell
 *                   within kOccupiedToleranceCells (1 cell, Chebyshev): a
 *                   wall drawn one cell off is placed, not invented;
 *   walls found     reference-occupied cells with an occupied cell of ours
 *                   within the same tolerance / reference-occupied cells.
 * Agreement is cell for cell (no tolerance); the two occupied figures measure
 * where walls are drawn, with the one-cell tolerance of a wall falling on
 * either side of a cell edge. */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace hslam::benchdata
{
enum class ECellClass
{
	unknown,
	free,
	occupied
};

constexpr double kClassMargin = 0.01;
constexpr int kOccupiedToleranceCells = 1;

ECellClass classifyOccupancy(double occupancyProbability, double margin = kClassMargin);

/** A map seen as the class of each of our cells. */
using TCellClassOf = std::function<ECellClass(const maps::TGlobalCell&)>;

/** Our grid's classes (unobserved cells unknown). */
TCellClassOf cellClassesOf(const maps::CTiledOccupancyGrid& grid);
/** An MRPT grid's classes at the centres of our cells (`ours` gives the
 * lattice; outside the MRPT grid: unknown). */
TCellClassOf cellClassesOf(const mrpt::maps::COccupancyGridMap2D& grid, const maps::CTiledGridGeometry& ours);
/** Our cells whose centres lie inside the MRPT grid. */
maps::TCellBounds cellBoundsOf(const mrpt::maps::COccupancyGridMap2D& grid, const maps::CTiledGridGeometry& ours);

struct TMapScore
{
	size_t compared = 0;  //!< cells known in either map
	size_t agreed = 0;  //!< of those, same class in both
	size_t ours_known = 0;  //!< of those, known in ours
	size_t ours_occupied = 0;
	size_t false_occupied = 0;  //!< occupied in ours, no reference-occupied cell within the tolerance
	size_t reference_occupied = 0;
	size_t reference_occupied_found = 0;  //!< with an occupied cell of ours within the tolerance
	double agreement() const { return compared ? static_cast<double>(agreed) / compared : 1.0; }
	double agreementOfOursKnown() const { return ours_known ? static_cast<double>(agreed) / ours_known : 1.0; }
	double wallsFound() const
	{
		return reference_occupied ? static_cast<double>(reference_occupied_found) / reference_occupied : 1.0;
	}
	/** Sums the counts (pooling several maps or runs). */
	void add(const TMapScore& o);
};

/** Scores `ours` against `reference` over `cells`. */
TMapScore scoreMap(const TCellClassOf& ours, const TCellClassOf& reference, const maps::TCellBounds& cells);

/** Our grid against an MRPT grid of the same resolution (cell edges on the
 * same multiples of it, as maps::toMrptGrid and resampleOntoOurCells make
 * them), over the MRPT grid's cells; throws std::invalid_argument if the
 * resolutions differ. */
TMapScore scoreMap(const maps::CTiledOccupancyGrid& ours, const mrpt::maps::COccupancyGridMap2D& reference);

/** Cells of `cells` occupied in `ours` with no reference-occupied cell within
 * kOccupiedToleranceCells (the "false occupied" cells of TMapScore). */
std::vector<maps::TGlobalCell> falseOccupiedCells(const TCellClassOf& ours, const TCellClassOf& reference,
												  const maps::TCellBounds& cells);

/** Observed cells of `grid` classified occupied. */
std::vector<maps::TGlobalCell> occupiedCells(const maps::CTiledOccupancyGrid& grid);

}  // namespace hslam::benchdata
