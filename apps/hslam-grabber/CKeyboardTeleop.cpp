/* hslam-grabber: keyboard teleoperation (see CKeyboardTeleop.h). */
#include "CKeyboardTeleop.h"

#include <poll.h>
#include <unistd.h>

#include <iostream>

CKeyboardTeleop::CKeyboardTeleop(double vStep_mps, double wStep_rad_s) : m_vStep(vStep_mps), m_wStep(wStep_rad_s)
{
	if (!isatty(STDIN_FILENO) || tcgetattr(STDIN_FILENO, &m_saved) != 0) return;
	termios raw = m_saved;
	raw.c_lflag &= ~(ICANON | ECHO);
	raw.c_cc[VMIN] = 0;
	raw.c_cc[VTIME] = 0;
	m_active = tcsetattr(STDIN_FILENO, TCSANOW, &raw) == 0;
	if (m_active) std::cerr << "teleop: w/s speed, a/d turn, space stop, q quit\n";
}

CKeyboardTeleop::~CKeyboardTeleop()
{
	if (m_active) tcsetattr(STDIN_FILENO, TCSANOW, &m_saved);
}

bool CKeyboardTeleop::poll()
{
	if (!m_active) return true;
	pollfd p{STDIN_FILENO, POLLIN, 0};
	while (::poll(&p, 1, 0) > 0)
	{
		char c;
		if (::read(STDIN_FILENO, &c, 1) != 1) break;
		switch (c)
		{
			case 'w': m_v += m_vStep; break;
			case 's': m_v -= m_vStep; break;
			case 'a': m_w += m_wStep; break;
			case 'd': m_w -= m_wStep; break;
			case ' ': m_v = m_w = 0; break;
			case 'q': return false;
			default: break;
		}
	}
	return true;
}
