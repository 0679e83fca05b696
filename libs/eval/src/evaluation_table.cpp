/* hslam: printing an evaluation as a text table. */
#include <hslam/eval/evaluation_table.h>

#include <mrpt/core/bits_math.h>

#include <iomanip>
#include <algorithm>
#include <cmath>
#include <sstream>

namespace hslam::eval
{
namespace
{
void printInput(std::ostream& os, const char* role, const std::string& label, size_t poses,
				const TTimeRange& t)
{
	os << "  " << std::left << std::setw(10) << role << std::right << label << ": " << poses << " poses";
	if (!t.empty) os << ", t = [" << t.first_s << ", " << t.last_s << "] s";
	os << "\n";
}

void printHeader(std::ostream& os, const TTrajectoryErrors& e)
{
	os << "Trajectory evaluation\n" << std::fixed << std::setprecision(3);
	printInput(os, "reference", e.reference_label, e.reference_poses, e.reference_time);
	printInput(os, "estimate", e.estimate_label, e.estimate_poses, e.estimate_time);
	os << "  matched   " << e.matched << " poses within " << std::defaultfloat << e.max_dt_s << std::fixed
	   << " s (unmatched: "
	   << e.unmatched_estimate << " estimate, " << e.unmatched_reference << " reference)\n";
	os << "  alignment x = " << e.ate.alignment.x << " m, y = " << e.ate.alignment.y
	   << " m, phi = " << mrpt::RAD2DEG(e.ate.alignment.phi) << " deg (applied to the estimate)\n\n";
}

void printAte(std::ostream& os, const TErrorStats& ate_m)
{
	os << std::left << std::setw(34) << "ATE (m, after SE(2) alignment)" << std::right << std::setw(10) << "rmse"
	   << std::setw(10) << "mean" << std::setw(10) << "max" << "\n";
	os << std::setprecision(4) << std::setw(34) << "" << std::setw(10) << ate_m.rmse << std::setw(10)
	   << ate_m.mean << std::setw(10) << ate_m.max << "\n\n";
}

void printRpeRow(std::ostream& os, const TRpeResult& r)
{
	os << std::left << std::setw(14) << r.name << std::right << std::setw(7) << r.errors.pairs();
	if (r.errors.pairs() == 0)
	{
		os << "   no pairs: the matched reference path never covers " << std::defaultfloat << r.distance_m
		   << " m\n" << std::fixed;
		return;
	}
	const auto& t = r.errors.trans_m;
	const auto& a = r.errors.rot_deg;
	os << std::setprecision(4) << std::setw(14) << t.rmse << std::setw(14) << t.mean << std::setw(14) << t.max
	   << std::setprecision(3) << std::setw(14) << a.rmse << std::setw(14) << a.mean << std::setw(14) << a.max
	   << "\n";
}

void printRpe(std::ostream& os, const std::vector<TRpeResult>& rpe)
{
	os << std::left << std::setw(14) << "RPE" << std::right << std::setw(7) << "pairs" << std::setw(14)
	   << "trans rmse m" << std::setw(14) << "trans mean m" << std::setw(14) << "trans max m" << std::setw(14)
	   << "rot rmse deg" << std::setw(14) << "rot mean deg" << std::setw(14) << "rot max deg" << "\n";
	for (const auto& r : rpe) printRpeRow(os, r);
}

}  // namespace

void printEvaluation(std::ostream& os, const TTrajectoryErrors& errors)
{
	std::ostringstream text;  // format here so the caller's stream flags stay as they were
	printHeader(text, errors);
	printAte(text, errors.ate.position_m);
	printRpe(text, errors.rpe);
	os << text.str();
}

namespace
{
void printPairs(std::ostream& os, const char* title, std::vector<TScanPairMisfit> pairs, size_t listed)
{
	std::sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b)
			  { return std::abs(a.estimate_m - a.reference_m) > std::abs(b.estimate_m - b.reference_m); });
	os << "  " << title << ": " << pairs.size() << " pairs";
	if (!pairs.empty()) os << " (t s: reference / estimate misfit m)";
	os << "\n";
	for (size_t k = 0; k < std::min(listed, pairs.size()); ++k)
		os << "    t=" << std::setprecision(3) << std::fixed << pairs[k].t_s << "  " << pairs[k].reference_m << " / "
		   << pairs[k].estimate_m << "\n";
}
}  // namespace

void printScanConsistency(std::ostream& os, const TScanConsistency& c, size_t listed)
{
	std::ostringstream text;
	text << "\nScan consistency (consecutive scans placed at each trajectory's poses; mean distance of a scan's\n"
		 << "points to the previous scan's, each capped; lower is better):\n"
		 << "  scans " << c.scans << ", pairs posed by both " << c.pairs.size() << "\n"
		 << std::fixed << std::setprecision(4) << "  mean misfit: reference " << c.reference_mean_m << " m, estimate "
		 << c.estimate_mean_m << " m\n";
	printPairs(text, "estimate clearly worse", c.estimate_worse, listed);
	printPairs(text, "estimate clearly better (the reference slipped)", c.estimate_better, listed);
	os << text.str();
}

}  // namespace hslam::eval
