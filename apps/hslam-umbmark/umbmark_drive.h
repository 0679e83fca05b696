/* hslam-umbmark --drive: the UMBmark square (thesis 4.1: L = 4.4 m, run
 * clockwise and counter-clockwise) driven by the tool itself. The simulated
 * P3-DX of a simulator INI (libs/sim CSimulator, the code hslam-navigate's
 * simulated mode and hslam-simulate run; [robot] gives its Ed, Eb and random
 * slip) follows the square's corners by its own odometry, as the thesis's
 * robot did; every observation is recorded into a rawlog and the true pose
 * into a TUM file, and the calibration is then computed from that recording
 * exactly as for `hslam-umbmark -i RAWLOG --truth TUM`. */
#pragma once

#include <hslam/calib/umbmark_runs.h>

#include <string>
#include <vector>

namespace hslam::apps
{
/** [umbmark_drive] of the drive INI (config_ini/umbmark-drive.ini). */
struct TUmbmarkDriveOptions
{
	std::string sim_ini = "sim-umbmark.ini";  //!< robot and follower; relative to the drive INI
	double side_m = 4.4;  //!< L (thesis 4.1: 4.4 m)
	int runs_per_direction = 5;  //!< Borenstein & Feng: 5 CW + 5 CCW
	double start_x_m = 0, start_y_m = 0;  //!< first corner (world frame of the scene)

	template <class V>
	void visit(V& v)
	{
		v.text("sim_ini", sim_ini);
		v.real("side_m", side_m, 0.5, 50);
		v.integer("runs_per_direction", runs_per_direction, 1, 50);
		v.real("start_x_m", start_x_m, -1e4, 1e4);
		v.real("start_y_m", start_y_m, -1e4, 1e4);
	}
};

/** Loads [umbmark_drive] of `path`; errors name the file and the key. */
TUmbmarkDriveOptions loadDriveOptions(const std::string& path);

/** Waypoints "x y; ..." of the runs: CW squares first, then CCW, starting and
 * ending at (start_x, start_y) heading +x. */
std::string umbmarkSquareWaypoints(const TUmbmarkDriveOptions& options);

struct TUmbmarkDriveOutput
{
	std::string rawlog;  //!< outDir/umbmark.rawlog
	std::string truth;  //!< outDir/ground_truth.tum (the pose at every odometry reading)
	double sim_time_s = 0;
};

/** Drives the runs (simulated time) and writes the recording into `outDir`
 * (created; must not hold a previous umbmark.rawlog). */
TUmbmarkDriveOutput driveUmbmark(const std::string& driveIni, const TUmbmarkDriveOptions& options,
								 const std::string& outDir);

}  // namespace hslam::apps
