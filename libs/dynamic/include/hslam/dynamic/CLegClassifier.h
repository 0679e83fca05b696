/* hslam: learned leg / non-leg decision for one scan cluster (beyond the
 * thesis, whose 4.7.1 hand-set rules its own 4.7.5 calls the weak point).
 * A random forest (OpenCV's cv::ml::RTrees, as in leg_tracker, Leigh et al.
 * ICRA 2015) over the features of leg_features.h. probability() is the
 * fraction of trees voting "leg"; CLegDetector accepts a cluster at or above
 * its classifier_threshold. Models are trained by `hslam-legs-train` (or
 * in-memory by `hslam-bench legs`, per cross-validation fold) and stored in
 * OpenCV's FileStorage format (.yml / .yml.gz). */
#pragma once

#include <hslam/dynamic/leg_features.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::dynamic
{
class CLegClassifier
{
   public:
	struct TTrainOptions
	{
		int trees = 100;  //!< forest size
		int max_depth = 12;  //!< depth limit of each tree
		int min_sample_count = 4;  //!< a node with fewer samples is a leaf
		int active_features = 0;  //!< features tried per split (0: sqrt of the feature count)
		double positive_prior = 0.5;  //!< class prior of "leg" (0.5: balanced however many negatives)
		int seed = 1;  //!< random number seed (training is deterministic)

		template <class V>
		void visit(V& v)
		{
			v.integer("forest_trees", trees, 1, 10000);
			v.integer("forest_max_depth", max_depth, 1, 64);
			v.integer("forest_min_sample_count", min_sample_count, 1, 100000);
			v.integer("forest_active_features", active_features, 0, static_cast<int>(kLegFeatureCount));
			v.real("forest_positive_prior", positive_prior, 0.001, 0.999);
			v.integer("forest_seed", seed, 0, 1 << 30);
		}
	};

	CLegClassifier();
	~CLegClassifier();
	CLegClassifier(CLegClassifier&&) noexcept;
	CLegClassifier& operator=(CLegClassifier&&) noexcept;
	CLegClassifier(const CLegClassifier&) = delete;
	CLegClassifier& operator=(const CLegClassifier&) = delete;

	/** Trains on `features` with `isLeg` labels (both classes needed;
	 * throws std::invalid_argument otherwise). */
	void train(const std::vector<TLegFeatures>& features, const std::vector<bool>& isLeg,
			   const TTrainOptions& options);
	/** Fraction of trees voting "leg", in [0, 1]. Throws std::logic_error if
	 * nothing was trained or loaded. */
	double probability(const TLegFeatures& f) const;
	bool trained() const;
	int trees() const;
	/** Relative importance of each feature (sums to 1; empty if unknown). */
	std::vector<double> featureImportance() const;

	/** Writes the model (OpenCV FileStorage; ".gz" compresses). Throws
	 * std::runtime_error naming the path on failure. */
	void save(const std::string& path) const;
	/** Reads a model written by save(); throws std::runtime_error naming
	 * the path if it is missing, unreadable, not a forest, or made for a
	 * different feature count. */
	static CLegClassifier load(const std::string& path);

   private:
	struct TImpl;
	std::unique_ptr<TImpl> m_impl;
};

}  // namespace hslam::dynamic
