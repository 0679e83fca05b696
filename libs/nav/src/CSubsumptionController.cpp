/* hslam nav: the subsumption controller (thesis 4.2; see the header). */
#include <hslam/common/options_io.h>
#include <hslam/nav/CSubsumptionController.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
const char* navStateName(ENavState s)
{
	switch (s)
	{
		case ENavState::navigating: return "navigating";
		case ENavState::escaping: return "escaping";
		case ENavState::target_reached: return "target_reached";
		case ENavState::no_target: return "no_target";
	}
	return "?";
}

const char* navLayerName(ENavLayer l)
{
	switch (l)
	{
		case ENavLayer::none: return "none";
		case ENavLayer::target: return "target";
		case ENavLayer::sector: return "sector";
		case ENavLayer::side: return "side";
		case ENavLayer::forward_turning: return "forward_turning";
		case ENavLayer::boundary: return "boundary";
	}
	return "?";
}

std::vector<std::string> TSubsumptionOptions::sections()
{
	return {"nav_controller",		"nav_fusion",		  "nav_target_seeking",	 "nav_velocity_control",
			"nav_sector_selecting", "nav_side_avoidance", "nav_forward_turning", "nav_corner_trap",
			"nav_boundary_following"};
}

TSubsumptionOptions TSubsumptionOptions::load(const mrpt::config::CConfigFileBase& cfg)
{
	TSubsumptionOptions o;
	const auto s = sections();
	common::loadOptions(o.controller, cfg, s[0]);
	common::loadOptions(o.fusion, cfg, s[1]);
	common::loadOptions(o.target_seeking, cfg, s[2]);
	common::loadOptions(o.velocity_control, cfg, s[3]);
	common::loadOptions(o.sector_selecting, cfg, s[4]);
	common::loadOptions(o.side_avoidance, cfg, s[5]);
	common::loadOptions(o.forward_turning, cfg, s[6]);
	common::loadOptions(o.corner_trap, cfg, s[7]);
	common::loadOptions(o.boundary_following, cfg, s[8]);
	return o;
}

void TSubsumptionOptions::save(mrpt::config::CConfigFileBase& cfg) const
{
	const auto s = sections();
	common::saveOptions(controller, cfg, s[0]);
	common::saveOptions(fusion, cfg, s[1]);
	common::saveOptions(target_seeking, cfg, s[2]);
	common::saveOptions(velocity_control, cfg, s[3]);
	common::saveOptions(sector_selecting, cfg, s[4]);
	common::saveOptions(side_avoidance, cfg, s[5]);
	common::saveOptions(forward_turning, cfg, s[6]);
	common::saveOptions(corner_trap, cfg, s[7]);
	common::saveOptions(boundary_following, cfg, s[8]);
}

CSubsumptionController::CSubsumptionController(const TSubsumptionOptions& o)
	: m_opts(o),
	  m_fusion(o.fusion),
	  m_targetSeeking(o.target_seeking),
	  m_velocityControl(o.velocity_control),
	  m_sectors(o.sector_selecting),
	  m_side(o.side_avoidance),
	  m_forwardTurning(o.forward_turning, o.corner_trap),
	  m_boundary(o.boundary_following),
	  m_profile(m_fusion.makeProfile())
{
}

void CSubsumptionController::setTargets(std::vector<mrpt::math::TPoint2D> targets)
{
	m_targets = CTargetSequence(std::move(targets));
	m_boundary.reset();
}

double CSubsumptionController::rotationCommand(const std::array<TVirtualSonar, 8>& ring, const TSectorChoice& sectors,
											   const TTargetSeekingOutput& target, double v_mps,
											   double nearest_mm, ENavLayer& layer, double& heading) const
{
	const auto side = m_side.evaluate(ring, v_mps);
	layer = ENavLayer::side;
	heading = side.w_rad_s / std::max(1e-6, m_opts.controller.heading_gain_per_s);
	if (side.subsume) return side.w_rad_s;
	// Eq. 35: far from everything the free target bearing rules; near obstacles
	// the clear sector nearest the target (figure 60) does.
	const double ws = farRangeWeight(nearest_mm);
	// Blended on the circle (the sector search covers +-180 deg: a linear blend
	// of -170 and +170 deg would give 0, straight ahead).
	heading = sectors.target_clear
				  ? target.bearing_rad
				  : mrpt::math::wrapToPi(sectors.chosen_rad + ws * mrpt::math::wrapToPi(target.bearing_rad - sectors.chosen_rad));
	layer = sectors.target_clear ? ENavLayer::target : ENavLayer::sector;
	const double wa = sideAvoidanceWeight(nearest_mm);  // eq. 36
	return m_opts.controller.heading_gain_per_s * heading + wa * side.w_rad_s;
}

