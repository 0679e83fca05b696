/* hslam: byte-stream transports for device drivers (client side).
 *
 * A Pioneer is reached over a serial port (9600 8N1 by default, or a pseudo-
 * terminal of an emulator) or a TCP socket (MobileSim/AMRISim port 8101, or our
 * emulator). Both are plain file descriptors, so one poll()-based read with a
 * timeout serves both; read errors and end-of-file are reported as exceptions
 * so the driver can reconnect (MRPT's CClientTCPSocket does not report a peer
 * closing the connection distinctly, which the reconnection logic needs). */
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace hslam::hwdrivers
{
/** Thrown when the link is broken (device gone, peer closed, I/O error). */
class link_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

class CByteStream
{
   public:
	virtual ~CByteStream();
	CByteStream() = default;
	CByteStream(const CByteStream&) = delete;
	CByteStream& operator=(const CByteStream&) = delete;

	/** Opens the link; throws link_error with a readable reason. */
	virtual void open() = 0;
	void close();
	bool isOpen() const { return m_fd >= 0; }

	/** Reads up to `max` bytes, waiting at most timeout_s for the first one.
	 * Returns 0 on timeout; throws link_error on EOF or error. */
	size_t read(uint8_t* buf, size_t max, double timeout_s);

	/** Writes all bytes (waits at most 0.5 s for buffer space); throws link_error. */
	void write(const uint8_t* data, size_t n);

	/** Human-readable endpoint ("/dev/ttyS0@9600", "localhost:8101"). */
	virtual std::string describe() const = 0;

   protected:
	int m_fd = -1;
};

/** Serial port or pseudo-terminal, raw 8N1, no flow control. */
class CSerialStream : public CByteStream
{
   public:
	CSerialStream(std::string device, int baud) : m_device(std::move(device)), m_baud(baud) {}
	void open() override;
	std::string describe() const override { return m_device + "@" + std::to_string(m_baud); }

   private:
	std::string m_device;
	int m_baud;
};

/** TCP client (blocking connect with timeout). */
class CTcpStream : public CByteStream
{
   public:
	CTcpStream(std::string host, int port, double connectTimeout_s = 2.0)
		: m_host(std::move(host)), m_port(port), m_connectTimeout_s(connectTimeout_s)
	{
	}
	void open() override;
	std::string describe() const override { return m_host + ":" + std::to_string(m_port); }

   private:
	std::string m_host;
	int m_port;
	double m_connectTimeout_s;
};

/** Puts a terminal file descriptor in raw mode at the given baud rate; throws
 * std::invalid_argument for an unsupported rate. */
void setRawTerminal(int fd, int baud);

}  // namespace hslam::hwdrivers
