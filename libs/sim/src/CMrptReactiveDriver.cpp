/* hslam sim: CMrptReactiveDriver (see CMrptReactiveDriver.h). */
#include <hslam/sim/CMrptReactiveDriver.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>

#include <stdexcept>

namespace hslam::sim
{
namespace
{
/** MRPT's navigator without the profilers that print their statistics on
 * destruction (one dump per run would flood the bench's output). */
class CQuietReactiveNavigator : public mrpt::nav::CReactiveNavigationSystem
{
   public:
	explicit CQuietReactiveNavigator(mrpt::nav::CRobot2NavInterface& robot)
		: CReactiveNavigationSystem(robot, false /*console*/, false /*log file*/)
	{
		m_timlog_delays.disable();
		m_navProfiler.disable();
	}
};
}  // namespace

std::string mrptReactiveConfig(const std::string& configText, const TMrptReactiveOptions& o)
{
	const auto& m = o.holonomic_method;
	if (m != "CHolonomicND" && m != "CHolonomicVFF" && m != "CHolonomicFullEval")
		throw std::invalid_argument("MRPT holonomic method '" + m + "': expected CHolonomicND, CHolonomicVFF or CHolonomicFullEval");
	mrpt::config::CConfigFileMemory cfg(configText);
	cfg.write("CAbstractPTGBasedReactive", "holonomic_method", m);
	cfg.write("CAbstractPTGBasedReactive", "ptg_cache_files_directory", o.ptg_cache_dir);
	if (o.p3dx_footprint)
	{
		// 455 mm long, rotation centre 35 mm behind the middle: front +262.5 mm, rear -192.5 mm; 381 mm wide.
		cfg.write("CReactiveNavigationSystem", "RobotModel_shape2D_xs", std::string("-0.1925 0.2625 0.2625 -0.1925"));
		cfg.write("CReactiveNavigationSystem", "RobotModel_shape2D_ys", std::string("0.1905 0.1905 -0.1905 -0.1905"));
	}
	std::string out;
	cfg.getContent(out);
	return out;
}

CMrptReactiveDriver::CMrptReactiveDriver(const std::string& configText, const TMrptReactiveOptions& o,
										 const mrpt::math::TPoint2D& target, double clockOrigin_s)
	: m_robot(std::make_unique<CSimRobot2NavInterface>(clockOrigin_s)),
	  m_target(target),
	  m_allowed_m(o.target_allowed_distance_m)
{
	m_robot->setMinLoggingLevel(mrpt::system::LVL_ERROR);
	m_nav = std::make_unique<CQuietReactiveNavigator>(*m_robot);
	m_nav->setMinLoggingLevel(mrpt::system::LVL_ERROR);
	m_nav->loadConfigFile(mrpt::config::CConfigFileMemory(mrptReactiveConfig(configText, o)));
	m_nav->initialize();
}

CMrptReactiveDriver::~CMrptReactiveDriver() = default;

int CMrptReactiveDriver::navigatorState() const { return static_cast<int>(m_nav->getCurrentState()); }

TControlOutput CMrptReactiveDriver::control(const TControlInput& in)
{
	m_robot->setInput(in);
	if (!m_started)
	{
		mrpt::nav::CAbstractNavigator::TNavigationParams p;
		p.target.target_coords = mrpt::math::TPose2D(m_target.x, m_target.y, 0);
		p.target.targetAllowedDistance = static_cast<float>(m_allowed_m);
		p.target.targetIsRelative = false;
		m_robot->resetNavigationTimer();
		m_nav->navigate(&p);
		m_started = true;
	}
	m_nav->navigationStep();
	TControlOutput out{m_robot->commandV_mps(), m_robot->commandW_rad_s()};
	const auto state = m_nav->getCurrentState();
	out.finished = state == mrpt::nav::CAbstractNavigator::IDLE;  // it stops itself at the target
	out.failed = state == mrpt::nav::CAbstractNavigator::NAV_ERROR;
	if (out.finished || out.failed) out.v_mps = out.w_rad_s = 0;
	return out;
}
}  // namespace hslam::sim
