/* hslam: CCarmenLineParser, strict CARMEN line parsing. */
#include <hslam/common/parse_number.h>
#include <hslam/io/CCarmenLineParser.h>

#include <cstdlib>
#include <sstream>
#include <string_view>

namespace hslam::io
{
namespace
{
// Sanity cap on a declared beam/remission count, so that a corrupt count
// cannot make us reserve gigabytes; real scanners give at most a few thousand.
constexpr long long kMaxValuesPerMessage = 100000;

// Fields after the ranges: FLASER "x y theta odom_x odom_y odom_theta ipc host logger".
constexpr size_t kFlaserTrailingFields = 9;
// ROBOTLASER after the remissions: 6 pose + 5 (tv rv fwd side turn) + 3 stamp fields.
constexpr size_t kRobotLaserTrailingFields = 14;
// RAWLASER after the remissions: "ipc host logger".
constexpr size_t kStampFields = 3;
// ODOM after the name: "x y theta tv rv accel ipc host logger".
constexpr size_t kOdomFields = 9;

std::vector<std::string> splitTokens(const std::string& line)
{
	std::istringstream in(line);
	std::vector<std::string> tokens;
	for (std::string token; in >> token;) tokens.push_back(token);
	return tokens;
}

/** Walks over the tokens of one line, converting them strictly. */
class CTokenCursor
{
   public:
	explicit CTokenCursor(std::vector<std::string> tokens) : m_tokens(std::move(tokens)) {}

	size_t remaining() const { return m_tokens.size() - m_next; }

	/** Requires exactly `expected` more fields; `context` explains why. */
	void expectExactly(size_t expected, const std::string& context) const
	{
		if (remaining() < expected)
			throw carmen_format_error(
				"truncated line: " + context + " needs " + std::to_string(expected) + " more fields, found " +
				std::to_string(remaining()));
		if (remaining() > expected)
			throw carmen_format_error(
				context + ": " + std::to_string(remaining() - expected) + " unexpected extra field(s) at the end");
	}

	void expectAtLeast(size_t expected, const std::string& context) const
	{
		if (remaining() < expected)
			throw carmen_format_error(
				"truncated line: " + context + " needs at least " + std::to_string(expected) +
				" more fields, found " + std::to_string(remaining()));
	}

	const std::string& word(const std::string& field)
	{
		expectAtLeast(1, field);
		return m_tokens[m_next++];
	}

	double real(const std::string& field)
	{
		const std::string& token = word(field);
		const auto value = hslam::common::tryParseDouble(token);
		if (!value) throw carmen_format_error("bad number '" + token + "' for " + field);
		return *value;
	}

	/** Like real() but also accepts nan/inf: unusable clocks are judged later
	 * (carmen_clock.h), not rejected as malformed lines. */
	double timestamp(const std::string& field)
	{
		const std::string& token = word(field);
		char* end = nullptr;
		const double value = std::strtod(token.c_str(), &end);
		if (token.empty() || end != token.c_str() + token.size())
			throw carmen_format_error("bad timestamp '" + token + "' for " + field);
		return value;
	}

	size_t count(const std::string& field)
	{
		const std::string& token = word(field);
		const auto value = hslam::common::tryParseInteger(token);
		if (!value || *value < 0 || *value > kMaxValuesPerMessage)
			throw carmen_format_error("bad count '" + token + "' for " + field);
		return static_cast<size_t>(*value);
	}

	std::vector<double> reals(size_t n, const std::string& field)
	{
		std::vector<double> out(n);
		for (size_t i = 0; i < n; ++i) out[i] = real(field + " " + std::to_string(i + 1));
		return out;
	}

	mrpt::math::TPose2D pose(const std::string& field)
	{
		const double x = real(field + " x"), y = real(field + " y"), phi = real(field + " theta");
		return {x, y, phi};
	}

	TCarmenStamp stamp()
	{
		TCarmenStamp s;
		s.ipc_s = timestamp("ipc_timestamp");
		s.host = word("hostname");
		s.logger_s = timestamp("logger_timestamp");
		return s;
	}

	std::string joinRest(size_t dropLast) const
	{
		std::string out;
		for (size_t i = m_next; i + dropLast < m_tokens.size(); ++i) out += (out.empty() ? "" : " ") + m_tokens[i];
		return out;
	}
	const std::string& peekFromEnd(size_t back) const { return m_tokens[m_tokens.size() - 1 - back]; }

