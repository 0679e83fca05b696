/* hslam: training the learned leg classifier (CLegClassifier) on labelled
 * data (leg_dataset.h), and the cross-validation folds that score it on data
 * it never saw. Used by hslam-legs-train (the shipped model) and by
 * hslam-bench legs (cross-validated scores).
 *
 * Folds: the parts with people and the parts without are each dealt round
 * robin over k folds (k = 3, or fewer if a kind has fewer parts), so with
 * ../shared/datasets/legs fold i holds positive_i_extracted and one of the
 * three negative_2 lasers. Consecutive scans of one recording are nearly
 * identical, so splitting scans at random would score the forest on copies
 * of its training data; whole recordings per fold do not. */
#pragma once

#include <hslam/dynamic/CLegClassifier.h>
#include <hslam/dynamic/CLegDetector.h>
#include <hslam/benchdata/leg_dataset.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::benchdata
{
/** Labelled leg / non-leg samples of the parts whose index is in `use`
 * (unlabelled clusters are skipped), segmented as `detector` segments. */
struct TLegTrainingSet
{
	std::vector<dynamic::TLegFeatures> features;
	std::vector<bool> is_leg;
	size_t legs() const;
};
TLegTrainingSet legTrainingSet(const std::vector<TLegDataPart>& parts, const std::vector<size_t>& use,
							   const dynamic::CLegDetector::TOptions& detector);

/** Fold of each part (see file comment); throws std::runtime_error if the
 * parts lack people or non-people. */
std::vector<int> legCrossValidationFolds(const std::vector<TLegDataPart>& parts, int folds = 3);

/** One forest per fold, each trained on the other folds' parts. */
struct TFoldClassifiers
{
	std::vector<std::shared_ptr<const dynamic::CLegClassifier>> models;
	std::vector<int> fold_of_part;
	std::string description;  //!< "fold 1: positive_1_extracted + negative_2/left_laser; ..."
};
TFoldClassifiers trainFoldClassifiers(const std::vector<TLegDataPart>& parts, const dynamic::CLegDetector::TOptions& detector,
									  const dynamic::CLegClassifier::TTrainOptions& training);

/** A forest trained on every labelled part. */
std::shared_ptr<const dynamic::CLegClassifier> trainOnAll(const std::vector<TLegDataPart>& parts,
												 const dynamic::CLegDetector::TOptions& detector,
												 const dynamic::CLegClassifier::TTrainOptions& training);

}  // namespace hslam::benchdata
