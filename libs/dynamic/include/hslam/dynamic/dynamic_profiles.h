/* hslam: options of the dynamic object filter read from INI files. The
 * named settings (profiles) for other sensors than the thesis' SICK at 1 deg
 * are INI files in config_ini/, the only place they are written (each key
 * documented there; docs/dynamic.md gives the measurements):
 *   hslam-legs-thesis.ini        the thesis' rule set (4.7.1-4.7.2, appendix H)
 *                                where the defaults go beyond it;
 *   hslam-legs-hokuyo-rules.ini  the rules for a Hokuyo at 0.35 deg with
 *                                people up to 5 m (../shared/datasets/legs);
 *   hslam-legs-hokuyo.ini        the learned leg classifier for that Hokuyo
 *                                (what hslam-process users run). */
#pragma once

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/CLegClassifier.h>

#include <string>
#include <vector>

namespace hslam::dynamic
{
/** Filter options: the defaults, then the [dynamic_objects] section of each
 * file of `iniFiles` in order, each on top of the previous (empty names are
 * skipped), all range-checked; a relative classifier_model is taken
 * relative to the folder of its INI file. Throws common::config_error
 * naming the file and line or key. */
CDynamicObjectFilter::TOptions loadDynamicOptions(const std::vector<std::string>& iniFiles);

/** Forest training options: defaults, then [leg_classifier] of `configFile`
 * (if not empty). */
CLegClassifier::TTrainOptions loadLegTrainOptions(const std::string& configFile);

}  // namespace hslam::dynamic
