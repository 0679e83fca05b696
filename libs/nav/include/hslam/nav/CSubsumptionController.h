/* hslam nav: the subsumption obstacle avoidance and target seeking controller
 * of thesis 4.2 (figures 59-63, eq. 33-36; Appendix A).
 *
 * Each control step takes the latest laser scan, the latest sonar ring (either
 * may be null) and the robot pose, fuses the ranges (CRangeFusion) and runs
 * the layers:
 *  forward velocity (figure 59): v = min(v_t (eq. 33), v_c (eq. 34)), subsumed
 *    by the forward turning layer (0 while the heading error is too large, or
 *    the back-off speed during an escape);
 *  rotation (figure 60): the sector selecting layer's candidates filtered by
 *    target seeking give the heading h_sector; the free target bearing is
 *    h_target; with w_s of eq. 35 the heading is h = h_sector +
 *    w_s wrap(h_target - h_sector) (the blend on the circle), and
 *    w = k_h h + w_a w_side (w_a: eq. 36), clipped. The
 *    side layer subsumes the heading below its threshold; the forward turning
 *    layer subsumes everything during an escape.
 * Out of a local minimum (no progress towards the target for a while) the
 * boundary following layer takes over the heading (CBoundaryFollowingLayer;
 * an addition to the thesis). At the last target the controller stops (0, 0)
 * and reports done. No I/O. */
#pragma once

#include <hslam/nav/CBoundaryFollowingLayer.h>
#include <hslam/nav/CForwardTurningLayer.h>
#include <hslam/nav/CRangeFusion.h>
#include <hslam/nav/CSectorSelectingLayer.h>
#include <hslam/nav/CSideAvoidanceLayer.h>
#include <hslam/nav/CTargetSeekingLayer.h>
#include <hslam/nav/CTargetSequence.h>
#include <hslam/nav/CVelocityControlLayer.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>
#include <vector>

namespace hslam::nav
{
struct TControllerOptions  //!< [nav_controller]
{
	double heading_gain_per_s = 1.5;  //!< w = gain * heading (rad/s per rad)
	double max_speed_mm_s = 500;  //!< overall clamp of v
	double max_turn_rate_rad_s = 60.0 * M_PI / 180.0;  //!< overall clamp of |w|
	double virtual_sonar_cone_rad = 30.0 * M_PI / 180.0;  //!< cone of the eight ring directions

	template <class V>
	void visit(V& v)
	{
		v.real("heading_gain_per_s", heading_gain_per_s, 0.0, 20.0);
		v.real("max_speed_mm_s", max_speed_mm_s, 10.0, 2000.0);
		v.degrees("max_turn_rate_deg_s", max_turn_rate_rad_s, 1.0, 300.0);
		v.degrees("virtual_sonar_cone_deg", virtual_sonar_cone_rad, 1.0, 90.0);
	}
};

/** Every option of the controller, one INI section each. */
struct TSubsumptionOptions
{
	TControllerOptions controller;
	TRangeFusionOptions fusion;
	TTargetSeekingOptions target_seeking;
	TVelocityControlOptions velocity_control;
	TSectorSelectingOptions sector_selecting;
	TSideAvoidanceOptions side_avoidance;
	TForwardTurningOptions forward_turning;
	TCornerTrapOptions corner_trap;
	TBoundaryFollowingOptions boundary_following;

	/** Section names, in the order load() reads them. */
	static std::vector<std::string> sections();
	/** Loads every section (absent sections keep the defaults; bad values throw common::config_error). */
	static TSubsumptionOptions load(const mrpt::config::CConfigFileBase& cfg);
	void save(mrpt::config::CConfigFileBase& cfg) const;
};

enum class ENavState
{
	navigating,
	escaping,  //!< forward turning layer backing off
	target_reached,  //!< all targets reached: stopped
	no_target
};
const char* navStateName(ENavState state);

/** Which layer set the rotation of a step (diagnostics: path.csv, hslam-bench nav --trace). */
enum class ENavLayer
{
	none,  //!< stopped (target reached, no target)
	target,  //!< free target bearing (eq. 35 far from everything)
	sector,  //!< sector selecting blended with the target bearing (figure 60-61)
	side,  //!< side obstacle avoidance subsuming the heading (figure 62)
	forward_turning,  //!< back-off manoeuvre (figure 63)
	boundary  //!< boundary following out of a local minimum
};
const char* navLayerName(ENavLayer layer);

struct TNavCommand
{
	double v_mps = 0, w_rad_s = 0;
	ENavState state = ENavState::no_target;
	double nearest_m = 0;  //!< nearest fused range from the robot centre
	size_t targets_reached = 0;
	ENavLayer layer = ENavLayer::none;  //!< the layer that set w
	bool turn_in_place = false;  //!< forward turning subsumed v with 0 (heading beyond turn_in_place_above_deg)
};

class CSubsumptionController
{
   public:
	explicit CSubsumptionController(const TSubsumptionOptions& options = {});

	void setTargets(std::vector<mrpt::math::TPoint2D> targets);
	const CTargetSequence& targets() const { return m_targets; }

	/** One control step at time t_s (s, any monotonic clock). */
	TNavCommand step(const mrpt::math::TPose2D& pose, const mrpt::obs::CObservation2DRangeScan* scan,
					 const mrpt::obs::CObservationRange* sonar, double t_s);

	const TSubsumptionOptions& options() const { return m_opts; }

   private:
	double rotationCommand(const std::array<TVirtualSonar, 8>& ring, const TSectorChoice& sectors,
						   const TTargetSeekingOutput& target, double v_mps, double nearest_mm,
						   ENavLayer& layer, double& heading_rad) const;
	/** (v, w) of the layers below the forward turning layer. */
	void blendLayers(const CPolarProfile& profile, const TTargetSeekingOutput& seek, double t_s, TNavCommand& cmd);

	TSubsumptionOptions m_opts;
	CRangeFusion m_fusion;
	CTargetSeekingLayer m_targetSeeking;
	CVelocityControlLayer m_velocityControl;
	CSectorSelectingLayer m_sectors;
	CSideAvoidanceLayer m_side;
	CForwardTurningLayer m_forwardTurning;
	CBoundaryFollowingLayer m_boundary;
	CTargetSequence m_targets;
	CPolarProfile m_profile;  //!< this step's fused ranges (kept: no allocation per step)
	int m_turnDirection = 0;  //!< +1 / -1 while turning in place (forward turning), else 0
};

}  // namespace hslam::nav
