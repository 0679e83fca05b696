/* hslam: Pioneer P3-DX as an MRPT CGenericSensor (driver = CPioneerSensor).
 *
 * Usable from MRPT's rawlog-grabber through the plug-in module
 * (rawlog-grabber -p libhslam-hwdrivers-plugin.so grab.ini) and from hslam-grabber.
 * Per SIP (10 Hz) it emits:
 *  - CObservationOdometry (label odometry_label): accumulated pose with
 *    wrap-around handled (CArcosOdometry), wheel-derived velocities;
 *  - CObservationRange (label sonar_label): the sonars updated in that SIP,
 *    one TMeasurement each with sensorID = sonar index, its pose from
 *    sonar_poses, range in metres clamped to [0, sonar_max_range_m];
 * plus CObservationBatteryState every battery_period_s, and a CObservationComment
 * (label bumper_label) whenever bumpers/stall bits change or the link drops or
 * comes back (so a rawlog documents outages). Velocity commands come from
 * driver().setVelocity() (hslam-grabber teleop) or, with teleop_udp_port > 0,
 * from loopback UDP datagrams "v_mps w_rad_s" (CUdpVelocityReceiver).
 *
 * INI section: the common CGenericSensor keys (driver, process_rate, sensorLabel,
 * max_queue_len, grab_decimation) plus TOptions below; unknown keys are rejected.
 * Keys are documented in config_ini/grabber-pioneer-*.ini. */
#pragma once

#include <hslam/hwdrivers/CPioneerDriver.h>
#include <hslam/hwdrivers/CUdpVelocityReceiver.h>
#include <hslam/hwdrivers/p3dx_geometry.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/system/COutputLogger.h>

#include <memory>

namespace hslam::hwdrivers
{
/** Logs through MRPT's COutputLogger, as MRPT's own sensors do
 * (C2DRangeFinderAbstract): link up/down and failed connections. */
class CPioneerSensor : public mrpt::system::COutputLogger, public mrpt::hwdrivers::CGenericSensor
{
	DEFINE_GENERIC_SENSOR(CPioneerSensor)

   public:
	struct TOptions
	{
		CPioneerDriver::TOptions driver;
		std::string odometry_label = "ODOMETRY";
		std::string sonar_label = "SONAR";
		std::string battery_label = "BATTERY";
		std::string bumper_label = "BUMPERS";
		std::string sonar_poses = P3DX_FRONT_SONAR_POSES;
		double sonar_z_m = 0.2;
		double sonar_cone_rad = 20.0 * M_PI / 180.0;
		double sonar_min_range_m = 0.1;
		double sonar_max_range_m = 5.0;
		double battery_period_s = 1.0;
		int teleop_udp_port = 0;
		// Keys read by CGenericSensor::loadConfig / rawlog-grabber themselves:
		std::string c_driver, c_rate, c_label, c_queue, c_decim, c_ignore;

		template <class V>
		void visit(V& v)
		{
			driver.visit(v);
			v.text("odometry_label", odometry_label);
			v.text("sonar_label", sonar_label);
			v.text("battery_label", battery_label);
			v.text("bumper_label", bumper_label);
			v.text("sonar_poses", sonar_poses);
			v.real("sonar_z_m", sonar_z_m, -2.0, 2.0);
			v.degrees("sonar_cone_deg", sonar_cone_rad, 1.0, 90.0);
			v.real("sonar_min_range_m", sonar_min_range_m, 0.0, 1.0);
			v.real("sonar_max_range_m", sonar_max_range_m, 0.5, 20.0);
			v.real("battery_period_s", battery_period_s, 0.1, 3600.0);
			v.integer("teleop_udp_port", teleop_udp_port, 0, 65535);
			v.text("driver", c_driver);
			v.text("process_rate", c_rate);
			v.text("sensorLabel", c_label);
			v.text("max_queue_len", c_queue);
			v.text("grab_decimation", c_decim);
			v.text("rawlog-grabber-ignore", c_ignore);
		}
	};

	CPioneerSensor();
	~CPioneerSensor() override;

	/** Connects (a failure is reported and retried by doProcess). */
	void initialize() override;
	/** Reads the SIPs available now (bounded wait) and queues observations. */
	void doProcess() override;

	CPioneerDriver& driver() { return *m_driver; }
	const TOptions& options() const { return m_opts; }

	/** Options from an INI section (throws hslam::common::config_error). */
	void setOptions(const TOptions& opts);

   protected:
	void loadConfig_sensorSpecific(const mrpt::config::CConfigFileBase& cfg, const std::string& section) override;

   private:
	void emitState(const TPioneerState& st);
	void emitComment(const std::string& text, mrpt::Clock::time_point t);

	TOptions m_opts;
	std::vector<mrpt::math::TPose2D> m_sonarPoses;
	std::unique_ptr<CPioneerDriver> m_driver;
	std::unique_ptr<CUdpVelocityReceiver> m_teleop;
	mrpt::Clock::time_point m_lastBattery{};
	int m_lastBumpState = -1;
	bool m_wasConnected = false;
};

/** Registers hslam's sensor classes with MRPT's CGenericSensor factory (called
 * by the plug-in module at load time and by hslam-grabber). Idempotent. */
void registerHwdriversSensors();

}  // namespace hslam::hwdrivers
