/* hslam sim: our subsumption controller (libs/nav, thesis 4.2) as a
 * closed-loop controller of the simulated robot. */
#pragma once

#include <hslam/nav/CSubsumptionController.h>
#include <hslam/sim/closed_loop.h>

namespace hslam::sim
{
class CSubsumptionDriver : public IClosedLoopController
{
   public:
	CSubsumptionDriver(const nav::TSubsumptionOptions& options, std::vector<mrpt::math::TPoint2D> targets)
		: m_controller(options)
	{
		m_controller.setTargets(std::move(targets));
	}
	TControlOutput control(const TControlInput& in) override
	{
		last = m_controller.step(in.pose, in.scan, in.sonar, in.t_s);
		return {last.v_mps, last.w_rad_s, last.state == nav::ENavState::target_reached, false};
	}
	const nav::CSubsumptionController& controller() const { return m_controller; }
	nav::TNavCommand last;  //!< the latest command and state

   private:
	nav::CSubsumptionController m_controller;
};
}  // namespace hslam::sim
