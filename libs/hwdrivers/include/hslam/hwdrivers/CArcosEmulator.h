/* hslam: Pioneer P3-DX ARCOS server emulator (for tests and recording without hardware).
 *
 * Listens on a pseudo-terminal (serial side) and/or a loopback TCP port (like
 * MobileSim's 8101) and speaks the server side of ARCOS
 * (../shared/notes/mrpt-plugins-and-protocols.md s.3): SYNC0/1/2 handshake
 * (SYNC2 reply: name, "Pioneer", subclass), OPEN starts a SIP every
 * sip_period_s (ARCOS default 100 ms), CLOSE stops it; accepts PULSE, ENABLE,
 * VEL (mm/s), RVEL (deg/s), SETO, SONAR, STOP, ESTOP; stops the robot when no
 * client packet arrived for watchdog_s (ARCOS: 2 s). Bytes before a header are
 * skipped (Aria writes "WMS2\r" first on serial).
 *
 * The robot moves by a CEmulatorKinematics (default: exact arc integration,
 * odometry = truth, so a test can compare the driver's odometry with
 * truePose(); the simulator's CDiffDriveRobot adds UMBmark errors) in a
 * CEmulatorWorld; sonars are ray-cast from the P3-DX front-ring poses. Reported
 * wheel speeds use the wheel base 2/DiffConvFactor = 357 mm. The SIP position
 * is the odometry since the last SETO.
 *
 * Faults (thread-safe calls, also random rates in TOptions): corrupted
 * checksums, truncated SIPs, garbage bytes, silence, dropped connection (TCP
 * clients closed; the pseudo-terminal re-created behind the same symlink). */
#pragma once

#include <hslam/hwdrivers/CEmulatorWorld.h>
#include <hslam/hwdrivers/CPseudoTerminal.h>
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/p3dx_geometry.h>
#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

namespace hslam::hwdrivers
{
struct TArcosEmulatorStats
{
	uint64_t sipsSent = 0, commands = 0, handshakes = 0, tcpAccepts = 0, watchdogStops = 0;
	uint64_t faultsInjected = 0;
	double v_mps = 0, w_rad_s = 0;  //!< current commanded velocities
	bool motorsEnabled = false;
};

class CArcosEmulator
{
   public:
	struct TOptions
	{
		std::string pty_link;  //!< symlink to create for the pty; "" = no pty unless use_pty
		bool use_pty = true;
		int tcp_port = -1;  //!< -1 = no TCP, 0 = any free port
		double sip_period_s = 0.1;
		double watchdog_s = 2.0;
		std::string robot_name = "hslam-emulator";
		std::string subclass = "p3dx-sh";
		std::string sonar_poses = P3DX_FRONT_SONAR_POSES;
		int sonars_per_sip = 8;
		double sonar_max_range_m = 5.0;
		double wheel_base_m = 2.0 / 5.6;  //!< 2 / DiffConvFactor(0.0056 /mm)
		double battery_V = 12.6;
		mrpt::poses::CPose2D start_pose{0, 0, 0};
		// Random fault rates per SIP (0..1) and their random seed.
		double bad_checksum_rate = 0, partial_rate = 0, garbage_rate = 0;
		unsigned seed = 1;
	};

	/** `kinematics` null = CExactKinematics from options.start_pose. */
	CArcosEmulator(const TOptions& options, std::shared_ptr<const CEmulatorWorld> world,
				   std::shared_ptr<CEmulatorKinematics> kinematics = nullptr);
	~CArcosEmulator();

	/** Sonar model: ranges (m) of every sonar (index = sonar number) at a true
	 * robot pose; >= sonar_max_range_m = no echo. Default (unset): one exact
	 * ray per sonar from the sonar_poses in the world. Set before start(). */
	using TSonarModel = std::function<std::vector<double>(const mrpt::poses::CPose2D& truePose)>;
	void setSonarModel(TSonarModel model) { m_sonarModel = std::move(model); }

	/** Opens the endpoints and starts the emulator thread; throws std::runtime_error. */
	void start();
	void stop();

	std::string ptyPath() const;  //!< the path a client opens
	int tcpPort() const { return m_tcpPort; }

	mrpt::poses::CPose2D truePose() const;
	TArcosEmulatorStats stats() const;

	// Fault injection.
	void injectGarbage(size_t nBytes);
	void corruptNextSips(int n);
	void truncateNextSips(int n);
	void silence(double seconds);
	void dropConnection();

   private:
	struct TClient
	{
		int fd = -1;
		bool isPty = false;
		arcos::CArcosPacketParser parser;
		int state = 0;  //!< 0..2 waiting SYNCn, 3 synced, 4 open (streaming)
		mrpt::Clock::time_point lastRx;
	};
	void run();
	void openTcp();
	void acceptClients();
	void handleInput(TClient& c);
	void handlePacket(TClient& c, const std::vector<uint8_t>& payload);
	void tick(double dt);
	std::vector<uint8_t> makeSip();
	void sendTo(TClient& c, std::vector<uint8_t> bytes);
	void dropNow();

	TOptions m_opts;
	std::shared_ptr<const CEmulatorWorld> m_world;
	std::vector<mrpt::math::TPose2D> m_sonarPoses;
	TSonarModel m_sonarModel;
	CPseudoTerminal m_pty;
	int m_listenFd = -1, m_tcpPort = -1;
	std::vector<TClient> m_clients;
	std::thread m_thread;
	std::atomic<bool> m_quit{false};

	mutable std::mutex m_mtx;  //!< guards everything below
	std::shared_ptr<CEmulatorKinematics> m_kin;
	mrpt::poses::CPose2D m_odomOrigin;  //!< odometry pose at the last SETO
	double m_v = 0, m_w = 0;
	bool m_motors = false, m_sonarOn = true;
	size_t m_nextSonar = 0;
	TArcosEmulatorStats m_stats;
	size_t m_pendingGarbage = 0;
	int m_corruptLeft = 0, m_truncateLeft = 0;
	mrpt::Clock::time_point m_silentUntil{};
	bool m_dropRequested = false;
	mrpt::Clock::time_point m_lastRxAny{};
	std::mt19937 m_rng;
};

}  // namespace hslam::hwdrivers
