/* hslam: ARCOS server emulator (see CArcosEmulator.h). */
#include <hslam/hwdrivers/CArcosEmulator.h>
#include <hslam/hwdrivers/arcos_sip.h>
#include <mrpt/math/wrap2pi.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace hslam::hwdrivers
{
using namespace arcos;
using Clock = mrpt::Clock;

namespace
{
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
Clock::duration toDuration(double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); }
constexpr double ANGLE_UNIT_RAD = 2.0 * M_PI / 4096.0;  // ARCOS heading unit
}  // namespace

CArcosEmulator::CArcosEmulator(const TOptions& options, std::shared_ptr<const CEmulatorWorld> world,
							   std::shared_ptr<CEmulatorKinematics> kinematics)
	: m_opts(options), m_world(std::move(world)), m_kin(std::move(kinematics)), m_rng(options.seed)
{
	// A zero or negative period would stream SIPs with non-increasing stamps
	// as fast as the link takes them (issue 15 item 6); ARCOS allows 0.01-2 s
	// in practice (its own watchdog is 2 s).
	if (!(options.sip_period_s >= 0.01 && options.sip_period_s < 2.0))
		throw std::invalid_argument("SIP period " + std::to_string(options.sip_period_s) + " s: expected 0.01 <= period < 2 s");
	for (double rate : {options.bad_checksum_rate, options.partial_rate, options.garbage_rate})
		if (!(rate >= 0 && rate <= 1)) throw std::invalid_argument("fault rate " + std::to_string(rate) + ": expected 0..1");
	if (!m_kin) m_kin = std::make_shared<CExactKinematics>(options.start_pose);
	m_odomOrigin = m_kin->odometryPose();
	m_sonarPoses = parseSonarPoses(m_opts.sonar_poses);
}

CArcosEmulator::~CArcosEmulator() { stop(); }

void CArcosEmulator::openTcp()
{
	m_listenFd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
	int one = 1;
	setsockopt(m_listenFd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_port = htons(static_cast<uint16_t>(m_opts.tcp_port));
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	if (::bind(m_listenFd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) != 0 || ::listen(m_listenFd, 4) != 0)
		throw std::runtime_error("ARCOS emulator: cannot listen on 127.0.0.1:" + std::to_string(m_opts.tcp_port) +
								 ": " + std::strerror(errno));
	socklen_t len = sizeof(a);
	getsockname(m_listenFd, reinterpret_cast<sockaddr*>(&a), &len);
	m_tcpPort = ntohs(a.sin_port);
}

void CArcosEmulator::start()
{
	if (m_opts.use_pty)
	{
		m_pty.open(m_opts.pty_link);
		TClient c;
		c.fd = m_pty.masterFd();
		c.isPty = true;
		m_clients.push_back(std::move(c));
	}
	if (m_opts.tcp_port >= 0) openTcp();
	m_quit = false;
	m_thread = std::thread([this] { run(); });
}

void CArcosEmulator::stop()
{
	m_quit = true;
	if (m_thread.joinable()) m_thread.join();
	for (auto& c : m_clients)
		if (!c.isPty) ::close(c.fd);
	m_clients.clear();
	m_pty.close();
	if (m_listenFd >= 0) ::close(m_listenFd);
	m_listenFd = -1;
}

std::string CArcosEmulator::ptyPath() const { return m_pty.clientPath(); }

mrpt::poses::CPose2D CArcosEmulator::truePose() const
{
	std::lock_guard<std::mutex> lk(m_mtx);
	return m_kin->truePose();
}

TArcosEmulatorStats CArcosEmulator::stats() const
{
	std::lock_guard<std::mutex> lk(m_mtx);
	auto s = m_stats;
	s.v_mps = m_v;
	s.w_rad_s = m_w;
	s.motorsEnabled = m_motors;
	return s;
}

void CArcosEmulator::injectGarbage(size_t nBytes)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_pendingGarbage += nBytes;
}
void CArcosEmulator::corruptNextSips(int n)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_corruptLeft += n;
}
void CArcosEmulator::truncateNextSips(int n)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_truncateLeft += n;
}
void CArcosEmulator::silence(double s)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_silentUntil = Clock::now() + toDuration(s);
}
void CArcosEmulator::dropConnection()
{
	std::lock_guard<std::mutex> lk(m_mtx);
	m_dropRequested = true;
}

void CArcosEmulator::dropNow()
{
	for (auto& c : m_clients)
		if (!c.isPty) ::close(c.fd);
	m_clients.clear();
	if (m_opts.use_pty)
	{
		m_pty.open(m_opts.pty_link);  // new /dev/pts/N behind the same symlink
		TClient c;
		c.fd = m_pty.masterFd();
		c.isPty = true;
		m_clients.push_back(std::move(c));
	}
	m_v = m_w = 0;
	++m_stats.faultsInjected;
}

