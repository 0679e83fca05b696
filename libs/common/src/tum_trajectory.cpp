#include <hslam/common/parse_number.h>
#include <hslam/common/output_folder.h>
#include <hslam/common/tum_trajectory.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hslam::common
{
void writeTumFile(const std::string& path, const TTrajectory2D& trajectory)
{
	std::string text = "# timestamp tx ty tz qx qy qz qw\n";
	for (const auto& p : trajectory)
	{
		const double half = 0.5 * p.pose.phi;
		const auto format = [&](char* out, size_t size) {
			return std::snprintf(out, size, "%.6f %.6f %.6f 0 0 0 %.9f %.9f\n", p.t_s, p.pose.x, p.pose.y,
								 std::sin(half), std::cos(half));
		};
		std::string line(static_cast<size_t>(format(nullptr, 0)) + 1, '\0');  // %f of 1e300 is 300+ characters
		line.resize(static_cast<size_t>(format(line.data(), line.size())));
		text += line;
	}
	writeTextFileAtomically(path, text);  // a cut-short write never replaces a previous file
}

TTrajectory2D parseTum(const std::string& text, const std::string& name)
{
	TTrajectory2D out;
	std::istringstream in(text);
	std::string line;
	for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber)
	{
		const std::string content = trim(line);
		if (content.empty() || content[0] == '#') continue;
		std::istringstream fields(content);
		std::vector<double> v;
		for (std::string token; fields >> token;)
		{
			const auto value = tryParseDouble(token);
			if (!value)
				throw std::runtime_error(name + ":" + std::to_string(lineNumber) + ": bad number '" + token + "'");
			v.push_back(*value);
		}
		if (v.size() != 8)
			throw std::runtime_error(name + ":" + std::to_string(lineNumber) + ": expected 8 fields (t tx ty tz qx qy qz qw), got " +
									 std::to_string(v.size()));
		const double qx = v[4], qy = v[5], qz = v[6], qw = v[7];
		if (std::abs(qx * qx + qy * qy + qz * qz + qw * qw - 1.0) > 1e-3)
			throw std::runtime_error(name + ":" + std::to_string(lineNumber) + ": quaternion is not unit length");
		TTimedPose2D p;
		p.t_s = v[0];
		p.pose.x = v[1];
		p.pose.y = v[2];
		p.pose.phi = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
		out.push_back(p);
	}
	return out;
}

TTrajectory2D readTumFile(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error(path + ": cannot open trajectory file");
	std::stringstream contents;
	contents << in.rdbuf();
	return parseTum(contents.str(), path);
}

}  // namespace hslam::common
