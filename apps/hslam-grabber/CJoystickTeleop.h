/* hslam-grabber: joystick teleoperation while recording (the thesis robot was
 * driven by joystick), through MRPT's CJoystick (/dev/input/js<N>).
 * Stick forward/back = translational velocity up to max_v_mps, left/right =
 * rotational velocity up to max_w_rad_s (left = CCW); button 0 is a dead-man
 * switch: released = zero command. Button 1 stops the recording. */
#pragma once

#include <mrpt/hwdrivers/CJoystick.h>

class CJoystickTeleop
{
   public:
	CJoystickTeleop(int index, double maxV_mps, double maxW_rad_s);

	/** False until the first successful read. */
	bool active() const { return m_active; }
	/** Reads the stick; returns false when button 1 is pressed. */
	bool poll();
	double v_mps() const { return m_v; }
	double w_rad_s() const { return m_w; }

   private:
	mrpt::hwdrivers::CJoystick m_joy;
	int m_index;
	double m_maxV, m_maxW, m_v = 0, m_w = 0;
	bool m_active = false;
};