void CArcosEmulator::sendTo(TClient& c, std::vector<uint8_t> bytes)
{
	if (Clock::now() < m_silentUntil) return;
	if (m_pendingGarbage > 0)
	{
		std::vector<uint8_t> g(m_pendingGarbage);
		for (auto& b : g) b = static_cast<uint8_t>(m_rng());
		bytes.insert(bytes.begin(), g.begin(), g.end());
		m_pendingGarbage = 0;
		++m_stats.faultsInjected;
	}
	// A full pty buffer (no client reading) or a slow TCP client: drop, like a
	// serial line nobody listens to.
	const ssize_t w = ::send(c.fd, bytes.data(), bytes.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
	if (w < 0 && errno == ENOTSOCK) (void)!::write(c.fd, bytes.data(), bytes.size());
}

void CArcosEmulator::handlePacket(TClient& c, const std::vector<uint8_t>& payload)
{
	++m_stats.commands;
	const auto cmd = decodeCommand(payload);
	if (!cmd) return;
	if (c.state < 3)
	{
		// Handshake: SYNCn echoes n; anything unexpected restarts at SYNC0.
		if (cmd->command == c.state)
		{
			if (c.state < 2)
				sendTo(c, framePacket({static_cast<uint8_t>(c.state)}));
			else
			{
				std::vector<uint8_t> p{2};
				for (const std::string& s : {m_opts.robot_name, std::string("Pioneer"), m_opts.subclass})
				{
					p.insert(p.end(), s.begin(), s.end());
					p.push_back(0);
				}
				sendTo(c, framePacket(p));
				++m_stats.handshakes;
			}
			++c.state;
		}
		else
			c.state = 0;
		return;
	}
	const int arg = cmd->intValue;
	switch (cmd->command)
	{
		case CMD_OPEN: c.state = 4; break;
		case CMD_CLOSE:
			c.state = 0;
			m_v = m_w = 0;
			break;
		case CMD_ENABLE: m_motors = arg != 0; break;
		case CMD_VEL: m_v = arg * 1e-3; break;
		case CMD_RVEL: m_w = arg * M_PI / 180.0; break;
		case CMD_SETO: m_odomOrigin = m_kin->odometryPose(); break;
		case CMD_SONAR: m_sonarOn = arg != 0; break;
		case CMD_STOP:
		case CMD_ESTOP: m_v = m_w = 0; break;
		default: break;  // PULSE and the rest: keep-alive only
	}
}

void CArcosEmulator::handleInput(TClient& c)
{
	uint8_t buf[512];
	for (;;)
	{
		const ssize_t n = ::read(c.fd, buf, sizeof(buf));
		if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR))
		{
			if (!c.isPty)
			{
				::close(c.fd);
				c.fd = -1;  // removed by run()
			}
			return;
		}
		if (n < 0) return;
		if (Clock::now() < m_silentUntil) continue;  // a hung device hears nothing
		c.lastRx = m_lastRxAny = Clock::now();
		c.parser.feed(buf, static_cast<size_t>(n));
		std::vector<uint8_t> payload;
		while (c.parser.next(payload)) handlePacket(c, payload);
	}
}

