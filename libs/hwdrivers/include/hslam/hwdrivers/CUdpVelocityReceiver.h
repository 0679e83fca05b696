/* hslam: velocity commands over loopback UDP, so that a teleoperation client,
 * the obstacle avoider or a test can drive a robot whose driver runs inside
 * MRPT's rawlog-grabber (which has no command channel). One datagram = one
 * text command "v_mps w_rad_s" (e.g. "0.2 0.1"). Malformed datagrams are
 * counted and ignored. */
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace hslam::hwdrivers
{
class CUdpVelocityReceiver
{
   public:
	/** Binds 127.0.0.1:port; throws std::runtime_error if it cannot. */
	explicit CUdpVelocityReceiver(int port);
	~CUdpVelocityReceiver();
	CUdpVelocityReceiver(const CUdpVelocityReceiver&) = delete;
	CUdpVelocityReceiver& operator=(const CUdpVelocityReceiver&) = delete;

	/** The newest command received since the last call (non-blocking). */
	std::optional<std::pair<double, double>> poll();

	uint64_t malformed() const { return m_malformed; }

   private:
	int m_fd = -1;
	uint64_t m_malformed = 0;
};

/** Sends one command datagram to 127.0.0.1:port (teleop clients, tests). */
void sendUdpVelocity(int port, double v_mps, double w_rad_s);

}  // namespace hslam::hwdrivers
