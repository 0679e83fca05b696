/* hslam: selectCarmenClock, the scan time base of a CARMEN import. */
#include <hslam/io/carmen_clock.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "text_format.h"

namespace hslam::io
{
namespace
{
using detail::formatNumber;

std::vector<double> ipcTimes(const std::vector<TCarmenStamp>& stamps)
{
	std::vector<double> t;
	for (const auto& s : stamps) t.push_back(s.ipc_s);
	return t;
}

std::vector<double> loggerTimes(const std::vector<TCarmenStamp>& stamps)
{
	std::vector<double> t;
	for (const auto& s : stamps) t.push_back(s.logger_s);
	return t;
}

std::vector<double> syntheticTimes(size_t count, double period_s)
{
	std::vector<double> t(count);
	for (size_t k = 0; k < count; ++k) t[k] = static_cast<double>(k) * period_s;
	return t;
}

std::string scanAt(size_t k, double t) { return "scan " + std::to_string(k) + " at " + formatNumber(t, 12) + " s"; }

std::string describeOk(const std::string& field, size_t count)
{
	return field + " is finite, > 0, strictly increasing and never jumps more than " +
		   formatNumber(kMaxClockJump_s) + " s over all " + std::to_string(count) + " scans";
}

TCarmenClock useTimes(const std::string& name, std::vector<double> t, const std::string& reason)
{
	return {name, reason, std::move(t)};
}

TCarmenClock forced(const std::string& name, std::vector<double> t)
{
	const auto problem = carmenClockProblem(t);
	const std::string field = name + "_timestamp";
	return useTimes(name, std::move(t),
					"forced by the clock option" + (problem ? " (warning: " + field + " " + *problem + ")" : ""));
}

std::string repairNote(size_t repaired)
{
	return repaired ? " after repairing " + std::to_string(repaired) + " small backward step(s) (t_k = t_{k-1} + 1 ms)"
					: "";
}

std::string isolatedNote(size_t repaired)
{
	return repaired ? " after replacing " + std::to_string(repaired) +
						  " isolated bad stamp(s) (not finite, <= 0 or out of order) by the midpoint of their neighbours"
					: "";
}

TCarmenClock withRepairs(TCarmenClock clock, size_t isolated)
{
	clock.repairedStamps = isolated;
	return clock;
}

TCarmenClock automatic(const std::vector<TCarmenStamp>& stamps, double period_s)
{
	auto ipc = ipcTimes(stamps);
	const size_t ipcIsolated = repairIsolatedBadStamps(ipc);
	const size_t ipcRepaired = repairSmallBackwardSteps(ipc);
	const auto ipcProblem = carmenClockProblem(ipc);
	if (!ipcProblem)
		return withRepairs(useTimes("ipc", std::move(ipc),
									describeOk("ipc_timestamp", stamps.size()) + isolatedNote(ipcIsolated) + repairNote(ipcRepaired)),
						   ipcIsolated);
	auto logger = loggerTimes(stamps);
	const size_t loggerIsolated = repairIsolatedBadStamps(logger);
	const size_t loggerRepaired = repairSmallBackwardSteps(logger);
	const auto loggerProblem = carmenClockProblem(logger);
	const std::string ipcRejected = "ipc_timestamp rejected: " + *ipcProblem;
	if (!loggerProblem)
		return withRepairs(useTimes("logger", std::move(logger),
									ipcRejected + "; " + describeOk("logger_timestamp", stamps.size()) +
										isolatedNote(loggerIsolated) + repairNote(loggerRepaired)),
						   loggerIsolated);
	return useTimes("synthetic", syntheticTimes(stamps.size(), period_s),
					ipcRejected + "; logger_timestamp rejected: " + *loggerProblem + "; using t_k = k * " +
						formatNumber(period_s) + " s from 0");
}
}  // namespace

size_t repairIsolatedBadStamps(std::vector<double>& t_s)
{
	const size_t n = t_s.size();
	if (n < 3) return 0;
	const auto good = [](double t) { return std::isfinite(t) && t > 0; };
	std::vector<double> steps;
	for (size_t k = 1; k < n; ++k)
		if (good(t_s[k]) && good(t_s[k - 1]) && t_s[k] > t_s[k - 1]) steps.push_back(t_s[k] - t_s[k - 1]);
	if (steps.empty()) return 0;
	std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
	const double medianStep_s = steps[steps.size() / 2];
	std::vector<std::pair<size_t, double>> fixes;
	for (size_t k = 0; k < n; ++k)
	{
		const bool hasPrev = k > 0 && good(t_s[k - 1]), hasNext = k + 1 < n && good(t_s[k + 1]);
		if (k > 0 && k + 1 < n)
		{
			if (!hasPrev || !hasNext || !(t_s[k + 1] > t_s[k - 1])) continue;  // not isolated
			if (good(t_s[k]) && t_s[k] > t_s[k - 1] && t_s[k] < t_s[k + 1]) continue;  // fine
			fixes.emplace_back(k, 0.5 * (t_s[k - 1] + t_s[k + 1]));
		}
		else if (!good(t_s[k]) || (k == 0 && hasNext && !(t_s[0] < t_s[1])) || (k + 1 == n && hasPrev && !(t_s[k] > t_s[k - 1])))
		{
			if (k == 0 && hasNext) fixes.emplace_back(k, t_s[1] - medianStep_s);
			if (k + 1 == n && hasPrev) fixes.emplace_back(k, t_s[k - 1] + medianStep_s);
		}
	}
	if (fixes.empty() || fixes.size() > std::max<size_t>(1, n / 100)) return 0;
	for (const auto& [k, t] : fixes) t_s[k] = t;
	return fixes.size();
}

size_t repairSmallBackwardSteps(std::vector<double>& t_s)
{
	constexpr double kRepairStep_s = 1e-3;
	size_t bad = 0;
	for (size_t k = 1; k < t_s.size(); ++k)
	{
		if (!std::isfinite(t_s[k]) || !std::isfinite(t_s[k - 1])) return 0;
		if (t_s[k] > t_s[k - 1]) continue;
		if (t_s[k - 1] - t_s[k] > kMaxRepairableBackStep_s) return 0;
		++bad;
	}
	if (bad == 0 || bad > std::max<size_t>(1, t_s.size() / 100)) return 0;
	for (size_t k = 1; k < t_s.size(); ++k) t_s[k] = std::max(t_s[k], t_s[k - 1] + kRepairStep_s);
	return bad;
}

std::optional<std::string> carmenClockProblem(const std::vector<double>& t_s)
{
	for (size_t k = 0; k < t_s.size(); ++k)
	{
		if (!std::isfinite(t_s[k]) || t_s[k] <= 0) return "not finite and > 0 (" + scanAt(k, t_s[k]) + ")";
		if (k == 0) continue;
		const double step_s = t_s[k] - t_s[k - 1];
		if (!(step_s > 0))
			return "not strictly increasing (" + scanAt(k, t_s[k]) + " after " + scanAt(k - 1, t_s[k - 1]) + ")";
		if (step_s > kMaxClockJump_s)
			return "jumps " + formatNumber(step_s) + " s (" + scanAt(k, t_s[k]) + " after " + scanAt(k - 1, t_s[k - 1]) +
				   ")";
	}
	return std::nullopt;
}

TCarmenClock selectCarmenClock(const std::vector<TCarmenStamp>& scanStamps, const std::string& mode,
							   double syntheticPeriod_s)
{
	if (!(syntheticPeriod_s > 0)) throw std::invalid_argument("synthetic clock period must be > 0");
	if (mode == "auto") return automatic(scanStamps, syntheticPeriod_s);
	if (mode == "ipc") return forced("ipc", ipcTimes(scanStamps));
	if (mode == "logger") return forced("logger", loggerTimes(scanStamps));
	if (mode == "synthetic")
		return useTimes("synthetic", syntheticTimes(scanStamps.size(), syntheticPeriod_s),
						"forced by the clock option: t_k = k * " + formatNumber(syntheticPeriod_s) + " s from 0");
	throw std::invalid_argument("unknown clock '" + mode + "' (use auto, ipc, logger or synthetic)");
}

}  // namespace hslam::io
