/* hslam: serial and TCP byte streams (see byte_stream.h). */
#include <hslam/hwdrivers/byte_stream.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace hslam::hwdrivers
{
CByteStream::~CByteStream() { close(); }

void CByteStream::close()
{
	if (m_fd >= 0) ::close(m_fd);
	m_fd = -1;
}

size_t CByteStream::read(uint8_t* buf, size_t max, double timeout_s)
{
	if (m_fd < 0) throw link_error(describe() + ": not open");
	pollfd p{m_fd, POLLIN, 0};
	const int r = ::poll(&p, 1, static_cast<int>(timeout_s * 1000.0));
	if (r < 0)
	{
		if (errno == EINTR) return 0;
		throw link_error(describe() + ": poll: " + std::strerror(errno));
	}
	if (r == 0) return 0;
	const ssize_t n = ::read(m_fd, buf, max);
	if (n > 0) return static_cast<size_t>(n);
	if (n < 0 && (errno == EAGAIN || errno == EINTR)) return 0;
	throw link_error(describe() + (n == 0 ? ": connection closed by the device" : ": read: " + std::string(std::strerror(errno))));
}

void CByteStream::write(const uint8_t* data, size_t n)
{
	if (m_fd < 0) throw link_error(describe() + ": not open");
	size_t done = 0;
	while (done < n)
	{
		const ssize_t w = ::write(m_fd, data + done, n - done);
		if (w > 0)
		{
			done += static_cast<size_t>(w);
			continue;
		}
		if (w < 0 && (errno == EAGAIN || errno == EINTR))
		{
			pollfd p{m_fd, POLLOUT, 0};
			if (::poll(&p, 1, 500) <= 0) throw link_error(describe() + ": write timed out");
			continue;
		}
		throw link_error(describe() + ": write: " + std::strerror(errno));
	}
}

void setRawTerminal(int fd, int baud)
{
	speed_t speed;
	switch (baud)
	{
		case 9600: speed = B9600; break;
		case 19200: speed = B19200; break;
		case 38400: speed = B38400; break;
		case 57600: speed = B57600; break;
		case 115200: speed = B115200; break;
		case 500000: speed = B500000; break;
		default: throw std::invalid_argument("unsupported baud rate " + std::to_string(baud));
	}
	termios t{};
	if (tcgetattr(fd, &t) != 0) throw link_error(std::string("tcgetattr: ") + std::strerror(errno));
	cfmakeraw(&t);
	t.c_cflag |= CLOCAL | CREAD;
	t.c_cflag &= ~(CSTOPB | PARENB | CRTSCTS);
	t.c_cc[VMIN] = 0;
	t.c_cc[VTIME] = 0;
	cfsetispeed(&t, speed);
	cfsetospeed(&t, speed);
	if (tcsetattr(fd, TCSANOW, &t) != 0) throw link_error(std::string("tcsetattr: ") + std::strerror(errno));
}

void CSerialStream::open()
{
	close();
	const int fd = ::open(m_device.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
	if (fd < 0) throw link_error(m_device + ": cannot open: " + std::strerror(errno));
	try
	{
		setRawTerminal(fd, m_baud);
	}
	catch (const std::exception& e)
	{
		::close(fd);
		throw link_error(m_device + ": " + e.what());
	}
	tcflush(fd, TCIOFLUSH);
	m_fd = fd;
}

void CTcpStream::open()
{
	close();
	addrinfo hints{};
	hints.ai_family = AF_INET;
	hints.ai_socktype = SOCK_STREAM;
	addrinfo* res = nullptr;
	if (getaddrinfo(m_host.c_str(), std::to_string(m_port).c_str(), &hints, &res) != 0 || !res)
		throw link_error(describe() + ": cannot resolve host");
	const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	if (fd < 0)
	{
		freeaddrinfo(res);
		throw link_error(describe() + ": socket: " + std::strerror(errno));
	}
	int rc = ::connect(fd, res->ai_addr, res->ai_addrlen);
	freeaddrinfo(res);
	if (rc != 0 && errno == EINPROGRESS)
	{
		pollfd p{fd, POLLOUT, 0};
		rc = ::poll(&p, 1, static_cast<int>(m_connectTimeout_s * 1000)) == 1 ? 0 : -1;
		int err = 0;
		socklen_t len = sizeof(err);
		if (rc == 0 && getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) == 0 && err != 0)
		{
			errno = err;
			rc = -1;
		}
		else if (rc != 0)
			errno = ETIMEDOUT;
	}
	if (rc != 0)
	{
		const std::string why = std::strerror(errno);
		::close(fd);
		throw link_error(describe() + ": connect: " + why);
	}
	int one = 1;
	setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
	m_fd = fd;
}

}  // namespace hslam::hwdrivers
