/* hslam: SICK LMS200 serial-protocol emulator on a pseudo-terminal, accepted by
 * MRPT's own CSickLaserSerial (driver = CSickLaserSerial, COM_port_LIN = the
 * symlink). Telegrams (../shared/notes/mrpt-plugins-and-protocols.md s.2.2):
 * host frames 02 00 Llo Lhi <cmd...> CRC16; every command is answered with ACK
 * 06 and a reply frame 02 80 Llo Lhi <reply... status 10> CRC16 (SICK CRC,
 * polynomial 0x8005, little-endian):
 *   20 xx -> A0 00 10 (mode/baud change; 20 24 starts, 20 25 stops streaming)
 *   31 -> B1 <version text> 10;  74 -> F4 <33 config bytes> 10
 *   77 ... -> F7 01 <33 config bytes> 10 (command byte 7 = 0x06 selects mm mode)
 *   3B fov res -> BB 01 fov res 10 (angular range 100/180 deg, 0.25/0.5/1 deg)
 * While streaming, B0 frames: INFO (bits 0-8 = points, bit 14 = mm units),
 * ranges right (-fov/2) to left, status 10, at scan_rate_hz. Ranges are ray-cast
 * in the CEmulatorWorld from the robot pose given by a callback (the ARCOS
 * emulator's true pose) composed with the laser pose on the robot; no echo within
 * max_range_m -> the overflow value (0x1FFF cm / 0x7FFF mm, which MRPT marks invalid). */
#pragma once

#include <hslam/hwdrivers/CEmulatorWorld.h>
#include <hslam/hwdrivers/CPseudoTerminal.h>
#include <mrpt/poses/CPose2D.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace hslam::hwdrivers
{
/** SICK LMS2xx CRC-16 (MRPT's compute_CRC16 with polynomial 0x8005). */
uint16_t sickCrc16(const uint8_t* data, size_t n);

class CLms200Emulator
{
   public:
	struct TOptions
	{
		std::string pty_link;
		double scan_rate_hz = 10.0;
		double max_range_m = 8.0;
		mrpt::poses::CPose2D laser_pose{0.021, 0, 0};  //!< on the robot (Aria LaserX 21 mm)
	};
	using TPoseSource = std::function<mrpt::poses::CPose2D()>;

	CLms200Emulator(const TOptions& options, std::shared_ptr<const CEmulatorWorld> world, TPoseSource robotPose);
	~CLms200Emulator();

	/** Scan model: ranges (m) of n beams from -fov/2 (right) to +fov/2 at the
	 * laser's world pose; >= max_range_m = no echo. Default (unset): exact rays
	 * in the world. Set before start(). */
	using TScanModel =
		std::function<std::vector<double>(const mrpt::poses::CPose2D& laserPose, double fov_rad, int n, double maxRange_m)>;
	void setScanModel(TScanModel model) { m_scanModel = std::move(model); }

	void start();
	void stop();
	std::string ptyPath() const { return m_pty.clientPath(); }
	uint64_t scansSent() const { return m_scans; }
	uint64_t commandsReceived() const { return m_commands; }

   private:
	void run();
	void handleCommand(const std::vector<uint8_t>& cmd);
	void sendReply(const std::vector<uint8_t>& body, bool ack);
	std::vector<uint8_t> scanBody();

	TOptions m_opts;
	std::shared_ptr<const CEmulatorWorld> m_world;
	TPoseSource m_pose;
	TScanModel m_scanModel;
	CPseudoTerminal m_pty;
	std::thread m_thread;
	std::atomic<bool> m_quit{false};
	std::atomic<uint64_t> m_scans{0}, m_commands{0};
	std::vector<uint8_t> m_rx;
	bool m_streaming = false, m_mm = false;
	int m_fov_deg = 180, m_res_centideg = 50;
	std::vector<uint8_t> m_config;
};

}  // namespace hslam::hwdrivers
