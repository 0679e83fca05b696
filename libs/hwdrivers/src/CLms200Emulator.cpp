/* hslam: SICK LMS200 emulator (see CLms200Emulator.h). */
#include <hslam/hwdrivers/CLms200Emulator.h>

#include <stdexcept>

#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cmath>

namespace hslam::hwdrivers
{
namespace
{
/** Appends by push_back (vector::insert trips a GCC 12 -Warray-bounds false positive here). */
void append(std::vector<uint8_t>& dst, const std::vector<uint8_t>& src)
{
	for (uint8_t b : src) dst.push_back(b);
}
}  // namespace

uint16_t sickCrc16(const uint8_t* data, size_t n)
{
	uint16_t crc = 0;
	uint8_t prev = 0;
	for (size_t i = 0; i < n; ++i)
	{
		const uint8_t hi = prev;
		prev = data[i];
		if (crc & 0x8000)
			crc = static_cast<uint16_t>(((crc & 0x7FFF) << 1) ^ 0x8005);
		else
			crc = static_cast<uint16_t>(crc << 1);
		crc ^= static_cast<uint16_t>(data[i] | (hi << 8));
	}
	return crc;
}

CLms200Emulator::CLms200Emulator(const TOptions& options, std::shared_ptr<const CEmulatorWorld> world,
								 TPoseSource robotPose)
	: m_opts(options), m_world(std::move(world)), m_pose(std::move(robotPose)), m_config(33, 0)
{
	if (!(options.scan_rate_hz > 0 && options.scan_rate_hz <= 100))
		throw std::invalid_argument("LMS200 scan rate " + std::to_string(options.scan_rate_hz) + " Hz: expected 0 < rate <= 100");
}

CLms200Emulator::~CLms200Emulator() { stop(); }

void CLms200Emulator::start()
{
	m_pty.open(m_opts.pty_link);
	m_quit = false;
	m_thread = std::thread([this] { run(); });
}

void CLms200Emulator::stop()
{
	m_quit = true;
	if (m_thread.joinable()) m_thread.join();
	m_pty.close();
}

void CLms200Emulator::sendReply(const std::vector<uint8_t>& body, bool ack)
{
	std::vector<uint8_t> f;
	if (ack) f.push_back(0x06);
	const size_t start = f.size();
	f.push_back(0x02);
	f.push_back(0x80);
	f.push_back(static_cast<uint8_t>(body.size() & 0xFF));
	f.push_back(static_cast<uint8_t>(body.size() >> 8));
	append(f, body);
	const uint16_t crc = sickCrc16(&f[start], f.size() - start);
	f.push_back(static_cast<uint8_t>(crc & 0xFF));
	f.push_back(static_cast<uint8_t>(crc >> 8));
	(void)!::write(m_pty.masterFd(), f.data(), f.size());
}

void CLms200Emulator::handleCommand(const std::vector<uint8_t>& c)
{
	++m_commands;
	switch (c[0])
	{
		case 0x20:
			if (c.size() > 1 && c[1] == 0x24) m_streaming = true;
			if (c.size() > 1 && c[1] == 0x25) m_streaming = false;
			sendReply({0xA0, 0x00, 0x10}, true);
			break;
		case 0x31:
		{
			std::vector<uint8_t> r{0xB1};
			for (char ch : std::string("hslam LMS200 emulator")) r.push_back(static_cast<uint8_t>(ch));
			r.push_back(0x10);
			sendReply(r, true);
			break;
		}
		case 0x74:
		{
			std::vector<uint8_t> r{0xF4};
			append(r, m_config);
			r.push_back(0x10);
			sendReply(r, true);
			break;
		}
		case 0x77:
		{
			if (c.size() >= 8) m_mm = c[6] == 0x06;  // measuring mode bytes (MRPT writes 06 01 for mm)
			for (size_t i = 1; i < c.size() && i - 1 < m_config.size(); ++i) m_config[i - 1] = c[i];
			std::vector<uint8_t> r{0xF7, 0x01};
			append(r, m_config);
			r.push_back(0x10);
			sendReply(r, true);
			break;
		}
		case 0x3B:
			if (c.size() >= 5)
			{
				m_fov_deg = c[1] | (c[2] << 8);
				m_res_centideg = c[3] | (c[4] << 8);
			}
			sendReply({0xBB, 0x01, static_cast<uint8_t>(m_fov_deg & 0xFF), static_cast<uint8_t>(m_fov_deg >> 8),
					   static_cast<uint8_t>(m_res_centideg & 0xFF), static_cast<uint8_t>(m_res_centideg >> 8), 0x10},
					  true);
			break;
		default: (void)!::write(m_pty.masterFd(), "\x15", 1);  // NACK
	}
}

std::vector<uint8_t> CLms200Emulator::scanBody()
{
	const int n = m_fov_deg * 100 / m_res_centideg + 1;
	std::vector<uint8_t> b{0xB0, static_cast<uint8_t>(n & 0xFF), static_cast<uint8_t>(((n >> 8) & 0x01) | (m_mm ? 0x40 : 0))};
	const mrpt::poses::CPose2D lp = m_pose() + m_opts.laser_pose;
	const double unit_m = m_mm ? 0.001 : 0.01;
	const unsigned overflow = m_mm ? 0x7FFF : 0x1FFF;
	std::vector<double> ranges;
	if (m_scanModel)
		ranges = m_scanModel(lp, m_fov_deg * M_PI / 180.0, n, m_opts.max_range_m);
	else
		for (int i = 0; i < n; ++i)
		{
			const double a = lp.phi() + (-0.5 * m_fov_deg + i * m_res_centideg / 100.0) * M_PI / 180.0;
			ranges.push_back(m_world ? m_world->rayRange_m(lp.x(), lp.y(), a, m_opts.max_range_m) : m_opts.max_range_m);
		}
	ranges.resize(static_cast<size_t>(n), m_opts.max_range_m);
	for (double r : ranges)
	{
		const unsigned v = r >= m_opts.max_range_m ? overflow : static_cast<unsigned>(std::lround(std::max(0.0, r) / unit_m));
		b.push_back(static_cast<uint8_t>(v & 0xFF));
		b.push_back(static_cast<uint8_t>(v >> 8));
	}
	b.push_back(0x10);
	return b;
}

void CLms200Emulator::run()
{
	using Clock = std::chrono::steady_clock;
	const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / m_opts.scan_rate_hz));
	auto next = Clock::now() + period;
	while (!m_quit)
	{
		pollfd p{m_pty.masterFd(), POLLIN, 0};
		::poll(&p, 1, 5);
		uint8_t buf[512];
		ssize_t n;
		while ((n = ::read(m_pty.masterFd(), buf, sizeof(buf))) > 0) m_rx.insert(m_rx.end(), buf, buf + n);
		// Frames: 02 00 Llo Lhi <L> CRC CRC; resync on 02 00.
		for (;;)
		{
			size_t s = 0;
			while (s + 1 < m_rx.size() && !(m_rx[s] == 0x02 && m_rx[s + 1] == 0x00)) ++s;
			m_rx.erase(m_rx.begin(), m_rx.begin() + static_cast<std::ptrdiff_t>(s));
			if (m_rx.size() < 4) break;
			const size_t len = m_rx[2] | (m_rx[3] << 8);
			if (len == 0 || len > 800)
			{
				m_rx.erase(m_rx.begin());
				continue;
			}
			if (m_rx.size() < len + 6) break;
			const uint16_t crc = static_cast<uint16_t>(m_rx[4 + len] | (m_rx[5 + len] << 8));
			if (crc != sickCrc16(m_rx.data(), 4 + len))
			{
				m_rx.erase(m_rx.begin());
				continue;
			}
			const std::vector<uint8_t> cmd(m_rx.begin() + 4, m_rx.begin() + 4 + static_cast<std::ptrdiff_t>(len));
			m_rx.erase(m_rx.begin(), m_rx.begin() + static_cast<std::ptrdiff_t>(len + 6));
			handleCommand(cmd);
		}
		const auto now = Clock::now();
		if (now >= next)
		{
			next += period;
			if (next < now) next = now + period;
			if (m_streaming)
			{
				sendReply(scanBody(), false);
				++m_scans;
			}
		}
	}
}

}  // namespace hslam::hwdrivers
