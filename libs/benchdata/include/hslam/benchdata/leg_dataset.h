/* hslam: labelled leg data laid out like ../shared/datasets/legs/ (see its
 * README.md), for training and scoring leg detectors:
 *   positive_*_extracted.rawlog + <same stem>.scans.csv
 *       full scans; the CSV column annotated_xy lists, per scan, the
 *       centroids ("x,y;x,y" m, laser frame) of the leg clusters inside the
 *       arc (bearing -15..15 deg, < 5 m). Clusters outside it carry no label.
 *   negative_*.rawlog
 *       no people: every cluster is a non-leg; one part per sensorLabel (the
 *       sensors' mounting poses are unknown, so they are never fused).
 * Every error names the file and, for the CSV, the line. */
#pragma once

#include <hslam/dynamic/leg_clusters.h>
#include <hslam/dynamic/leg_features.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace hslam::benchdata
{
/** One recording of one sensor. */
struct TLegDataPart
{
	std::string name;  //!< "positive_1_extracted", "negative_2/left_laser", ...
	bool has_people = false;  //!< false: every cluster is a non-leg
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	/** Positive parts: annotated leg centroids per scan (laser frame). */
	std::vector<std::vector<mrpt::math::TPoint2D>> annotations;
};

/** Annotated leg centroids per row of a .scans.csv (column annotated_xy). */
std::vector<std::vector<mrpt::math::TPoint2D>> readLegAnnotations(const std::string& csvPath);

/** The positive parts (sorted by name), then the negative parts (sorted by
 * file, then sensorLabel). Throws std::runtime_error if the folder has
 * neither, or a CSV does not have one row per scan. */
std::vector<TLegDataPart> loadLegDataset(const std::string& dir);

/** True inside the labelled arc of the positive files: bearing strictly
 * within (-15, 15) deg and distance below 5 m (laser frame). */
bool inAnnotatedArc(const mrpt::math::TPoint2D& p);

/** A cluster with its features and label. */
struct TLabelledCluster
{
	size_t scan = 0;  //!< index in the part
	mrpt::math::TPoint2D centroid;  //!< laser frame
	dynamic::TLegFeatures features{};
	enum class ELabel
	{
		leg,
		non_leg,
		unlabelled
	} label = ELabel::unlabelled;
};

/** Clusters of every scan of `part` whose centroid is nearer than
 * maxCentroidRange_m,
 * labelled: in a positive part a cluster whose centroid is within
 * 0.01 m of an annotation is a leg, one elsewhere in the arc a non-leg (the
 * extraction labelled every cluster there), one outside unlabelled; in a
 * negative part all are non-legs. */
std::vector<TLabelledCluster> labelledClusters(const TLegDataPart& part, const dynamic::TClusterOptions& clustering,
											   double maxCentroidRange_m);

}  // namespace hslam::benchdata
