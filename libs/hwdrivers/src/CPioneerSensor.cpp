/* hslam: Pioneer CGenericSensor (see CPioneerSensor.h). */
#include <hslam/common/options_io.h>
#include <hslam/hwdrivers/CPioneerSensor.h>
#include <mrpt/obs/CObservationBatteryState.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRange.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string_view>

IMPLEMENTS_GENERIC_SENSOR(CPioneerSensor, hslam::hwdrivers)

namespace hslam::hwdrivers
{
CPioneerSensor::CPioneerSensor() : mrpt::system::COutputLogger("CPioneerSensor")
{
	// COutputLogger prints to the console as for MRPT's own sensors (INFO and
	// WARN on std::cout, ERROR on std::cerr). std::cout is block-buffered when
	// rawlog-grabber's console goes to a file, so link events would show up
	// late: a callback (run after the console output) flushes it.
	logRegisterCallback([](std::string_view, mrpt::system::VerbosityLevel, std::string_view, mrpt::Clock::time_point) {
		std::cout.flush();
	});
	m_sensorLabel = "PIONEER";
	setOptions(TOptions());
}

CPioneerSensor::~CPioneerSensor() = default;

void CPioneerSensor::setOptions(const TOptions& opts)
{
	try
	{
		m_sonarPoses = parseSonarPoses(opts.sonar_poses);
	}
	catch (const std::invalid_argument& e)
	{
		throw hslam::common::config_error("sonar_poses = '" + opts.sonar_poses + "': " + e.what());
	}
	m_opts = opts;
	m_driver = std::make_unique<CPioneerDriver>(m_opts.driver);
	m_teleop.reset();
}

void CPioneerSensor::loadConfig_sensorSpecific(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	TOptions o;
	hslam::common::loadOptions(o, cfg, section);
	try
	{
		setOptions(o);
	}
	catch (const hslam::common::config_error& e)
	{
		throw hslam::common::config_error("[" + section + "] " + e.what());
	}
}

void CPioneerSensor::initialize()
{
	if (m_opts.teleop_udp_port > 0) m_teleop = std::make_unique<CUdpVelocityReceiver>(m_opts.teleop_udp_port);
	if (!m_driver->connect())
		MRPT_LOG_WARN_STREAM("connection failed (will retry): " << m_driver->stats().lastError);
	m_state = ssWorking;
}

void CPioneerSensor::doProcess()
{
	if (m_teleop)
		if (const auto cmd = m_teleop->poll()) m_driver->setVelocity(cmd->first, cmd->second);
	// Wait at most half a processing period, and never more than 50 ms, so
	// rawlog-grabber's rate timer keeps its pace.
	const double rate = m_process_rate > 0 ? m_process_rate : 20.0;
	const auto states = m_driver->spinOnce(std::min(0.05, 0.5 / rate));
	const bool connected = m_driver->isConnected();
	if (connected != m_wasConnected)
	{
		const auto s = m_driver->stats();
		const std::string msg = connected ? "link up: " + s.robotName + " " + s.robotClass + " " + s.robotSubclass +
												" (connection #" + std::to_string(s.connections) + ")"
										  : "link down: " + s.lastError;
		if (connected)
			MRPT_LOG_INFO(msg);
		else
			MRPT_LOG_WARN(msg);
		emitComment(msg, mrpt::Clock::now());
		m_wasConnected = connected;
	}
	for (const auto& st : states) emitState(st);
}

void CPioneerSensor::emitComment(const std::string& text, mrpt::Clock::time_point t)
{
	auto c = mrpt::obs::CObservationComment::Create();
	c->timestamp = t;
	c->sensorLabel = m_opts.bumper_label;
	c->text = text;
	appendObservation(c);
}

void CPioneerSensor::emitState(const TPioneerState& st)
{
	auto odo = mrpt::obs::CObservationOdometry::Create();
	odo->timestamp = st.timestamp;
	odo->sensorLabel = m_opts.odometry_label;
	odo->odometry = st.odometry;
	odo->hasVelocities = true;
	odo->velocityLocal = st.velocityLocal;
	appendObservation(odo);

	if (!st.sip.sonars.empty())
	{
		auto rng = mrpt::obs::CObservationRange::Create();
		rng->timestamp = st.timestamp;
		rng->sensorLabel = m_opts.sonar_label;
		rng->minSensorDistance = static_cast<float>(m_opts.sonar_min_range_m);
		rng->maxSensorDistance = static_cast<float>(m_opts.sonar_max_range_m);
		rng->sensorConeApperture = static_cast<float>(m_opts.sonar_cone_rad);
		for (const auto& s : st.sip.sonars)
		{
			if (s.index >= m_sonarPoses.size()) continue;  // sonar not configured (e.g. rear ring)
			mrpt::obs::CObservationRange::TMeasurement m;
			m.sensorID = s.index;
			const auto& p = m_sonarPoses[s.index];
			m.sensorPose = mrpt::math::TPose3D(p.x, p.y, m_opts.sonar_z_m, p.phi, 0, 0);
			const double r_m = s.range_raw * m_opts.driver.conversion.range_mm_per_unit * 1e-3;
			m.sensedDistance = static_cast<float>(std::min(r_m, m_opts.sonar_max_range_m));
			rng->sensedData.push_back(m);
		}
		if (!rng->sensedData.empty()) appendObservation(rng);
	}

	if (std::chrono::duration<double>(st.timestamp - m_lastBattery).count() >= m_opts.battery_period_s)
	{
		auto bat = mrpt::obs::CObservationBatteryState::Create();
		bat->timestamp = st.timestamp;
		bat->sensorLabel = m_opts.battery_label;
		bat->voltageMainRobotBattery = st.battery_V;
		bat->voltageMainRobotBatteryIsValid = true;
		appendObservation(bat);
		m_lastBattery = st.timestamp;
	}

	if (static_cast<int>(st.sip.stall_bump) != m_lastBumpState)
	{
		char text[160];
		std::snprintf(text, sizeof(text), "bumpers front=0x%02X rear=0x%02X stall_left=%d stall_right=%d",
					  st.sip.frontBumpers(), st.sip.rearBumpers(), st.sip.leftStall() ? 1 : 0,
					  st.sip.rightStall() ? 1 : 0);
		emitComment(text, st.timestamp);
		m_lastBumpState = st.sip.stall_bump;
	}
}

void registerHwdriversSensors() { CPioneerSensor::doRegister(); }

}  // namespace hslam::hwdrivers
