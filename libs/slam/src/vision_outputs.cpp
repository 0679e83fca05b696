#include <hslam/common/output_folder.h>
#include <hslam/slam/vision_outputs.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace hslam::slam
{
void writeVisionCsv(const std::vector<TVisionRow>& rows, std::ostream& out)
{
	out << "frame,t_s,robot_yaw_deg,rotation_known,corners,tracks,lost,fb_rejected,foe_valid,foe_x_px,foe_y_px,"
		   "foe_confidence,foe_std_px,foe_vectors,foe_expanding,vote_x_valid,vote_x_px,vote_y_valid,vote_y_px,"
		   "inconsistent_vectors,moving_regions,region_bearings_deg\n";
	out << std::fixed << std::setprecision(6);
	for (const auto& r : rows)
	{
		out << r.frame << ',' << r.t_s << ',' << r.robot_yaw_deg << ',' << r.rotation_known << ',' << r.corners << ','
			<< r.tracks << ',' << r.lost << ',' << r.fb_rejected << ',' << r.foe.valid << ',' << r.foe.x_px << ','
			<< r.foe.y_px << ',' << r.foe.confidence << ',' << r.foe.std_px << ',' << r.foe.used << ','
			<< r.foe.expanding << ',' << r.vote.valid_x << ',' << r.vote.x_px << ',' << r.vote.valid_y << ','
			<< r.vote.y_px << ',' << r.inconsistent << ',' << r.regions.size() << ',';
		for (size_t i = 0; i < r.regions.size(); ++i)
			out << (i ? " " : "") << r.regions[i].bearing_rad * 180.0 / M_PI;
		out << '\n';
	}
}

void writeVisionOutputs(const CVisionStage& stage, const std::string& dir, std::vector<std::string>& written)
{
	if (stage.rows().empty()) return;
	const std::string path = dir + "/vision.csv";
	common::writeStreamAtomically(path, [&stage](std::ostream& csv) { writeVisionCsv(stage.rows(), csv); });
	written.push_back(path);
	if (stage.debugImages().empty()) return;
	std::filesystem::create_directories(dir + "/vision");
	for (const auto& [frame, png] : stage.debugImages())
	{
		std::ostringstream name;
		name << dir << "/vision/frame_" << std::setw(6) << std::setfill('0') << frame << ".png";
		common::writeTextFileAtomically(name.str(), std::string(png.begin(), png.end()));
		written.push_back(name.str());
	}
}

}  // namespace hslam::slam
