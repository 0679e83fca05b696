#include <hslam/common/parse_number.h>
#include <hslam/eval/point_landmark_score.h>
#include <hslam/io/csv_line.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hslam::eval
{
namespace
{
double distanceToTruth(const mrpt::math::TPoint2D& p, const mrpt::math::TPoint2D& t, double truthRadius)
{
	return std::max(0.0, std::hypot(p.x - t.x, p.y - t.y) - truthRadius);
}

}  // namespace

TPointLandmarkScore scorePointLandmarks(const std::vector<mrpt::math::TPoint2D>& found,
										const std::vector<mrpt::math::TPoint2D>& truth, double radius_m,
										const mrpt::poses::CPose2D& foundFrameInTruth, const std::vector<double>& truthRadii)
{
	if (!truthRadii.empty() && truthRadii.size() != truth.size())
		throw std::invalid_argument("scorePointLandmarks: one radius per true point expected");
	const auto radius = [&](size_t i) { return truthRadii.empty() ? 0.0 : truthRadii[i]; };
	std::vector<mrpt::math::TPoint2D> inTruthFrame;
	for (const auto& p : found)
	{
		mrpt::math::TPoint2D q;
		foundFrameInTruth.composePoint(p.x, p.y, q.x, q.y);
		inTruthFrame.push_back(q);
	}
	TPointLandmarkScore s;
	s.found = found.size();
	s.truth = truth.size();
	std::vector<bool> truthFound(truth.size(), false);
	for (const auto& p : inTruthFrame)
	{
		bool near = false;
		for (size_t i = 0; i < truth.size(); ++i)
			if (distanceToTruth(p, truth[i], radius(i)) <= radius_m) near = true, truthFound[i] = true;
		s.found_near_truth += near;
	}
	s.truth_found = static_cast<size_t>(std::count(truthFound.begin(), truthFound.end(), true));
	return s;
}

std::vector<mrpt::math::TPoint2D> readPointsCsv(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot open");
	std::string line;
	if (!std::getline(f, line)) throw std::runtime_error(path + ": empty file (no header)");
	const auto header = io::splitCsvLine(line);
	const auto column = [&](const std::string& name) {
		const auto it = std::find(header.begin(), header.end(), name);
		if (it == header.end()) throw std::runtime_error(path + ":1: no column '" + name + "'");
		return static_cast<size_t>(it - header.begin());
	};
	const size_t ix = column("x_m"), iy = column("y_m");
	std::vector<mrpt::math::TPoint2D> points;
	for (size_t lineNo = 2; std::getline(f, line); ++lineNo)
	{
		if (line.empty()) continue;
		const auto fields = io::splitCsvLine(line);
		const std::string where = path + ":" + std::to_string(lineNo);
		if (fields.size() <= std::max(ix, iy)) throw std::runtime_error(where + ": too few fields");
		const auto x = common::tryParseDouble(common::trim(fields[ix])), y = common::tryParseDouble(common::trim(fields[iy]));
		if (!x || !y) throw std::runtime_error(where + ": x_m/y_m is not a number: '" + line + "'");
		points.push_back({*x, *y});
	}
	return points;
}

}  // namespace hslam::eval
