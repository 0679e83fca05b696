/* hslam-grabber: keyboard teleoperation while recording (stdin in raw mode):
 *   w / s : translational velocity +/- v_step_mps     a / d : rotational velocity +/- w_step (CCW +)
 *   space : stop                                      q     : stop recording
 * The current command is re-sent every poll() (so the driver's command watchdog
 * only fires if the grabber itself hangs). Only active when stdin is a terminal. */
#pragma once

#include <termios.h>

class CKeyboardTeleop
{
   public:
	CKeyboardTeleop(double vStep_mps, double wStep_rad_s);
	~CKeyboardTeleop();

	bool active() const { return m_active; }
	/** Reads pending keys; returns false when 'q' was pressed. */
	bool poll();
	double v_mps() const { return m_v; }
	double w_rad_s() const { return m_w; }

   private:
	bool m_active = false;
	termios m_saved{};
	double m_vStep, m_wStep, m_v = 0, m_w = 0;
};
