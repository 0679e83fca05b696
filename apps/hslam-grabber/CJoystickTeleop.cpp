/* hslam-grabber: joystick teleoperation (see CJoystickTeleop.h). */
#include "CJoystickTeleop.h"

#include <vector>

CJoystickTeleop::CJoystickTeleop(int index, double maxV_mps, double maxW_rad_s)
	: m_index(index), m_maxV(maxV_mps), m_maxW(maxW_rad_s)
{
}

bool CJoystickTeleop::poll()
{
	float x = 0, y = 0, z = 0;
	std::vector<bool> buttons;
	if (!m_joy.getJoystickPosition(m_index, x, y, z, buttons))
	{
		m_v = m_w = 0;
		return true;
	}
	m_active = true;
	const bool deadman = !buttons.empty() && buttons[0];
	m_v = deadman ? -y * m_maxV : 0.0;  // stick forward = negative y
	m_w = deadman ? -x * m_maxW : 0.0;  // stick left = negative x = CCW
	return !(buttons.size() > 1 && buttons[1]);
}