void CSubsumptionController::blendLayers(const CPolarProfile& profile, const TTargetSeekingOutput& seek, double t_s,
										 TNavCommand& cmd)
{
	const auto ring = virtualSonars(profile, m_opts.controller.virtual_sonar_cone_rad);
	double v = std::min({seek.v_mps, m_velocityControl.evaluate(ring), 1e-3 * m_opts.controller.max_speed_mm_s});
	const auto sectors = m_sectors.evaluate(profile, seek.bearing_rad, seek.distance_m);
	const auto boundary = m_boundary.update(profile, seek.distance_m, sectors.target_clear, t_s);
	const double maxW = m_opts.controller.max_turn_rate_rad_s;
	if (boundary.active)
	{
		m_turnDirection = 0;
		cmd.v_mps = std::min(v, boundary.v_mps);
		cmd.w_rad_s = std::clamp(boundary.w_rad_s, -maxW, maxW);
		cmd.layer = ENavLayer::boundary;
		return;
	}
	double heading = 0;
	cmd.w_rad_s =
		std::clamp(rotationCommand(ring, sectors, seek, v, cmd.nearest_m * 1e3, cmd.layer, heading), -maxW, maxW);
	// Figure 59: forward turning subsumes v with 0 when the turn is too sharp.
	// The heading to steer by decides, not the clipped rate: 60 deg/s / 1.5 per s
	// stands for 40 deg at most, so the 70 deg rule never fired on the clipped w.
	if (!m_forwardTurning.allowsForwardMotion(heading))
	{
		// A turn in place keeps its direction while the heading lies behind
		// (beyond 90 deg) on the other side: with the sector search all round,
		// a heading near 180 deg flips sign as the robot turns, and it would
		// rock in place (U-trap, docs/nav.md).
		if (m_turnDirection != 0 && heading * m_turnDirection < 0 && std::abs(heading) > 0.5 * M_PI)
			cmd.w_rad_s = m_turnDirection * maxW;
		m_turnDirection = cmd.w_rad_s >= 0 ? 1 : -1;
		v = 0, cmd.turn_in_place = true;
	}
	else
		m_turnDirection = 0;
	cmd.v_mps = std::max(0.0, v);
}

TNavCommand CSubsumptionController::step(const mrpt::math::TPose2D& pose,
										 const mrpt::obs::CObservation2DRangeScan* scan,
										 const mrpt::obs::CObservationRange* sonar, double t_s)
{
	TNavCommand cmd;
	m_fusion.fuseInto(m_profile, scan, sonar);
	const CPolarProfile& profile = m_profile;
	cmd.nearest_m = profile.minRange(-M_PI, M_PI);
	cmd.targets_reached = m_targets.reachedCount();
	auto target = m_targets.current();
	if (!target)
	{
		cmd.state = m_targets.targets().empty() ? ENavState::no_target : ENavState::target_reached;
		return cmd;
	}
	auto seek = m_targetSeeking.evaluate(pose, *target);
	while (seek.reached)  // stop at the target, then go on to the next one
	{
		m_targets.advance();
		m_boundary.reset();
		cmd.targets_reached = m_targets.reachedCount();
		if (!(target = m_targets.current()))
		{
			cmd.state = ENavState::target_reached;
			return cmd;
		}
		seek = m_targetSeeking.evaluate(pose, *target);
	}
	const auto escape = m_forwardTurning.update(profile, pose, t_s);
	if (escape.escaping)
	{
		cmd.state = ENavState::escaping;
		cmd.v_mps = escape.v_mps;
		cmd.w_rad_s = escape.w_rad_s;
		cmd.layer = ENavLayer::forward_turning;
		return cmd;
	}
	blendLayers(profile, seek, t_s, cmd);
	cmd.state = ENavState::navigating;
	return cmd;
}

}  // namespace hslam::nav
