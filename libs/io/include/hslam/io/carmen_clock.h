/* hslam: choice of the time base for the scans of a CARMEN log.
 *
 * Measured on 13 real CARMEN logs: the scan timestamps are unusable in some
 * of them - all equal because they were printed with too few digits (csail:
 * ipc_timestamp written as 1.13486e+09), all zero, jumping to ~4.29e9, or
 * going backwards (intel: 4 times, by up to 0.86 s). So a clock is only used
 * if, over all scans in file order, it is finite, > 0, strictly increasing and
 * never jumps more than kMaxClockJump_s between consecutive scans. "auto"
 * tries ipc_timestamp, then logger_timestamp, then a synthetic clock
 * t_k = k * period (k = 0, 1, ... over all scans in file order). */
#pragma once

#include <hslam/io/carmen_messages.h>

#include <optional>
#include <string>
#include <vector>

namespace hslam::io
{
/** Largest step between consecutive scans still taken as a real clock (1 h:
 * longer pauses inside one log are not plausible; ~4.29e9 jumps are). */
constexpr double kMaxClockJump_s = 3600.0;

struct TCarmenClock
{
	std::string name;  //!< "ipc", "logger" or "synthetic"
	std::string reason;  //!< why this clock was used (and why others were not)
	std::vector<double> t_s;  //!< one timestamp per scan, in file order
	size_t repairedStamps = 0;  //!< isolated bad stamps replaced by interpolation (warned about)
};

/** Largest backward step (s) that an otherwise usable timestamp stream may
 * have and still be repaired instead of rejected. intel-corrected has four
 * such steps (0.11 to 0.86 s) among 910 scans; rejecting its whole clock for
 * them would throw away true timestamps. */
constexpr double kMaxRepairableBackStep_s = 1.0;

/** Repairs a few small backward (or repeated) timestamps in place with
 * t_k = t_{k-1} + 1 ms, when there are at most max(1, 1 %) of them and none
 * goes back more than kMaxRepairableBackStep_s; returns how many were changed
 * (0 and no change otherwise: the stream is then judged as it is). */
size_t repairSmallBackwardSteps(std::vector<double>& t_s);

/** Repairs isolated bad stamps in place (issue 15 item 2): a stamp that is
 * not finite, <= 0, or out of order between two neighbours that are in order
 * (a single 1e308 or -1 among good stamps) is replaced by the midpoint of its
 * neighbours (at either end: the neighbour -/+ the median step). At most
 * max(1, 1 %) of the stamps, else nothing changes (the clock is then judged
 * and rejected as a whole); returns how many were changed. */
size_t repairIsolatedBadStamps(std::vector<double>& t_s);

/** nullopt if `t_s` passes the test above, else a short explanation. */
std::optional<std::string> carmenClockProblem(const std::vector<double>& t_s);

/** Picks the clock for `scanStamps` (all scans in file order). `mode` is
 * "auto", "ipc", "logger" or "synthetic"; a forced clock is used even if it
 * fails the test (the reason then says so). Throws std::invalid_argument for
 * an unknown mode or a non-positive period. */
TCarmenClock selectCarmenClock(const std::vector<TCarmenStamp>& scanStamps, const std::string& mode,
							   double syntheticPeriod_s);

}  // namespace hslam::io
