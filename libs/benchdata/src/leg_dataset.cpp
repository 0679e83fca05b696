#include <hslam/benchdata/leg_dataset.h>
#include <hslam/io/csv_line.h>
#include <hslam/io/rawlog_scans.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace hslam::benchdata
{
namespace fs = std::filesystem;

namespace
{
std::vector<mrpt::math::TPoint2D> parseXyList(const std::string& text, const std::string& where)
{
	std::vector<mrpt::math::TPoint2D> legs;
	std::istringstream pairs(text);
	std::string xy;
	while (std::getline(pairs, xy, ';'))
	{
		mrpt::math::TPoint2D p;
		char comma = 0;
		std::istringstream one(xy);
		if (!(one >> p.x >> comma >> p.y) || comma != ',' || !std::isfinite(p.x) || !std::isfinite(p.y))
			throw std::runtime_error(where + ": annotated_xy '" + xy + "' is not 'x,y' in metres");
		legs.push_back(p);
	}
	return legs;
}

std::vector<fs::path> filesMatching(const std::string& dir, const std::string& prefix, const std::string& must)
{
	std::vector<fs::path> out;
	for (const auto& e : fs::directory_iterator(dir))
	{
		const std::string name = e.path().filename().string();
		if (name.rfind(prefix, 0) == 0 && e.path().extension() == ".rawlog" && name.find(must) != std::string::npos)
			out.push_back(e.path());
	}
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

std::vector<std::vector<mrpt::math::TPoint2D>> readLegAnnotations(const std::string& csvPath)
{
	std::ifstream in(csvPath);
	if (!in) throw std::runtime_error(csvPath + ": cannot open");
	std::string line;
	std::getline(in, line);
	const auto header = io::splitCsvLine(line);
	const auto col = std::find(header.begin(), header.end(), "annotated_xy");
	if (col == header.end()) throw std::runtime_error(csvPath + ": line 1: no 'annotated_xy' column");
	const size_t k = static_cast<size_t>(col - header.begin());
	std::vector<std::vector<mrpt::math::TPoint2D>> rows;
	for (size_t lineNo = 2; std::getline(in, line); ++lineNo)
	{
		const std::string where = csvPath + ": line " + std::to_string(lineNo);
		const auto fields = io::splitCsvLine(line);
		if (fields.size() != header.size())
			throw std::runtime_error(where + ": " + std::to_string(fields.size()) + " fields, header has " +
									 std::to_string(header.size()));
		rows.push_back(parseXyList(fields[k], where));
	}
	return rows;
}

std::vector<TLegDataPart> loadLegDataset(const std::string& dir)
{
	if (!fs::is_directory(dir)) throw std::runtime_error(dir + ": not a folder");
	std::vector<TLegDataPart> parts;
	for (const auto& p : filesMatching(dir, "positive_", "_extracted"))
	{
		TLegDataPart part;
		part.name = p.stem().string();
		part.has_people = true;
		part.scans = io::readRangeScans(p.string());
		const std::string csv = (p.parent_path() / (p.stem().string() + ".scans.csv")).string();
		part.annotations = readLegAnnotations(csv);
		if (part.annotations.size() != part.scans.size())
			throw std::runtime_error(csv + ": " + std::to_string(part.annotations.size()) + " rows but " +
									 p.string() + " has " + std::to_string(part.scans.size()) + " scans");
		parts.push_back(std::move(part));
	}
	for (const auto& p : filesMatching(dir, "negative_", ""))
	{
		std::map<std::string, TLegDataPart> bySensor;
		for (const auto& s : io::readRangeScans(p.string()))
		{
			auto& part = bySensor[s->sensorLabel];
			part.name = p.stem().string() + "/" + s->sensorLabel;
			part.scans.push_back(s);
		}
		for (auto& [label, part] : bySensor) parts.push_back(std::move(part));
	}
	if (parts.empty())
		throw std::runtime_error(dir + ": no positive_*_extracted.rawlog nor negative_*.rawlog (see "
									   "../shared/datasets/legs/README.md for the layout)");
	return parts;
}

bool inAnnotatedArc(const mrpt::math::TPoint2D& p)
{
	const double bearing_deg = std::atan2(p.y, p.x) * 180 / M_PI;
	return bearing_deg > -15 && bearing_deg < 15 && std::hypot(p.x, p.y) < 5.0;
}

std::vector<TLabelledCluster> labelledClusters(const TLegDataPart& part, const dynamic::TClusterOptions& clustering,
											   double maxCentroidRange_m)
{
	constexpr double kAnnotationMatch_m = 0.01;
	std::vector<TLabelledCluster> out;
	for (size_t i = 0; i < part.scans.size(); ++i)
	{
		const auto clusters = dynamic::clusterScan(*part.scans[i], clustering);
		for (size_t k = 0; k < clusters.size(); ++k)
		{
			const auto& c = clusters[k];
			TLabelledCluster l;
			l.scan = i;
			l.centroid = c.centroid;
			if (std::hypot(l.centroid.x, l.centroid.y) >= maxCentroidRange_m) continue;
			l.features = dynamic::legFeatures(clusters, k, *part.scans[i]);
			if (!part.has_people)
				l.label = TLabelledCluster::ELabel::non_leg;
			else if (inAnnotatedArc(l.centroid))
			{
				bool annotated = false;
				for (const auto& a : part.annotations[i])
					annotated |= std::hypot(a.x - l.centroid.x, a.y - l.centroid.y) < kAnnotationMatch_m;
				l.label = annotated ? TLabelledCluster::ELabel::leg : TLabelledCluster::ELabel::non_leg;
			}
			out.push_back(l);
		}
	}
	return out;
}

}  // namespace hslam::benchdata
