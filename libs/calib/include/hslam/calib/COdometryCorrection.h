/* hslam calib: applies a UMBmark calibration (thesis 4.1, eq. 25-28) to
 * odometry pose increments.
 *
 * A pose increment (dx, dy, dphi) measured with the nominal geometry is turned
 * back into the nominal wheel travels it came from (dL, dR, one arc of constant
 * curvature per increment), each wheel is scaled by its encoder factor
 * (c_L, c_R, eq. 28) and the heading change is divided by the wheelbase error
 * Eb (eq. 25: the actual wheelbase is Eb b):
 *     ds = (c_L dL + c_R dR) / 2,   dphi' = (c_R dR - c_L dL) / (Eb b).
 * Works on any odometry that reports poses (ARCOS SIPs, MRPT rawlog actions,
 * the simulator's encoders). Disabled (or all factors 1) = identity.
 * INI: section [odometry_correction] of a simulator or hslam-process INI, or
 * the same keys inside a Pioneer sensor's section (written by hslam-umbmark). */
#pragma once

#include <mrpt/poses/CPose2D.h>

namespace hslam::calib
{
struct TOdometryCorrection
{
	bool enabled = false;
	double left_factor = 1.0;  //!< c_L, eq. 28
	double right_factor = 1.0;  //!< c_R, eq. 28
	double wheelbase_ratio = 1.0;  //!< Eb = actual / nominal wheelbase (eq. 25)
	double nominal_wheelbase_m = 0.335;  //!< b the odometry was computed with

	template <class V>
	void visit(V& v)
	{
		// Prefixed names: the same keys also sit in a Pioneer sensor's section.
		v.flag("correct_odometry", enabled);
		v.real("odometry_left_factor", left_factor, 0.9, 1.1);
		v.real("odometry_right_factor", right_factor, 0.9, 1.1);
		v.real("odometry_wheelbase_ratio", wheelbase_ratio, 0.9, 1.1);
		v.real("odometry_nominal_wheelbase_m", nominal_wheelbase_m, 0.05, 5.0);
	}
};

class COdometryCorrection
{
   public:
	COdometryCorrection() = default;
	explicit COdometryCorrection(const TOdometryCorrection& options) : m_opts(options) {}

	bool active() const { return m_opts.enabled; }
	const TOdometryCorrection& options() const { return m_opts; }

	/** Corrected increment, in the robot frame at its start (identity if inactive). */
	mrpt::poses::CPose2D correctIncrement(const mrpt::poses::CPose2D& nominalIncrement) const;

	/** Corrected arc (ds_m, dphi_rad) from nominal wheel travels (for the simulator). */
	void correctWheelTravel(double dLeft_m, double dRight_m, double& ds_m, double& dphi_rad) const;

   private:
	TOdometryCorrection m_opts;
};

/** Pose increment of a constant-curvature arc of length ds_m and heading change dphi_rad. */
mrpt::poses::CPose2D arcIncrement(double ds_m, double dphi_rad);

}  // namespace hslam::calib
