/* hslam sim: a navigation controller driving the simulated robot in a closed
 * loop (thesis 4.2.2: the controller was tried in a simulator; 4.9: driven
 * runs). Any controller (ours, MRPT's reactive navigator) implements
 * IClosedLoopController; the runner steps the simulator (path mode external),
 * hands the controller the latest laser scan, sonar ring and pose every
 * control_period_s, applies its (v, w), and scores the run: path length, time,
 * minimum clearance to the obstacles (people included), collisions (clearance
 * below collision_radius_m with a static obstacle, the P3-DX footprint seen
 * as a disc), person contacts (the simulated people walk their paths blind,
 * through a robot in their way, so touching them is counted apart, per
 * control period), CPU time per control step
 * (thread CPU clock, only inside control()). A collision ends the run (the
 * simulator has no contact physics). No file I/O. */
#pragma once

#include <hslam/sim/CSimulator.h>

#include <vector>

namespace hslam::sim
{
struct TControlInput
{
	double t_s = 0;  //!< elapsed since the start of the run
	mrpt::math::TPose2D pose;  //!< true or odometry pose (TClosedLoopOptions::use_odometry_pose)
	const mrpt::obs::CObservation2DRangeScan* scan = nullptr;  //!< latest, may be null
	const mrpt::obs::CObservationRange* sonar = nullptr;  //!< latest, may be null
};

struct TControlOutput
{
	double v_mps = 0, w_rad_s = 0;
	bool finished = false;  //!< the controller reached its last target and stopped
	bool failed = false;  //!< the controller gave up
};

class IClosedLoopController
{
   public:
	virtual ~IClosedLoopController() = default;
	virtual TControlOutput control(const TControlInput& input) = 0;
};

struct TClosedLoopOptions
{
	double control_period_s = 0.1;  //!< Pioneer SIP cycle
	double timeout_s = 240;
	double collision_radius_m = 0.2;  //!< P3-DX: 381 mm wide, 455 mm long (centre 35 mm behind the middle)
	bool use_odometry_pose = false;  //!< false: a localised robot (MobileSim's perfect odometry in the thesis)
	double path_sample_period_s = 0.5;  //!< spacing of the recorded path samples
};

struct TPathSample
{
	double t_s = 0;
	mrpt::math::TPose2D pose;
	double v_mps = 0;
	double clearance_m = 0;
};

struct TClosedLoopResult
{
	bool finished = false;  //!< controller reported finished
	bool failed = false;
	bool collided = false;
	int person_contacts = 0;  //!< control periods in which a walking person touched the robot
	bool timed_out = false;
	double path_length_m = 0, time_s = 0;
	double min_clearance_m = 1e9;
	double min_static_clearance_m = 1e9;  //!< to static obstacles only (people left out)
	double cpu_s = 0;  //!< total CPU time inside control()
	size_t control_steps = 0;
	std::vector<TPathSample> path;
	double cpuPerStep_us() const { return control_steps ? 1e6 * cpu_s / control_steps : 0; }
	bool success() const { return finished && !collided; }
};

/** Runs until the controller finishes or fails, a collision, or the timeout.
 * `sink` (optional) also receives every observation (e.g. a rawlog writer). */
TClosedLoopResult runClosedLoop(CSimulator& sim, IClosedLoopController& controller, const TClosedLoopOptions& options,
								ISimulationSink* sink = nullptr);

}  // namespace hslam::sim
