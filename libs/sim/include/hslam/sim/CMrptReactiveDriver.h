/* hslam sim: MRPT 2.5's reactive navigator (mrpt::nav::CReactiveNavigationSystem:
 * PTGs + a holonomic method in TP-space) as a closed-loop controller of our
 * simulated P3-DX, the peer our subsumption controller (thesis 4.2) is
 * benchmarked against (hslam-bench nav). Headless: no log files, no console
 * output, the robot interface is CSimRobot2NavInterface.
 *
 * Configuration: the text of an MRPT reactive INI (the caller reads the file,
 * e.g. the stock kMrptReactive2dConfig), with the overrides of
 * TMrptReactiveOptions written on top: the holonomic method, the P3-DX
 * footprint instead of the stock 0.3 x 0.2 m polygon (widened to contain the
 * closed loop's collision disc, so that MRPT's collision-free is ours), the
 * reverse PTGs left out (our P3-DX senses ahead only: the LMS200's 180 deg
 * and the front sonar ring; MRPT keeps no obstacle memory, so a backward
 * path is planned through space no sensor sees), optionally one speed cap
 * for the navigator and its PTGs (stock: 1 m/s, 60 deg/s), the directory where
 * MRPT caches its PTG collision grids (MRPT's own file I/O; building the
 * grids takes seconds, loading them a fraction). The navigator is initialised
 * (PTGs built or loaded) in the constructor, so control() times one
 * navigation step only. */
#pragma once

#include <hslam/sim/CSimRobot2NavInterface.h>
#include <hslam/sim/closed_loop.h>

#include <memory>
#include <string>

namespace mrpt::nav
{
class CReactiveNavigationSystem;
}

namespace hslam::sim
{
/** The stock configuration shipped with mrpt-common. */
inline const char* kMrptReactive2dConfig = "/usr/share/mrpt/config_files/navigation-ptgs/reactive2d_config.ini";

struct TMrptReactiveOptions
{
	std::string holonomic_method = "CHolonomicND";  //!< CHolonomicND | CHolonomicVFF | CHolonomicFullEval
	double target_allowed_distance_m = 0.2;  //!< as ours: 200 mm (thesis App. A, CTargetSeekingLayer)
	bool p3dx_footprint = true;  //!< P3-DX 455 x 381 mm, rotation centre 35 mm behind the middle
	double footprint_min_radius_m = 0.2;  //!< the footprint is widened to contain this disc (TClosedLoopOptions::collision_radius_m)
	bool forward_ptgs_only = true;  //!< leave out the PTGs with K < 0 (backward motion; stock: PTG2)
	bool compensate_scan_age = true;  //!< obstacles moved into the current robot frame (CSimRobot2NavInterface)
	double max_speed_mps = 0;  //!< > 0: robotMax_V_mps and every PTG's v_max set to this (stock: 1.0); changes the PTGs, use its own ptg_cache_dir
	bool use_sonar = false;  //!< sonar echoes as obstacle points too (CSimRobot2NavInterface); default: the laser only
	std::string ptg_cache_dir = ".";  //!< where MRPT writes/reads ReacNavGrid_*.dat.gz
};

class CMrptReactiveDriver : public IClosedLoopController
{
   public:
	/** `configText`: the INI's content; `clockOrigin_s`: the simulation's start_time_s. */
	CMrptReactiveDriver(const std::string& configText, const TMrptReactiveOptions& options,
						const mrpt::math::TPoint2D& target, double clockOrigin_s);
	~CMrptReactiveDriver() override;

	TControlOutput control(const TControlInput& in) override;

	/** mrpt::nav::CAbstractNavigator::TState of the navigator (0 idle, 1 navigating, 3 error). */
	int navigatorState() const;
	const CSimRobot2NavInterface& robot() const { return *m_robot; }

   private:
	std::unique_ptr<CSimRobot2NavInterface> m_robot;
	std::unique_ptr<mrpt::nav::CReactiveNavigationSystem> m_nav;
	mrpt::math::TPoint2D m_target;
	double m_allowed_m;
	bool m_started = false;
};

/** The INI text `configText` with the options' overrides written on top. */
std::string mrptReactiveConfig(const std::string& configText, const TMrptReactiveOptions& options);

}  // namespace hslam::sim
