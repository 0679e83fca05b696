#include <hslam/common/output_folder.h>
#include <hslam/common/version.h>
#include <hslam/batch/html_report.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace hslam::batch
{
namespace
{
constexpr size_t kMaxTableRows = 100;  // longer tables: see the CSV file

const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em;max-width:1200px;color:#222}
h1{font-size:1.5em}h2{border-bottom:1px solid #ccc;margin-top:1.6em}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 8px;text-align:right}
th{background:#eee}td.l,th.l{text-align:left}img{max-width:100%;border:1px solid #ccc}
figure{display:inline-block;margin:0 1em 1em 0;vertical-align:top}figcaption{font-size:.9em;color:#555}
.warn{color:#a40}.ok{color:#080}pre{background:#f6f6f6;padding:.6em;overflow:auto;max-height:40em}
nav a{margin-right:1em})";

std::string number(double value, const char* format = "%.3f")
{
	char text[64];
	std::snprintf(text, sizeof(text), format, value);
	return text;
}

std::string figureRow(const std::string& label, const std::string& key, const std::string& value)
{
	return "<tr><th class=\"l\">" + htmlEscape(label) + "</th><td id=\"fig-" + key + "\">" + htmlEscape(value) +
		   "</td></tr>\n";
}

void writeSummaryTable(std::ostream& h, const TRunSummary& s)
{
	h << "<h2 id=\"summary\">Summary</h2>\n<table>\n"
	  << figureRow("input", "input", s.input) << figureRow("pose estimation", "pose_method", s.pose_method)
	  << figureRow("rawlog entries", "entries", std::to_string(s.entries))
	  << figureRow("laser scans used", "scans", std::to_string(s.scans))
	  << figureRow("wall time (s)", "wall_s", number(s.wall_s))
	  << figureRow("ms per scan", "ms_per_scan", number(s.ms_per_scan))
	  << figureRow("tiles", "tiles", std::to_string(s.tiles))
	  << figureRow("leg tracks", "leg_tracks", std::to_string(s.leg_tracks))
	  << figureRow("person tracks", "person_tracks", std::to_string(s.person_tracks))
	  << figureRow("TBF sonar corners", "sonar_corners", std::to_string(s.sonar_corners))
	  << figureRow("odometry distance scale (self-calibration)", "odometry_distance_scale",
				   number(s.odometry_distance_scale, "%.4f") + (s.odometry_scale_applied ? ", applied" : ", not applied"))
	  << figureRow("odometry turn scale, curvature deg/m (self-calibration)", "odometry_curvature_deg_per_m",
				   number(s.odometry_heading_scale, "%.4f") + ", " + number(s.odometry_curvature_deg_per_m, "%.3f") +
					   (s.odometry_heading_applied ? ", applied" : ", not applied"))
	  << figureRow("odometry time offset in use, s (fit)", "odometry_time_offset_s",
				   number(s.odometry_time_offset_s, "%.3f") + " (" +
					   (s.odometry_time_offset_fit_s ? number(*s.odometry_time_offset_fit_s, "%.3f") : "none") + ")");
	if (s.evaluation && !s.evaluation->ate.position_m.empty())
		h << figureRow("ATE RMSE (m)", "ate_rmse_m", number(s.evaluation->ate.position_m.rmse, "%.4f"));
	h << "</table>\n";
}

void writeWarnings(std::ostream& h, const TRunSummary& s)
{
	h << "<h2 id=\"warnings\">Warnings</h2>\n";
	if (s.warnings.empty())
	{
		h << "<p class=\"ok\" id=\"fig-warnings\">none</p>\n";
		return;
	}
	h << "<ul id=\"fig-warnings\">\n";
	for (const auto& w : s.warnings) h << "<li class=\"warn\">" << htmlEscape(w) << "</li>\n";
	h << "</ul>\n";
}

void writeFigures(std::ostream& h, const std::string& dir, const std::string& title, const std::string& anchor,
				  const std::vector<std::pair<std::string, std::string>>& images)
{
	std::ostringstream figures;
	for (const auto& [file, caption] : images)
		if (std::filesystem::exists(std::filesystem::path(dir) / file))
			figures << "<figure><a href=\"" << file << "\"><img src=\"" << file << "\" alt=\"" << htmlEscape(caption)
					<< "\"></a><figcaption>" << htmlEscape(caption) << " (" << file << ")</figcaption></figure>\n";
	if (figures.str().empty()) return;
	h << "<h2 id=\"" << anchor << "\">" << title << "</h2>\n" << figures.str();
}

void writeTiming(std::ostream& h, const common::CStageTimer& timer)
{
	h << "<h2 id=\"timing\">Timing per stage</h2>\n<table>\n<tr><th class=\"l\">stage</th><th>calls</th>"
	  << "<th>mean ms</th><th>p95 ms</th><th>max ms</th><th>total ms</th></tr>\n";
	for (const auto& st : timer.stats())
		h << "<tr><td class=\"l\">" << htmlEscape(st.stage) << "</td><td>" << st.count << "</td><td>"
		  << number(st.mean_ms) << "</td><td>" << number(st.p95_ms) << "</td><td>" << number(st.max_ms)
		  << "</td><td>" << number(st.total_ms, "%.1f") << "</td></tr>\n";
	h << "</table>\n<p>Also in <a href=\"timing.csv\">timing.csv</a>.</p>\n";
}

void writeEvaluation(std::ostream& h, const TRunSummary& s)
{
	if (!s.evaluation) return;
	const auto& e = *s.evaluation;
	h << "<h2 id=\"evaluation\">Evaluation against the reference</h2>\n<p>" << e.matched << " poses matched ("
	  << e.unmatched_estimate << " estimated and " << e.unmatched_reference
	  << " reference poses unmatched). ATE after SE(2) alignment; RPE per pose-pair family.</p>\n"
	  << "<table>\n<tr><th class=\"l\">error</th><th>pairs</th><th>RMSE</th><th>mean</th><th>max</th></tr>\n";
	const auto row = [&](const std::string& name, const eval::TErrorStats& st, const std::string& unit) {
		h << "<tr><td class=\"l\">" << htmlEscape(name) << " (" << unit << ")</td><td>" << st.count << "</td><td>"
		  << number(st.rmse, "%.4f") << "</td><td>" << number(st.mean, "%.4f") << "</td><td>"
		  << number(st.max, "%.4f") << "</td></tr>\n";
	};
	row("ATE position", e.ate.position_m, "m");
	for (const auto& r : e.rpe)
	{
		row("RPE " + r.name + " translation", r.errors.trans_m, "m");
		row("RPE " + r.name + " rotation", r.errors.rot_deg, "deg");
	}
	h << "</table>\n<p>Also in <a href=\"evaluation.json\">evaluation.json</a>.</p>\n";
}

/** "low score 298, ambiguous 30" */
std::string reasonsText(const std::map<std::string, size_t>& counts)
{
	std::string out;
	for (const auto& [reason, n] : counts) out += (out.empty() ? "" : ", ") + reason + " " + std::to_string(n);
	return out.empty() ? "-" : out;
}

/** The back-end's figures, the ATE before and after it, and the closures
 * drawn on the map. */
void writeLoopClosure(std::ostream& h, const TRunSummary& s, const std::string& dir)
{
	if (!s.loop_closure) return;
	const auto& l = *s.loop_closure;
	h << "<h2 id=\"loop-closure\">Loop closure</h2>\n<table>\n"
	  << figureRow("keyframes (graph nodes)", "keyframes", std::to_string(l.keyframes))
	  << figureRow("closures tested", "closures_tested", std::to_string(l.closures_tested))
	  << figureRow("closures accepted", "closures_accepted", std::to_string(l.closures_accepted))
	  << figureRow("closures rejected", "closures_rejected", std::to_string(l.closures_rejected))
	  << figureRow("rejected because", "rejected_by_reason", reasonsText(l.rejected_by_reason))
	  << figureRow("optimisations", "optimizations", std::to_string(l.optimizations))
	  << figureRow("back-end time (ms)", "backend_ms", number(l.backend_ms, "%.1f"))
	  << figureRow("map re-rendered from the optimised graph", "map_rerendered", l.map_rerendered ? "yes" : "no");
	if (l.ate_online_rmse_m && s.evaluation && !s.evaluation->ate.position_m.empty())
		h << figureRow("ATE RMSE before the pose graph (m)", "ate_online_rmse_m", number(*l.ate_online_rmse_m, "%.4f"))
		  << figureRow("ATE RMSE after (m)", "ate_optimised_rmse_m", number(s.evaluation->ate.position_m.rmse, "%.4f"));
	h << "</table>\n<p>Every tested closure with its scores: <a href=\"loop_closures.csv\">loop_closures.csv</a>; "
	  << "the graph in MRPT's format: <a href=\"graph.graph\">graph.graph</a>; the online trajectory: "
	  << "<a href=\"trajectory_online.tum\">trajectory_online.tum</a>.</p>\n";
	const std::string closures = "map_loop_closures.png";
	if (std::filesystem::exists(std::filesystem::path(dir) / closures))
		h << "<figure><a href=\"" << closures << "\"><img src=\"" << closures
		  << "\" alt=\"loop closures\"></a><figcaption>closures between keyframes: accepted green, rejected blue, "
		  << "dropped by the optimiser orange (" << closures << ")</figcaption></figure>\n";
}

/** One line per track: kind, id, first/last time, scans seen, last position. */
void writeTracks(std::ostream& h, const slam::CMappingPipeline& pipeline)
{
	if (!pipeline.dynamicFilter()) return;
	struct TSpan
	{
		const char* kind;
		double first_s, last_s;
		size_t seen;
		double x_m, y_m;
	};
	std::map<std::pair<std::string, int>, TSpan> spans;
	for (const auto& r : pipeline.trackRows())
	{
		auto [it, added] = spans.try_emplace({r.kind, r.track.id}, TSpan{r.kind, r.t_s, r.t_s, 0, 0, 0});
		it->second.last_s = r.t_s;
		it->second.seen += r.seen ? 1 : 0;
		it->second.x_m = r.track.x[0];
		it->second.y_m = r.track.x[1];
	}
	h << "<h2 id=\"tracks\">Leg and person tracks</h2>\n<p>" << spans.size()
	  << " tracks; every row per scan is in <a href=\"tracks.csv\">tracks.csv</a>.</p>\n<table>\n"
	  << "<tr><th class=\"l\">kind</th><th>id</th><th>first t (s)</th><th>last t (s)</th><th>scans seen</th>"
	  << "<th>last x (m)</th><th>last y (m)</th></tr>\n";
	size_t n = 0;
	for (const auto& [key, sp] : spans)
		if (n++ < kMaxTableRows)
			h << "<tr><td class=\"l\">" << sp.kind << "</td><td>" << key.second << "</td><td>" << number(sp.first_s)
			  << "</td><td>" << number(sp.last_s) << "</td><td>" << sp.seen << "</td><td>" << number(sp.x_m, "%.2f")
			  << "</td><td>" << number(sp.y_m, "%.2f") << "</td></tr>\n";
	h << "</table>\n";
}

void writeSonarCorners(std::ostream& h, const slam::CMappingPipeline& pipeline)
{
	const auto& corners = pipeline.sonarStage().corners();
	if (!pipeline.sonarStage().reportsCorners()) return;
	h << "<h2 id=\"corners\">TBF sonar corners</h2>\n<p>" << corners.size()
	  << " corners (map frame); also in <a href=\"sonar_corners.csv\">sonar_corners.csv</a>.</p>\n";
	if (corners.empty()) return;
	h << "<table>\n<tr><th>x (m)</th><th>y (m)</th><th>support</th><th>hypotheses</th><th>sigma x (m)</th>"
	  << "<th>sigma y (m)</th></tr>\n";
	for (size_t i = 0; i < corners.size() && i < kMaxTableRows; ++i)
	{
		const auto& c = corners[i];
		h << "<tr><td>" << number(c.point.x, "%.2f") << "</td><td>" << number(c.point.y, "%.2f") << "</td><td>"
		  << c.support << "</td><td>" << c.hypotheses << "</td><td>" << number(std::sqrt(c.cov(0, 0)), "%.3f")
		  << "</td><td>" << number(std::sqrt(c.cov(1, 1)), "%.3f") << "</td></tr>\n";
	}
	h << "</table>\n";
}

void writeConfiguration(std::ostream& h, const std::string& dir)
{
	std::ifstream f(std::filesystem::path(dir) / "config_used.ini");
	if (!f) return;
	std::ostringstream text;
	text << f.rdbuf();
	h << "<h2 id=\"config\">Effective configuration</h2>\n<p><a href=\"config_used.ini\">config_used.ini</a> "
	  << "reproduces this run (<code>hslam-process -c config_used.ini ...</code>).</p>\n<pre>"
	  << htmlEscape(text.str()) << "</pre>\n";
}
}  // namespace

std::string htmlEscape(const std::string& text)
{
	std::string out;
	out.reserve(text.size());
	for (const char c : text)
	{
		switch (c)
		{
			case '&': out += "&amp;"; break;
			case '<': out += "&lt;"; break;
			case '>': out += "&gt;"; break;
			case '"': out += "&quot;"; break;
			default: out += c;
		}
	}
	return out;
}

void writeHtmlReport(const TRunSummary& summary, const slam::CMappingPipeline& pipeline, const std::string& dir)
{
	std::ostringstream h;
	h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>hslam-process: "
	  << htmlEscape(summary.input) << "</title>\n<style>\n" << kStyle << "\n</style>\n</head>\n<body>\n"
	  << "<h1>hslam-process report</h1>\n<p>" << htmlEscape(summary.input) << " &rarr; "
	  << htmlEscape(summary.output_dir) << "<br>hslam " << common::versionText()
	  << ". Figures also in <a href=\"summary.json\">summary.json</a>.</p>\n"
	  << "<nav><a href=\"#summary\">summary</a><a href=\"#warnings\">warnings</a><a href=\"#map\">map</a>"
	  << "<a href=\"#poses\">poses</a><a href=\"#loop-closure\">loop closure</a><a href=\"#timing\">timing</a>"
	  << "<a href=\"#evaluation\">evaluation</a>"
	  << "<a href=\"#tracks\">tracks</a><a href=\"#corners\">sonar corners</a><a href=\"#config\">configuration</a>"
	  << "</nav>\n";
	writeSummaryTable(h, summary);
	writeWarnings(h, summary);
	writeFigures(h, dir, "Map", "map",
				 {{"map.png", "merged map, estimate red, odometry orange"},
				  {"map_sonar_corners.png", "map with TBF sonar corners"},
				  {"map_laser_only.png", "laser only"},
				  {"map_sonar_only.png", "sonar only"}});
	writeFigures(h, dir, "Pose estimates", "poses", {{"pose_plot.png", "x, y, theta with +-1 sigma and odometry"}});
	writeLoopClosure(h, summary, dir);
	writeTiming(h, pipeline.timer());
	writeEvaluation(h, summary);
	writeTracks(h, pipeline);
	writeSonarCorners(h, pipeline);
	writeConfiguration(h, dir);
	h << "</body>\n</html>\n";
	const std::string path = (std::filesystem::path(dir) / "report.html").string();
	common::writeTextFileAtomically(path, h.str());
}

}  // namespace hslam::batch
