/* hslam: sonar pose list parsing (see p3dx_geometry.h). */
#include <hslam/hwdrivers/p3dx_geometry.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hslam::hwdrivers
{
std::vector<mrpt::math::TPose2D> parseSonarPoses(const std::string& text)
{
	std::vector<mrpt::math::TPose2D> poses;
	std::string normalised = text;
	for (char& c : normalised)
		if (c == ';') c = ',';
	std::stringstream all(normalised);
	std::string entry;
	while (std::getline(all, entry, ','))
	{
		if (entry.find_first_not_of(" \t") == std::string::npos) continue;
		std::istringstream is(entry);
		double x, y, yawDeg;
		std::string extra;
		if (!(is >> x >> y >> yawDeg) || (is >> extra) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yawDeg))
			throw std::invalid_argument("sonar pose #" + std::to_string(poses.size()) + " '" + entry +
										"' is not 'x_m y_m yaw_deg'");
		poses.emplace_back(x, y, yawDeg * M_PI / 180.0);
	}
	if (poses.empty()) throw std::invalid_argument("no sonar poses given");
	return poses;
}

}  // namespace hslam::hwdrivers
