#include <hslam/dynamic/dynamic_outputs.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hslam::dynamic
{
void appendTrackRows(const TDynamicFrame& frame, size_t scanIndex, std::vector<TTrackRow>& rows)
{
	const auto add = [&](const std::vector<TTrack>& tracks, const char* kind) {
		for (const auto& t : tracks)
		{
			TTrackRow r;
			r.t_s = frame.t_s;
			r.scan = scanIndex;
			r.kind = kind;
			r.track = t;
			r.seen = t.observation >= 0;
			const auto p = frame.robot_pose.inverseComposePoint(t.position());
			r.x_robot_m = p.x;
			r.y_robot_m = p.y;
			rows.push_back(r);
		}
	};
	add(frame.leg_tracks, "leg");
	add(frame.person_tracks, "person");
}

void writeTracksCsv(std::ostream& out, const std::vector<TTrackRow>& rows)
{
	out << "t_s,scan,kind,id,state,seen,x_robot_m,y_robot_m,x_world_m,y_world_m,vx_world_mps,vy_world_mps,"
		   "speed_mps,range_m,bearing_deg,v_radial_mps,v_angular_degps,hits,misses,travel_m,mean_leg_probability\n";
	out << std::fixed;
	for (const auto& r : rows)
	{
		const auto& t = r.track;
		out << std::setprecision(6) << r.t_s << ',' << r.scan << ',' << r.kind << ',' << t.id << ','
			<< toString(t.state) << ',' << (r.seen ? 1 : 0) << ',' << std::setprecision(3) << r.x_robot_m << ','
			<< r.y_robot_m << ',' << t.x[0] << ',' << t.x[1] << ',' << t.x[2] << ',' << t.x[3] << ','
			<< t.speed_mps() << ',' << t.range_m << ',' << t.bearing_rad * 180 / M_PI << ',' << t.v_radial_mps << ','
			<< t.v_angular_radps * 180 / M_PI << ',' << t.hits << ',' << t.misses << ',' << t.travel_m << ',' << t.meanLegProbability() << '\n';
	}
}

namespace
{
struct TCanvas
{
	double scale, centre;
	/** Robot frame (x forward, y left) -> pixel, forward up as in the thesis figures. */
	void px(double x, double y, int& c, int& r) const
	{
		c = static_cast<int>(std::lround(centre - y * scale));
		r = static_cast<int>(std::lround(centre - x * scale));
	}
};

const mrpt::img::TColor kScan{90, 90, 90}, kDynamicBeam{230, 30, 30}, kLeg{30, 60, 230}, kGhost{20, 160, 20},
	kText{0, 0, 0};

mrpt::img::TColor trackColour(const TTrack& t)
{
	switch (t.state)
	{
		case ETrackState::dynamic: return kDynamicBeam;
		case ETrackState::ghost: return kGhost;
		default: return {150, 120, 0};
	}
}
}  // namespace

mrpt::img::CImage renderDynamicFrame(const mrpt::obs::CObservation2DRangeScan& scan, const TDynamicFrame& frame,
									 const TDynamicImageOptions& options)
{
	mrpt::img::CImage img(options.size_px, options.size_px, mrpt::img::CH_RGB);
	img.filledRectangle(0, 0, options.size_px - 1, options.size_px - 1, mrpt::img::TColor(255, 255, 255));
	const TCanvas cv{options.size_px / (2 * options.half_width_m), options.size_px / 2.0};
	int c, r, c2, r2;
	// 1 m rings around the robot.
	for (int ring = 1; ring <= static_cast<int>(options.half_width_m); ++ring)
		img.drawCircle(static_cast<int>(cv.centre), static_cast<int>(cv.centre), static_cast<int>(ring * cv.scale),
					   mrpt::img::TColor(225, 225, 225));
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	for (size_t b = 0; b < scan.getScanSize(); ++b)
	{
		const double range = scan.getScanRange(b);
		if (!scan.getScanRangeValidity(b) || !std::isfinite(range)) continue;
		const double a = beamBearing(scan, b);
		cv.px(sx + range * std::cos(a), sy + range * std::sin(a), c, r);
		const bool dyn = b < frame.beam_is_dynamic.size() && frame.beam_is_dynamic[b];
		img.filledRectangle(c - 1, r - 1, c + 1, r + 1, dyn ? kDynamicBeam : kScan);
	}
	// Leg segments: begin and end points (thesis figures 156-165), centroid circle.
	for (const auto& leg : frame.legs)
	{
		const auto& l = leg.segment;
		cv.px(l.x_m, l.y_m, c, r);
		img.drawCircle(c, r, std::max(3, static_cast<int>(0.1 * cv.scale)), kLeg, 1);
		for (size_t b : {l.first_beam, l.last_beam})
		{
			const double range = scan.getScanRange(b), a = beamBearing(scan, b);
			cv.px(sx + range * std::cos(a), sy + range * std::sin(a), c2, r2);
			img.filledRectangle(c2 - 2, r2 - 2, c2 + 2, r2 + 2, kLeg);
		}
	}
	// Person tracks: id, speed and a velocity arrow (1 s ahead), robot frame.
	const double th = frame.robot_pose.phi(), ct = std::cos(th), st = std::sin(th);
	for (const auto& t : frame.person_tracks)
	{
		if (t.state == ETrackState::tentative) continue;
		const auto p = frame.robot_pose.inverseComposePoint(t.position());
		const double vx = ct * t.x[2] + st * t.x[3], vy = -st * t.x[2] + ct * t.x[3];
		cv.px(p.x, p.y, c, r);
		cv.px(p.x + vx, p.y + vy, c2, r2);
		const auto colour = trackColour(t);
		img.drawCircle(c, r, std::max(4, static_cast<int>(0.25 * cv.scale)), colour, 1);
		img.line(c, r, c2, r2, colour, 2);
		std::ostringstream label;
		label << "#" << t.id << " " << std::fixed << std::setprecision(2) << t.speed_mps() << "m/s";
		img.textOut(c + 6, r + 6, label.str(), colour);
	}
	std::ostringstream header;
	header << std::fixed << std::setprecision(2) << "t=" << frame.t_s << "s legs=" << frame.legs.size()
		   << " dynamic beams=" << frame.dynamicBeams() << " (rings 1 m, forward up)";
	img.textOut(5, 5, header.str(), kText);
	cv.px(0, 0, c, r);
	img.filledRectangle(c - 3, r - 3, c + 3, r + 3, kText);
	return img;
}

}  // namespace hslam::dynamic
