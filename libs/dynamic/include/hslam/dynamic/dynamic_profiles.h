/* hslam: named settings of the dynamic object filter for other sensors than
 * the thesis' SICK at 1 deg (INI text for [dynamic_objects], loaded like a
 * config file, so every value is range-checked the same way). */
#pragma once

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/CLegClassifier.h>

#include <string>

namespace hslam::dynamic
{
/** The thesis' rule set (4.7.1-4.7.2, appendix H) where the defaults go
 * beyond it: find_interv from one leg width (0.18 m, the H.3 table) without
 * an upper beam count; a track is dynamic once it has moved 0.2 m from its
 * birth, without motion evidence, relative-motion test or speed
 * significance; a person track is confirmed by its own motion; the person
 * disc is a fixed 0.35 m; no static-world evidence. */
inline const char* kThesisProfileIni = R"([dynamic_objects]
min_leg_width_m = 0.18
max_leg_width_m = 0
confirm_free_hits = 0
confirm_relative_motion = false
confirm_moving_frames = 0
mask_radius_m = 0.35
mask_sigma = 0
person_needs_dynamic_leg = false
static_evidence = false
)";

/** Hokuyo at 0.35 deg with people up to 5 m (../shared/datasets/legs):
 * only what the sensor and the scoring region dictate differs from the
 * thesis defaults (docs/dynamic.md explains each value):
 *  - max_range_m = 5: people are annotated up to 5 m (the thesis' 3.2 m is
 *    its map range); find_interv gets one more band (2.2-3.2 m);
 *  - min_leg_width_m = 0.10, max 0.25, width 0.05-0.25 m: the visible chord of a leg at
 *    0.35 deg (thesis 4.7.1 cites 9-18 cm widths [20]; the thesis' 0.18 m
 *    reproduces its 1 deg table but asks fine scans for more beams than a
 *    leg gives);
 *  - require_isolated: wall pieces cut at 300 mm are not legs. */
inline const char* kHokuyoLegsProfileIni = R"([dynamic_objects]
max_range_m = 5.0
find_interv_bands_m = 1.0 1.2 1.5 2.2 3.2
min_leg_width_m = 0.10
max_leg_width_m = 0.25
min_width_m = 0.05
max_width_m = 0.25
require_isolated = true
)";

/** Lines added to kHokuyoLegsProfileIni when the learned classifier
 * decides (CLegClassifier; the rule thresholds above then only set the
 * range limit): candidates down to a low single-scan leg probability, a
 * track confirmed only when the mean over its observations is high, and a
 * person track by its own motion (the chair-leg pairs that made it need a
 * dynamic leg no longer pass the classifier), and no wait for the track to
 * step into space seen free before (the free-space evidence guarded the
 * rules against clutter; the classifier and the static-world evidence do
 * that now, and a cold start no longer delays confirmation). docs/dynamic.md gives the
 * cross-validated sweep these values come from. */
inline const char* kLearnedLegsProfileLines = R"(classifier_threshold = 0.05
confirm_min_leg_probability = 0.4
person_needs_dynamic_leg = false
confirm_free_hits = 0
)";

/** Filter options: the INI text `profileIni` (a profile above, or several
 * concatenated), then the [dynamic_objects] section of `configFile` (if
 * not empty) on top, both range-checked. Throws common::config_error
 * naming the file and key. */
CDynamicObjectFilter::TOptions loadDynamicOptions(const std::string& profileIni, const std::string& configFile);

/** Forest training options: defaults, then [leg_classifier] of `configFile`
 * (if not empty). */
CLegClassifier::TTrainOptions loadLegTrainOptions(const std::string& configFile);

}  // namespace hslam::dynamic
