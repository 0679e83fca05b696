/* hslam: pseudo-terminal for emulators (see CPseudoTerminal.h). */
#include <hslam/hwdrivers/CPseudoTerminal.h>
#include <hslam/hwdrivers/byte_stream.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace hslam::hwdrivers
{
CPseudoTerminal::~CPseudoTerminal()
{
	close();
	if (!m_link.empty()) ::unlink(m_link.c_str());
}

void CPseudoTerminal::close()
{
	if (m_slave >= 0) ::close(m_slave);
	if (m_master >= 0) ::close(m_master);
	m_slave = m_master = -1;
}

void CPseudoTerminal::open(const std::string& symlinkPath)
{
	close();
	m_master = posix_openpt(O_RDWR | O_NOCTTY);
	if (m_master < 0 || grantpt(m_master) != 0 || unlockpt(m_master) != 0)
		throw std::runtime_error(std::string("posix_openpt: ") + std::strerror(errno));
	const char* name = ptsname(m_master);
	if (!name) throw std::runtime_error("ptsname failed");
	m_slavePath = name;
	m_slave = ::open(name, O_RDWR | O_NOCTTY);
	if (m_slave < 0) throw std::runtime_error(m_slavePath + ": " + std::strerror(errno));
	setRawTerminal(m_slave, 9600);
	setRawTerminal(m_master, 9600);
	const int fl = fcntl(m_master, F_GETFL);
	fcntl(m_master, F_SETFL, fl | O_NONBLOCK);
	fcntl(m_master, F_SETFD, FD_CLOEXEC);
	fcntl(m_slave, F_SETFD, FD_CLOEXEC);
	m_link = symlinkPath;
	if (!m_link.empty())
	{
		const std::string tmp = m_link + ".new";
		::unlink(tmp.c_str());
		if (::symlink(m_slavePath.c_str(), tmp.c_str()) != 0 || ::rename(tmp.c_str(), m_link.c_str()) != 0)
			throw std::runtime_error("cannot create symlink " + m_link + ": " + std::strerror(errno));
	}
}

}  // namespace hslam::hwdrivers
