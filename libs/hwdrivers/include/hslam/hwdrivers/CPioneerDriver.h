/* hslam: Pioneer P3-DX client driver over the ARCOS protocol.
 *
 * Connection (../shared/notes/mrpt-plugins-and-protocols.md s.3): SYNC0, SYNC1,
 * SYNC2 (reply: robot name, class, subclass), OPEN, PULSE, then ENABLE 1, SONAR 1
 * and (first connection only) SETO; the robot streams SIPs every 100 ms. If a
 * SIP arrives during the handshake a previous session is still open: CLOSE and
 * restart at SYNC0. The robot stops by itself when it hears nothing for 2 s,
 * so spinOnce() sends VEL/RVEL (or PULSE) every pulse_period_s.
 *
 * Motion: setVelocity(v, w) may be called from any thread; the driver's own
 * watchdog zeroes the command when no new command came for command_timeout_s
 * (teleoperation or the obstacle avoider died), independently of the robot's.
 *
 * Faults: corrupted/partial packets and garbage are dropped by the parser
 * (counted in stats()); a link error (EOF, I/O error) or no SIP for
 * silence_timeout_s closes the link and spinOnce() reconnects every
 * reconnect_period_s. Odometry continues across reconnections (the increment
 * from the last SIP before the outage is unwrapped like any other). */
#pragma once

#include <hslam/hwdrivers/CArcosOdometry.h>
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/arcos_sip.h>
#include <hslam/hwdrivers/byte_stream.h>
#include <mrpt/core/Clock.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hslam::hwdrivers
{
/** Robot state decoded from one SIP. */
struct TPioneerState
{
	mrpt::Clock::time_point timestamp;  //!< PC time at reception
	arcos::TSip sip;  //!< raw packet fields (bumpers, flags, sonar raw ranges)
	mrpt::poses::CPose2D odometry;  //!< accumulated, unwrapped
	mrpt::math::TTwist2D velocityLocal;
	double leftWheel_mps = 0, rightWheel_mps = 0;
	double battery_V = 0;
};

struct TPioneerDriverStats
{
	bool connected = false;
	uint64_t connections = 0;  //!< successful handshakes
	uint64_t failedConnections = 0;
	uint64_t linkErrors = 0;  //!< EOF / I/O errors
	uint64_t silenceTimeouts = 0;  //!< no SIP for silence_timeout_s
	uint64_t watchdogStops = 0;  //!< commands zeroed by the command watchdog
	uint64_t sips = 0;
	uint64_t otherPackets = 0;
	uint64_t malformedSips = 0;
	arcos::CArcosPacketParser::TStats parser;
	std::string lastError;
	/** The driver's own clock of the link: when it last heard the robot (last
	 * SIP, or the handshake) and when it last closed the link (silence or
	 * link error). Tests compare these instead of their own wall clock. */
	mrpt::Clock::time_point lastHeard{}, lastLinkLoss{};
	/** Link outages ended by a reconnection: count, total and longest (s). */
	uint64_t outages = 0;
	double outageTotal_s = 0, longestOutage_s = 0;
	std::string robotName, robotClass, robotSubclass;
};

class CPioneerDriver
{
   public:
	struct TOptions
	{
		std::string serial_port;  //!< device path; empty -> TCP
		int baud = 9600;
		std::string tcp_host = "localhost";
		int tcp_port = 8101;
		double pulse_period_s = 0.5;
		double command_timeout_s = 0.6;
		double silence_timeout_s = 1.0;
		double reconnect_period_s = 0.5;
		double handshake_timeout_s = 0.3;  //!< per SYNC step (3 steps, up to 3 tries)
		bool enable_motors = true;
		bool enable_sonar = true;
		bool reset_odometry = true;
		double max_v_mps = 0.75;
		double max_w_rad_s = 100.0 * M_PI / 180.0;
		TArcosConversion conversion;

		template <class V>
		void visit(V& v)
		{
			v.text("COM_port_LIN", serial_port);
			v.integer("COM_baudRate", baud, 9600, 115200);
			v.text("tcp_host", tcp_host);
			v.integer("tcp_port", tcp_port, 1, 65535);
			v.real("pulse_period_s", pulse_period_s, 0.05, 1.9);
			v.real("command_timeout_s", command_timeout_s, 0.05, 10.0);
			v.real("silence_timeout_s", silence_timeout_s, 0.2, 10.0);
			v.real("reconnect_period_s", reconnect_period_s, 0.05, 60.0);
			v.real("handshake_timeout_s", handshake_timeout_s, 0.05, 10.0);
			v.flag("enable_motors", enable_motors);
			v.flag("enable_sonar", enable_sonar);
			v.flag("reset_odometry", reset_odometry);
			v.real("max_v_mps", max_v_mps, 0.0, 2.2);
			v.degrees("max_w_deg_s", max_w_rad_s, 0.0, 500.0);
			conversion.visit(v);
		}
	};

	using TStreamFactory = std::function<std::unique_ptr<CByteStream>()>;

	CPioneerDriver() : CPioneerDriver(TOptions()) {}
	explicit CPioneerDriver(const TOptions& options);
	~CPioneerDriver();

	/** Replaces the transport chosen from the options (serial or TCP). */
	void setStreamFactory(TStreamFactory factory) { m_factory = std::move(factory); }

	/** One connection attempt (open + handshake + start-up commands). Returns
	 * false with stats().lastError on failure; never throws for link problems. */
	bool connect();

	/** Stops the robot, sends CLOSE and closes the link. */
	void disconnect();

	/** Reads for up to timeout_s, returns the states of the SIPs received,
	 * sends keep-alives/commands, runs the watchdogs and reconnects. */
	std::vector<TPioneerState> spinOnce(double timeout_s);

	/** Commands translational (m/s) and rotational (rad/s, CCW +) velocity,
	 * clamped to max_v_mps / max_w_rad_s. Thread-safe. */
	void setVelocity(double v_mps, double w_rad_s);
	void stop() { setVelocity(0, 0); }

	TPioneerDriverStats stats() const;
	bool isConnected() const;
	const TOptions& options() const { return m_opts; }

   private:
	void send(const std::vector<uint8_t>& packet);
	/** Waits for a packet whose first payload byte is `type`; returns false on
	 * timeout; sets `gotSip` if a SIP arrived instead. */
	bool waitReply(uint8_t type, std::vector<uint8_t>& payload, bool& gotSip);
	bool handshake();
	void closeLink(const std::string& why, bool silence);
	void sendCommandsIfDue(mrpt::Clock::time_point now);
	void readAvailable(double timeout_s, std::vector<TPioneerState>& out);

	TOptions m_opts;
	TStreamFactory m_factory;
	std::unique_ptr<CByteStream> m_link;
	arcos::CArcosPacketParser m_parser;
	CArcosOdometry m_odometry;
	bool m_odometryResetDone = false;

	mutable std::mutex m_mtx;  //!< guards m_stats and the command fields
	TPioneerDriverStats m_stats;
	double m_cmdV_mps = 0, m_cmdW_rad_s = 0;
	mrpt::Clock::time_point m_cmdTime{};
	bool m_cmdActive = false;

	mrpt::Clock::time_point m_lastSend{}, m_lastSip{}, m_lastAttempt{};
	double m_sentV = 1e9, m_sentW = 1e9;  //!< last velocities sent (forces the first send)
};

}  // namespace hslam::hwdrivers
