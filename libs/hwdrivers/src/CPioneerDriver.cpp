/* hslam: Pioneer ARCOS client driver (see CPioneerDriver.h). */
#include <hslam/hwdrivers/CPioneerDriver.h>

#include <algorithm>
#include <cmath>
#include <thread>

namespace hslam::hwdrivers
{
using namespace arcos;
using Clock = mrpt::Clock;

namespace
{
double secondsSince(Clock::time_point t, Clock::time_point now) { return std::chrono::duration<double>(now - t).count(); }
}  // namespace

CPioneerDriver::CPioneerDriver(const TOptions& options) : m_opts(options), m_odometry(options.conversion)
{
	m_factory = [this]() -> std::unique_ptr<CByteStream> {
		if (!m_opts.serial_port.empty()) return std::make_unique<CSerialStream>(m_opts.serial_port, m_opts.baud);
		return std::make_unique<CTcpStream>(m_opts.tcp_host, m_opts.tcp_port);
	};
}

CPioneerDriver::~CPioneerDriver() { disconnect(); }

void CPioneerDriver::send(const std::vector<uint8_t>& packet)
{
	m_link->write(packet.data(), packet.size());
	m_lastSend = Clock::now();
}

bool CPioneerDriver::waitReply(uint8_t type, std::vector<uint8_t>& payload, bool& gotSip)
{
	const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
											 std::chrono::duration<double>(m_opts.handshake_timeout_s));
	uint8_t buf[256];
	for (;;)
	{
		while (m_parser.next(payload))
		{
			if (payload[0] == type && !isStandardSip(payload[0])) return true;
			if (isStandardSip(payload[0])) gotSip = true;
		}
		if (gotSip) return false;
		const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
		if (left <= 0) return false;
		const size_t n = m_link->read(buf, sizeof(buf), left);
		m_parser.feed(buf, n);
	}
}

bool CPioneerDriver::handshake()
{
	std::vector<uint8_t> reply;
	for (int attempt = 0; attempt < 3; ++attempt)
	{
		bool gotSip = false, ok = true;
		for (uint8_t sync : {CMD_SYNC0, CMD_SYNC1, CMD_SYNC2})
		{
			send(encodeCommand(sync));
			if (!waitReply(sync, reply, gotSip))
			{
				ok = false;
				break;
			}
		}
		if (ok)
		{
			// SYNC2 reply: type 2, then name, class, subclass (NUL-terminated).
			std::vector<std::string> fields(1);
			for (size_t i = 1; i < reply.size(); ++i)
			{
				if (reply[i] == 0)
					fields.emplace_back();
				else
					fields.back().push_back(static_cast<char>(reply[i]));
			}
			fields.resize(3);
			std::lock_guard<std::mutex> lk(m_mtx);
			m_stats.robotName = fields[0];
			m_stats.robotClass = fields[1];
			m_stats.robotSubclass = fields[2];
			return true;
		}
		// A session still open (SIPs) or no answer: CLOSE and start again.
		send(encodeCommand(CMD_CLOSE));
		std::this_thread::sleep_for(std::chrono::milliseconds(100));
		uint8_t buf[256];
		while (m_link->read(buf, sizeof(buf), 0.0) > 0)
		{
		}
		m_parser.clear();
	}
	return false;
}

bool CPioneerDriver::connect()
{
	m_lastAttempt = Clock::now();
	m_parser.clear();
	try
	{
		m_link = m_factory();
		m_link->open();
		if (!handshake()) throw link_error(m_link->describe() + ": no ARCOS handshake reply (SYNC0/1/2)");
		send(encodeCommand(CMD_OPEN));
		send(encodeCommand(CMD_PULSE));
		if (m_opts.enable_motors) send(encodeCommandInt(CMD_ENABLE, 1));
		send(encodeCommandInt(CMD_SONAR, m_opts.enable_sonar ? 1 : 0));
		if (m_opts.reset_odometry && !m_odometryResetDone)
		{
			send(encodeCommand(CMD_SETO));
			m_odometry.resetToOrigin();
			m_odometryResetDone = true;
		}
		m_sentV = m_sentW = 1e9;
		m_lastSip = Clock::now();
		std::lock_guard<std::mutex> lk(m_mtx);
		m_stats.lastHeard = m_lastSip;
		if (m_stats.connections > 0 && m_stats.lastLinkLoss != mrpt::Clock::time_point{})
		{
			const double outage_s = secondsSince(m_stats.lastLinkLoss, m_lastSip);
			++m_stats.outages;
			m_stats.outageTotal_s += outage_s;
			m_stats.longestOutage_s = std::max(m_stats.longestOutage_s, outage_s);
		}
		m_stats.connected = true;
		++m_stats.connections;
		return true;
	}
	catch (const std::exception& e)
	{
		if (m_link) m_link->close();
		std::lock_guard<std::mutex> lk(m_mtx);
		m_stats.connected = false;
		++m_stats.failedConnections;
		m_stats.lastError = e.what();
		return false;
	}
}

