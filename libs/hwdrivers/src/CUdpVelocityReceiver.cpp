/* hslam: UDP velocity commands (see CUdpVelocityReceiver.h). */
#include <hslam/hwdrivers/CUdpVelocityReceiver.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace hslam::hwdrivers
{
namespace
{
sockaddr_in loopback(int port)
{
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_port = htons(static_cast<uint16_t>(port));
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	return a;
}
}  // namespace

CUdpVelocityReceiver::CUdpVelocityReceiver(int port)
{
	m_fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	const sockaddr_in a = loopback(port);
	if (m_fd < 0 || ::bind(m_fd, reinterpret_cast<const sockaddr*>(&a), sizeof(a)) != 0)
	{
		const std::string why = std::strerror(errno);
		if (m_fd >= 0) ::close(m_fd);
		throw std::runtime_error("teleop UDP port " + std::to_string(port) + ": " + why);
	}
}

CUdpVelocityReceiver::~CUdpVelocityReceiver()
{
	if (m_fd >= 0) ::close(m_fd);
}

std::optional<std::pair<double, double>> CUdpVelocityReceiver::poll()
{
	std::optional<std::pair<double, double>> latest;
	char buf[256];
	for (;;)
	{
		const ssize_t n = ::recv(m_fd, buf, sizeof(buf) - 1, 0);
		if (n <= 0) break;
		buf[n] = 0;
		std::istringstream is(buf);
		double v, w;
		if (is >> v >> w && std::isfinite(v) && std::isfinite(w))
			latest = std::make_pair(v, w);
		else
			++m_malformed;
	}
	return latest;
}

void sendUdpVelocity(int port, double v_mps, double w_rad_s)
{
	const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (fd < 0) throw std::runtime_error(std::string("UDP socket: ") + std::strerror(errno));
	const std::string msg = std::to_string(v_mps) + " " + std::to_string(w_rad_s);
	const sockaddr_in a = loopback(port);
	::sendto(fd, msg.data(), msg.size(), 0, reinterpret_cast<const sockaddr*>(&a), sizeof(a));
	::close(fd);
}

}  // namespace hslam::hwdrivers
