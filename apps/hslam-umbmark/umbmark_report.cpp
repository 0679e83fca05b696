/* hslam-umbmark: report and INI output (see umbmark_report.h). */
#include "umbmark_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hslam::apps
{
namespace
{
std::string fmt(const char* format, double v)
{
	char text[64];
	std::snprintf(text, sizeof(text), format, v);
	return text;
}
}  // namespace

void printUmbmark(std::ostream& out, const std::vector<calib::TUmbmarkEndpoint>& runs,
				  const calib::TUmbmarkResult& r, const calib::TUmbmarkOptions& o)
{
	out << "UMBmark (thesis 4.1; Borenstein & Feng 1996): L = " << fmt("%.3f", o.side_length_m)
		<< " m, nominal wheelbase b = " << fmt("%.4f", o.nominal_wheelbase_m) << " m\n";
	out << "end-point errors (true - odometry, m; +x along the first leg):\n";
	for (const auto& e : runs)
		out << "  " << (e.clockwise ? "CW " : "CCW") << "  x " << fmt("%+8.4f", e.err_x_m) << "  y "
			<< fmt("%+8.4f", e.err_y_m) << "   " << e.label << "\n";
	out << "centre of gravity CW  (eq. 21-22): x " << fmt("%+.4f", r.cw.x_m) << " m, y " << fmt("%+.4f", r.cw.y_m)
		<< " m, r_cw = " << fmt("%.4f", r.cw.r_m) << " m (" << r.cw.runs << " runs)\n";
	out << "centre of gravity CCW (eq. 21-22): x " << fmt("%+.4f", r.ccw.x_m) << " m, y " << fmt("%+.4f", r.ccw.y_m)
		<< " m, r_ccw = " << fmt("%.4f", r.ccw.r_m) << " m (" << r.ccw.runs << " runs)\n";
	out << "alpha (eq. 23) = " << fmt("%+.4f", r.alpha_first_order_rad * 180 / M_PI) << " deg first order, "
		<< fmt("%+.4f", r.alpha_rad * 180 / M_PI) << " deg exact square model\n";
	out << "beta  (eq. 24) = " << fmt("%+.4f", r.beta_first_order_rad * 180 / M_PI) << " deg first order, "
		<< fmt("%+.4f", r.beta_rad * 180 / M_PI) << " deg exact square model\n";
	out << "R     (eq. 26) = " << fmt("%.1f", r.radius_m) << " m\n";
	out << "corrected wheelbase = Eb b = " << fmt("%.5f", r.corrected_wheelbase_m) << " m\n";
	out << "encoder factors (eq. 28): c_L = " << fmt("%.6f", r.left_factor) << ", c_R = " << fmt("%.6f", r.right_factor)
		<< "\n";
	out << "E_max,syst = max(r_cw, r_ccw) = " << fmt("%.4f", r.e_max_syst_m) << " m\n";
	out << "Ed=" << fmt("%.6f", r.ed) << "\n";
	out << "Eb=" << fmt("%.6f", r.eb) << "\n";
}

void writeCorrectionIni(const std::string& path, const calib::TUmbmarkResult& r, const calib::TUmbmarkOptions& o,
						const std::string& source)
{
	if (std::filesystem::exists(path)) throw std::runtime_error(path + ": exists; not overwritten (choose a new file)");
	std::ofstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot be written");
	f << "; UMBmark odometry calibration (thesis 4.1, eq. 25-28), written by hslam-umbmark from\n; " << source << "\n"
	  << "; Ed = " << fmt("%.6f", r.ed) << ", Eb = " << fmt("%.6f", r.eb)
	  << ", E_max,syst before = " << fmt("%.4f", r.e_max_syst_m) << " m.\n"
	  << "; Append to a simulator INI (hslam-simulate) or an hslam-process INI; the same keys\n"
	  << "; also go into a Pioneer sensor's section of a grabber INI.\n"
	  << "[odometry_correction]\n"
	  << "; Apply the correction to the odometry (true/false).\n"
	  << "correct_odometry = true\n"
	  << "; c_L = 2 / (Ed + 1): factor on the left wheel's travel (eq. 28). Range [0.9, 1.1].\n"
	  << "odometry_left_factor = " << fmt("%.8f", r.left_factor) << "\n"
	  << "; c_R = 2 / (1/Ed + 1): factor on the right wheel's travel (eq. 28). Range [0.9, 1.1].\n"
	  << "odometry_right_factor = " << fmt("%.8f", r.right_factor) << "\n"
	  << "; Eb = actual / nominal wheelbase = 90 / (90 - alpha_deg) (eq. 25). Range [0.9, 1.1].\n"
	  << "odometry_wheelbase_ratio = " << fmt("%.8f", r.eb) << "\n"
	  << "; Nominal wheelbase b (m) the odometry integrates with. Range [0.05, 5].\n"
	  << "odometry_nominal_wheelbase_m = " << fmt("%.4f", o.nominal_wheelbase_m) << "\n";
	if (!f) throw std::runtime_error(path + ": write failed");
}

}  // namespace hslam::apps