void CArcosEmulator::acceptClients()
{
	for (;;)
	{
		const int fd = ::accept4(m_listenFd, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
		if (fd < 0) return;
		int one = 1;
		setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
		TClient c;
		c.fd = fd;
		c.lastRx = Clock::now();
		m_clients.push_back(std::move(c));
		++m_stats.tcpAccepts;
	}
}

void CArcosEmulator::tick(double dt)
{
	if (!m_motors) return;
	// Stall against a wall: the P3-DX front is 0.21 m, the rear 0.30 m from
	// the centre of rotation (Aria p3dx-sh.p); the wheels then only turn.
	const mrpt::poses::CPose2D p = m_kin->truePose();
	const double ahead = (m_v >= 0 ? 0.21 : 0.30) + std::abs(m_v) * dt;
	const double dir = m_v >= 0 ? p.phi() : p.phi() + M_PI;
	const bool blocked = m_v != 0 && m_world && m_world->rayRange_m(p.x(), p.y(), dir, 1.0) < ahead;
	m_kin->step(blocked ? 0.0 : m_v, m_w, dt);
}

std::vector<uint8_t> CArcosEmulator::makeSip()
{
	TSip s;
	const mrpt::poses::CPose2D odo = m_kin->odometryPose() - m_odomOrigin;
	const mrpt::poses::CPose2D truth = m_kin->truePose();
	const bool moving = m_motors && (m_v != 0 || m_w != 0);
	s.type = moving ? SIP_MOVING : SIP_STOPPED;
	s.xpos_raw = static_cast<uint16_t>(std::lround(odo.x() * 1000.0) & 0x7FFF);
	s.ypos_raw = static_cast<uint16_t>(std::lround(odo.y() * 1000.0) & 0x7FFF);
	long th = std::lround(odo.phi() / ANGLE_UNIT_RAD);
	if (th >= 2048) th -= 4096;
	s.thpos_raw = static_cast<int16_t>(th);
	const double v = m_motors ? m_v : 0, w = m_motors ? m_w : 0;
	s.vel_left_raw = static_cast<int16_t>(std::lround((v - 0.5 * w * m_opts.wheel_base_m) * 1000.0));
	s.vel_right_raw = static_cast<int16_t>(std::lround((v + 0.5 * w * m_opts.wheel_base_m) * 1000.0));
	s.battery_dV = static_cast<uint8_t>(std::lround(m_opts.battery_V * 10));
	s.flags = m_motors ? 1 : 0;
	if (m_sonarOn && (m_world || m_sonarModel))
	{
		std::vector<double> ranges;
		if (m_sonarModel)
			ranges = m_sonarModel(truth);
		else
			for (const auto& sp0 : m_sonarPoses)
			{
				const mrpt::poses::CPose2D sp = truth + mrpt::poses::CPose2D(sp0);
				ranges.push_back(m_world->rayRange_m(sp.x(), sp.y(), sp.phi(), m_opts.sonar_max_range_m));
			}
		const int n = std::min<int>(m_opts.sonars_per_sip, static_cast<int>(ranges.size()));
		for (int k = 0; k < n; ++k)
		{
			const size_t i = m_nextSonar % ranges.size();
			m_nextSonar = (i + 1) % ranges.size();
			const double r = std::min(ranges[i], m_opts.sonar_max_range_m);
			s.sonars.push_back({static_cast<uint8_t>(i), static_cast<uint16_t>(std::lround(r * 1000.0))});
		}
	}
	s.has_tail = true;
	s.battery_x10 = s.battery_dV;
	s.rotvel_x10 = static_cast<int16_t>(std::lround(w * 180.0 / M_PI * 10.0));
	std::vector<uint8_t> packet = framePacket(encodeSip(s));
	// Faults.
	std::uniform_real_distribution<double> u(0, 1);
	if (m_corruptLeft > 0 || u(m_rng) < m_opts.bad_checksum_rate)
	{
		if (m_corruptLeft > 0) --m_corruptLeft;
		packet.back() ^= 0x5A;
		++m_stats.faultsInjected;
	}
	else if (m_truncateLeft > 0 || u(m_rng) < m_opts.partial_rate)
	{
		if (m_truncateLeft > 0) --m_truncateLeft;
		packet.resize(packet.size() / 2);
		++m_stats.faultsInjected;
	}
	if (u(m_rng) < m_opts.garbage_rate) m_pendingGarbage += 1 + m_rng() % 40;
	return packet;
}

void CArcosEmulator::run()
{
	auto last = Clock::now();
	auto nextSip = last + toDuration(m_opts.sip_period_s);
	while (!m_quit)
	{
		std::vector<pollfd> fds;
		if (m_listenFd >= 0) fds.push_back({m_listenFd, POLLIN, 0});
		for (const auto& c : m_clients) fds.push_back({c.fd, POLLIN, 0});
		const int waitMs = std::clamp(static_cast<int>(seconds(nextSip - Clock::now()) * 1000.0), 1, 20);
		::poll(fds.data(), fds.size(), waitMs);

		std::lock_guard<std::mutex> lk(m_mtx);
		if (m_dropRequested)
		{
			m_dropRequested = false;
			dropNow();
			continue;
		}
		if (m_listenFd >= 0) acceptClients();
		for (auto& c : m_clients) handleInput(c);
		m_clients.erase(std::remove_if(m_clients.begin(), m_clients.end(), [](const TClient& c) { return c.fd < 0; }),
						m_clients.end());

		const auto now = Clock::now();
		// ARCOS watchdog: no client packet for watchdog_s -> stop the motors
		// (also when the client is gone).
		if ((m_v != 0 || m_w != 0) && seconds(now - m_lastRxAny) > m_opts.watchdog_s)
		{
			m_v = m_w = 0;
			++m_stats.watchdogStops;
		}
		if (now < nextSip) continue;
		tick(seconds(now - last));
		last = now;
		nextSip += toDuration(m_opts.sip_period_s);
		if (nextSip < now) nextSip = now + toDuration(m_opts.sip_period_s);
		bool anyOpen = false;
		for (const auto& c : m_clients) anyOpen |= c.state == 4;
		if (!anyOpen) continue;
		const auto sip = makeSip();
		for (auto& c : m_clients)
			if (c.state == 4)
			{
				sendTo(c, sip);
				++m_stats.sipsSent;
			}
	}
}

}  // namespace hslam::hwdrivers
