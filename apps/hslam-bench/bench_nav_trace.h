/* hslam-bench nav --trace DIR: per run, the path over the world (PNG) and,
 * for our controller, every control step (CSV: pose, command, state, the
 * layer that set the rotation), to see where a run gets stuck. */
#pragma once

#include <hslam/sim/CSubsumptionDriver.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>

#include <string>
#include <vector>

namespace hslam::bench
{
struct TNavTraceStep
{
	double t_s = 0;
	mrpt::math::TPose2D pose;
	nav::TNavCommand cmd;
};

/** Our controller, recording every step. */
class CTracingSubsumptionDriver : public sim::CSubsumptionDriver
{
   public:
	using sim::CSubsumptionDriver::CSubsumptionDriver;
	sim::TControlOutput control(const sim::TControlInput& in) override
	{
		const auto out = CSubsumptionDriver::control(in);
		steps.push_back({in.t_s, in.pose, last});
		return out;
	}
	std::vector<TNavTraceStep> steps;
};

/** Writes `dir`/`name`.png (path coloured by the layer that steered, or by
 * speed when `steps` is empty, over the world) and, with steps, `name`.csv. */
void writeNavTrace(const std::string& dir, const std::string& name, const sim::TScene& scene,
				   const sim::TNavScenario& scenario, const sim::TClosedLoopResult& result,
				   const std::vector<TNavTraceStep>& steps);
}  // namespace hslam::bench
