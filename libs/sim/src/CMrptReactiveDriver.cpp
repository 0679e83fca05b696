/* hslam sim: CMrptReactiveDriver (see CMrptReactiveDriver.h). */
#include <hslam/sim/CMrptReactiveDriver.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/format.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>


#include <algorithm>
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
constexpr const char* kPtgSection = "CReactiveNavigationSystem";

/** Renumbers the PTGs of [CReactiveNavigationSystem] without those whose K
 * (direction of motion) is negative; returns how many are kept. */
int dropReversePtgs(mrpt::config::CConfigFileMemory& cfg)
{
	const int count = cfg.read_int(kPtgSection, "PTG_COUNT", 0, true);
	std::vector<std::string> keys;
	cfg.getAllKeys(kPtgSection, keys);
	int kept = 0;
	for (int i = 0; i < count; ++i)
	{
		if (cfg.read_double(kPtgSection, mrpt::format("PTG%d_K", i), 1.0) < 0) continue;
		const std::string from = mrpt::format("PTG%d_", i), to = mrpt::format("PTG%d_", kept);
		for (const auto& k : keys)
			if (k.rfind(from, 0) == 0 && i != kept)
				cfg.write(kPtgSection, to + k.substr(from.size()), cfg.read_string(kPtgSection, k, ""));
		++kept;
	}
	if (kept == 0) throw std::invalid_argument("MRPT reactive config: no forward PTG left");
	cfg.write(kPtgSection, "PTG_COUNT", kept);
	return kept;
}

/** The P3-DX footprint (455 mm long, rotation centre 35 mm behind the middle:
 * front +262.5 mm, rear -192.5 mm; 381 mm wide) grown to contain a disc of radius r. */
void writeP3dxFootprint(mrpt::config::CConfigFileMemory& cfg, double r)
{
	const double front = std::max(0.2625, r), rear = -std::max(0.1925, r), side = std::max(0.1905, r);
	cfg.write(kPtgSection, "RobotModel_shape2D_xs", mrpt::format("%.4f %.4f %.4f %.4f", rear, front, front, rear));
	cfg.write(kPtgSection, "RobotModel_shape2D_ys", mrpt::format("%.4f %.4f %.4f %.4f", side, side, -side, -side));
}
/** Every speed limit of the navigator and its PTGs to v (m/s). */
void writeMaxSpeed(mrpt::config::CConfigFileMemory& cfg, double v)
{
	cfg.write("CAbstractPTGBasedReactive", "robotMax_V_mps", v);
	const int count = cfg.read_int(kPtgSection, "PTG_COUNT", 0, true);
	for (int i = 0; i < count; ++i) cfg.write(kPtgSection, mrpt::format("PTG%d_v_max_mps", i), v);
}
}  // namespace

std::string mrptReactiveConfig(const std::string& configText, const TMrptReactiveOptions& o)
{
	const auto& m = o.holonomic_method;
	if (m != "CHolonomicND" && m != "CHolonomicVFF" && m != "CHolonomicFullEval")
		throw std::invalid_argument("MRPT holonomic method '" + m + "': expected CHolonomicND, CHolonomicVFF or CHolonomicFullEval");
	mrpt::config::CConfigFileMemory cfg(configText);
	cfg.write("CAbstractPTGBasedReactive", "holonomic_method", m);
	if (o.p3dx_footprint) writeP3dxFootprint(cfg, o.footprint_min_radius_m);
	if (o.forward_ptgs_only) dropReversePtgs(cfg);
	if (o.max_speed_mps > 0) writeMaxSpeed(cfg, o.max_speed_mps);
	std::string out;
	cfg.getContent(out);
	return out;
}

CMrptReactiveDriver::CMrptReactiveDriver(const std::string& configText, const TMrptReactiveOptions& o,
										 const mrpt::math::TPoint2D& target, double clockOrigin_s)
	: m_robot(std::make_unique<CSimRobot2NavInterface>(clockOrigin_s, o.compensate_scan_age, o.use_sonar)),
	  m_target(target),
	  m_allowed_m(o.target_allowed_distance_m)
{
	m_robot->setMinLoggingLevel(mrpt::system::LVL_ERROR);
	m_nav = std::make_unique<CQuietReactiveNavigator>(*m_robot);
	m_nav->setMinLoggingLevel(mrpt::system::LVL_ERROR);
	m_nav->loadConfigFile(mrpt::config::CConfigFileMemory(mrptReactiveConfig(configText, o)));
	// Not read from the INI by MRPT 2.5: set after loading (MRPT's default "." is the working directory).
	m_nav->params_abstract_ptg_navigator.ptg_cache_files_directory = o.ptg_cache_dir;
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