void CPioneerDriver::disconnect()
{
	if (m_link && m_link->isOpen())
	{
		try
		{
			send(encodeCommandInt(CMD_VEL, 0));
			send(encodeCommandInt(CMD_RVEL, 0));
			send(encodeCommand(CMD_CLOSE));
		}
		catch (const std::exception&)
		{
		}
		m_link->close();
	}
	std::lock_guard<std::mutex> lk(m_mtx);
	m_stats.connected = false;
}

void CPioneerDriver::closeLink(const std::string& why, bool silence)
{
	if (m_link) m_link->close();
	m_parser.clear();
	std::lock_guard<std::mutex> lk(m_mtx);
	m_stats.connected = false;
	m_stats.lastLinkLoss = Clock::now();
	m_stats.lastError = why;
	++(silence ? m_stats.silenceTimeouts : m_stats.linkErrors);
}

void CPioneerDriver::setVelocity(double v_mps, double w_rad_s)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_cmdV_mps = std::clamp(v_mps, -m_opts.max_v_mps, m_opts.max_v_mps);
	m_cmdW_rad_s = std::clamp(w_rad_s, -m_opts.max_w_rad_s, m_opts.max_w_rad_s);
	m_cmdTime = Clock::now();
	m_cmdActive = true;
}

void CPioneerDriver::sendCommandsIfDue(Clock::time_point now)
{
	double v, w;
	{
		std::lock_guard<std::mutex> lk(m_mtx);
		if (m_cmdActive && secondsSince(m_cmdTime, now) > m_opts.command_timeout_s)
		{
			m_cmdActive = false;
			if (m_cmdV_mps != 0 || m_cmdW_rad_s != 0) ++m_stats.watchdogStops;
			m_cmdV_mps = m_cmdW_rad_s = 0;
		}
		v = m_cmdV_mps;
		w = m_cmdW_rad_s;
	}
	const bool changed = v != m_sentV || w != m_sentW;
	if (!changed && secondsSince(m_lastSend, now) < m_opts.pulse_period_s) return;
	if (changed || v != 0 || w != 0)
	{
		send(encodeCommandInt(CMD_VEL, static_cast<int>(std::lround(v * 1000.0))));
		send(encodeCommandInt(CMD_RVEL, static_cast<int>(std::lround(w * 180.0 / M_PI))));
		m_sentV = v;
		m_sentW = w;
	}
	else
		send(encodeCommand(CMD_PULSE));
}

void CPioneerDriver::readAvailable(double timeout_s, std::vector<TPioneerState>& out)
{
	uint8_t buf[1024];
	const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout_s));
	for (;;)
	{
		const double wait = out.empty() ? std::max(0.0, std::chrono::duration<double>(deadline - Clock::now()).count()) : 0.0;
		const size_t n = m_link->read(buf, sizeof(buf), wait);
		if (n == 0) break;
		m_parser.feed(buf, n);
		std::vector<uint8_t> payload;
		while (m_parser.next(payload))
		{
			if (!isStandardSip(payload[0]))
			{
				std::lock_guard<std::mutex> lk(m_mtx);
				++m_stats.otherPackets;
				continue;
			}
			const auto sip = decodeSip(payload);
			if (!sip)
			{
				std::lock_guard<std::mutex> lk(m_mtx);
				++m_stats.malformedSips;
				continue;
			}
			m_odometry.update(*sip);
			TPioneerState st;
			st.timestamp = Clock::now();
			st.sip = *sip;
			st.odometry = m_odometry.pose();
			st.velocityLocal = m_odometry.velocityLocal();
			st.leftWheel_mps = m_odometry.leftWheel_mps();
			st.rightWheel_mps = m_odometry.rightWheel_mps();
			st.battery_V = sip->batteryVolts();
			out.push_back(std::move(st));
			m_lastSip = out.back().timestamp;
			std::lock_guard<std::mutex> lk(m_mtx);
			m_stats.lastHeard = m_lastSip;
			++m_stats.sips;
		}
	}
}

std::vector<TPioneerState> CPioneerDriver::spinOnce(double timeout_s)
{
	std::vector<TPioneerState> out;
	auto now = Clock::now();
	if (!m_link || !m_link->isOpen())
	{
		if (secondsSince(m_lastAttempt, now) < m_opts.reconnect_period_s || !connect())
		{
			std::this_thread::sleep_for(std::chrono::duration<double>(timeout_s));
			return out;
		}
	}
	try
	{
		readAvailable(timeout_s, out);
		now = Clock::now();
		if (secondsSince(m_lastSip, now) > m_opts.silence_timeout_s)
		{
			closeLink(m_link->describe() + ": no SIP for " + std::to_string(m_opts.silence_timeout_s) + " s", true);
			return out;
		}
		sendCommandsIfDue(now);
	}
	catch (const link_error& e)
	{
		closeLink(e.what(), false);
	}
	std::lock_guard<std::mutex> lk(m_mtx);
	m_stats.parser = m_parser.stats();
	return out;
}

TPioneerDriverStats CPioneerDriver::stats() const
{
	std::lock_guard<std::mutex> lk(m_mtx);
	return m_stats;
}

bool CPioneerDriver::isConnected() const
{
	std::lock_guard<std::mutex> lk(m_mtx);
	return m_stats.connected;
}

}  // namespace hslam::hwdrivers