   private:
	std::vector<std::string> m_tokens;
	size_t m_next = 1;  // token 0 is the message name
};

std::string beamContext(const std::string& name, size_t n)
{
	return name + " declaring " + std::to_string(n) + " beams";
}

TCarmenLaser parseOldLaser(CTokenCursor& c, const std::string& name, TCarmenLaserRole role)
{
	TCarmenLaser laser;
	laser.name = name;
	laser.role = role;
	const size_t n = c.count("beam count");
	c.expectExactly(n + kFlaserTrailingFields, beamContext(name, n) + " (beam count or line length wrong)");
	laser.ranges_m = c.reals(n, "range");
	laser.laserPose = c.pose("laser pose");
	laser.robotPose = c.pose("odometry pose");
	laser.stamp = c.stamp();
	return laser;
}

TCarmenLaserConfig parseLaserConfig(CTokenCursor& c)
{
	c.word("laser_type");
	TCarmenLaserConfig cfg;
	cfg.startAngle_rad = c.real("start_angle");
	cfg.fov_rad = c.real("fov");
	cfg.resolution_rad = c.real("angular_resolution");
	cfg.maxRange_m = c.real("max_range");
	c.real("accuracy");
	c.word("remission_mode");
	return cfg;
}

/** Ranges and remissions of ROBOTLASER/RAWLASER; checks the trailing field count. */
std::vector<double> parseRangesAndRemissions(CTokenCursor& c, const std::string& name, size_t trailingFields)
{
	const size_t n = c.count("beam count");
	c.expectAtLeast(n + 1 + trailingFields, beamContext(name, n));
	std::vector<double> ranges = c.reals(n, "range");
	const size_t m = c.count("remission count");
	c.expectExactly(m + trailingFields, beamContext(name, n) + " and " + std::to_string(m) +
											" remissions (counts or line length wrong)");
	c.reals(m, "remission");
	return ranges;
}

TCarmenLaser parseRobotLaser(CTokenCursor& c, const std::string& name, TCarmenLaserRole role)
{
	TCarmenLaser laser;
	laser.name = name;
	laser.role = role;
	laser.config = parseLaserConfig(c);
	laser.ranges_m = parseRangesAndRemissions(c, name, kRobotLaserTrailingFields);
	laser.laserPose = c.pose("laser pose");
	laser.robotPose = c.pose("robot pose");
	laser.tv_mps = c.real("tv");
	laser.rv_radps = c.real("rv");
	c.real("forward_safety_dist");
	c.real("side_safety_dist");
	c.real("turn_axis");
	laser.stamp = c.stamp();
	return laser;
}

TCarmenLaser parseRawLaser(CTokenCursor& c, const std::string& name, int index)
{
	TCarmenLaser laser;
	laser.name = name;
	laser.role = TCarmenLaserRole::lrRaw;
	laser.rawIndex = index;
	laser.config = parseLaserConfig(c);
	laser.ranges_m = parseRangesAndRemissions(c, name, kStampFields);
	laser.stamp = c.stamp();
	return laser;
}

TCarmenOdometry parseOdometry(CTokenCursor& c)
{
	c.expectExactly(kOdomFields, "ODOM");
	TCarmenOdometry odo;
	odo.pose = c.pose("odometry");
	odo.tv_mps = c.real("tv");
	odo.rv_radps = c.real("rv");
	odo.accel_mps2 = c.real("accel");
	odo.stamp = c.stamp();
	return odo;
}

bool isNumber(const std::string& token) { return hslam::common::tryParseDouble(token).has_value(); }

/** How many trailing stamp fields a PARAM line has after its value:
 * 3 ("ipc_ts host logger_ts", e.g. csail), 2 ("host ts", e.g. intel:
 * "PARAM robot_frontlaser_offset 0.0 nohost 0") or 0. */
size_t paramStampFields(const CTokenCursor& c)
{
	const size_t n = c.remaining();  // value field(s) + stamp fields
	if (n >= 4 && isNumber(c.peekFromEnd(0)) && !isNumber(c.peekFromEnd(1)) && isNumber(c.peekFromEnd(2)))
		return kStampFields;
	if (n == 3 && isNumber(c.peekFromEnd(0)) && !isNumber(c.peekFromEnd(1))) return 2;
	return 0;
}

/** "PARAM name value [ipc_ts host logger_ts | host ts]"; a value may contain blanks. */
TCarmenParam parseParam(CTokenCursor& c)
{
	c.expectAtLeast(2, "PARAM");
	TCarmenParam p;
	p.name = c.word("parameter name");
	p.value = c.joinRest(paramStampFields(c));
	return p;
}

std::optional<int> rawLaserIndex(const std::string& name)
{
	const std::string prefix = "RAWLASER";
	if (name.size() != prefix.size() + 1 || name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
	const char digit = name.back();
	if (digit < '1' || digit > '4') return std::nullopt;
	return digit - '0';
}
}  // namespace

std::optional<TCarmenMessage> CCarmenLineParser::parse(const std::string& line) const
{
	std::vector<std::string> tokens = splitTokens(line);
	if (tokens.empty()) return std::nullopt;
	const std::string name = tokens[0];
	if (name[0] == '#') return TCarmenSkipped{"#"};
	CTokenCursor c(std::move(tokens));
	if (name == "FLASER") return parseOldLaser(c, name, TCarmenLaserRole::lrFront);
	if (name == "RLASER") return parseOldLaser(c, name, TCarmenLaserRole::lrRear);
	if (name == "ROBOTLASER1") return parseRobotLaser(c, name, TCarmenLaserRole::lrFront);
	if (name == "ROBOTLASER2") return parseRobotLaser(c, name, TCarmenLaserRole::lrRear);
	if (const auto index = rawLaserIndex(name)) return parseRawLaser(c, name, *index);
	if (name == "ODOM") return parseOdometry(c);
	if (name == "PARAM") return parseParam(c);
	return TCarmenSkipped{name};
}

}  // namespace hslam::io
