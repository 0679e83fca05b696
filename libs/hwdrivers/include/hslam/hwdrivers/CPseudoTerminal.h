/* hslam: a pseudo-terminal standing in for a serial device (emulators).
 *
 * posix_openpt + grantpt + unlockpt, raw mode, the emulator's own slave fd
 * kept open (otherwise reads on the master fail with EIO while no client has
 * the slave open), and an optional symlink (e.g. /tmp/pioneer -> /dev/pts/7)
 * replaced atomically when the terminal is re-created, which is how a "cable
 * pulled and plugged back" is emulated. */
#pragma once

#include <string>

namespace hslam::hwdrivers
{
class CPseudoTerminal
{
   public:
	CPseudoTerminal() = default;
	~CPseudoTerminal();
	CPseudoTerminal(const CPseudoTerminal&) = delete;
	CPseudoTerminal& operator=(const CPseudoTerminal&) = delete;

	/** Creates the terminal (closing a previous one); throws std::runtime_error. */
	void open(const std::string& symlinkPath = "");
	void close();

	int masterFd() const { return m_master; }
	/** /dev/pts/N of the client side. */
	const std::string& slavePath() const { return m_slavePath; }
	/** The symlink if one was asked for, else slavePath(). */
	std::string clientPath() const { return m_link.empty() ? m_slavePath : m_link; }

   private:
	int m_master = -1, m_slave = -1;
	std::string m_slavePath, m_link;
};

}  // namespace hslam::hwdrivers
