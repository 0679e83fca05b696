#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hslam::common
{
namespace
{
std::string joined(const std::vector<std::string>& items)
{
	std::string out;
	for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
	return out;
}

std::string formatReal(double value, int precision)
{
	std::ostringstream os;
	os.precision(precision);
	os << value;
	return os.str();
}

std::string formatReal(double value) { return formatReal(value, 10); }

/** The shortest text (at least 10 significant digits) of `shown` that the
 * reader turns back into exactly `stored` (`toStored` is the reader's
 * conversion), so a saved configuration reloads bit for bit. */
template <class TConvert>
std::string formatExactly(double shown, double stored, TConvert toStored)
{
	if (!std::isfinite(shown)) return formatReal(shown, 10);
	for (int precision = 10; precision < 17; ++precision)
	{
		const std::string text = formatReal(shown, precision);
		const auto parsed = tryParseDouble(text);
		if (parsed && toStored(*parsed) == stored) return text;
	}
	return formatReal(shown, 17);
}
}  // namespace

std::string stripInlineComment(const std::string& value)
{
	std::string out = value;
	for (size_t i = 1; i < out.size(); ++i)
	{
		const bool blankBefore = out[i - 1] == ' ' || out[i - 1] == '\t';
		if (blankBefore && (out[i] == ';' || out[i] == '#'))
		{
			out.resize(i);
			break;
		}
	}
	return trim(out);
}

CSectionReader::CSectionReader(const mrpt::config::CConfigFileBase& cfg, std::string section)
	: m_cfg(cfg), m_section(std::move(section))
{
}

std::optional<std::string> CSectionReader::rawValue(const std::string& key)
{
	m_knownKeys.insert(key);
	if (!m_cfg.keyExists(m_section, key)) return std::nullopt;
	return stripInlineComment(m_cfg.read_string(m_section, key, "", false));
}

void CSectionReader::fail(const std::string& key, const std::string& value, const std::string& why) const
{
	throw config_error("[" + m_section + "] " + key + " = '" + value + "': " + why);
}

void CSectionReader::real(const std::string& key, double& value, double minValue, double maxValue)
{
	const auto raw = rawValue(key);
	if (!raw) return;
	const auto parsed = tryParseDouble(*raw);
	if (!parsed) fail(key, *raw, "not a number");
	if (*parsed < minValue || *parsed > maxValue)
		fail(key, *raw, "out of range [" + formatReal(minValue) + ", " + formatReal(maxValue) + "]");
	value = *parsed;
}

void CSectionReader::integer(const std::string& key, int& value, int minValue, int maxValue)
{
	const auto raw = rawValue(key);
	if (!raw) return;
	const auto parsed = tryParseInteger(*raw);
	if (!parsed) fail(key, *raw, "not an integer");
	if (*parsed < minValue || *parsed > maxValue)
		fail(key, *raw, "out of range [" + std::to_string(minValue) + ", " + std::to_string(maxValue) + "]");
	value = static_cast<int>(*parsed);
}

void CSectionReader::flag(const std::string& key, bool& value)
{
	const auto raw = rawValue(key);
	if (!raw) return;
	const auto parsed = tryParseBool(*raw);
	if (!parsed) fail(key, *raw, "not a boolean (use true/false)");
	value = *parsed;
}

void CSectionReader::choice(const std::string& key, std::string& value, const std::vector<std::string>& allowed)
{
	const auto raw = rawValue(key);
	if (!raw) return;
	if (std::find(allowed.begin(), allowed.end(), *raw) == allowed.end())
		fail(key, *raw, "unknown choice; allowed: " + joined(allowed));
	value = *raw;
}

void CSectionReader::degrees(const std::string& key, double& radians, double minDeg, double maxDeg)
{
	const double shown = radians * 180.0 / M_PI;
	double deg = shown;
	real(key, deg, minDeg, maxDeg);
	// a key left out keeps the stored radians bit for bit (degrees and back
	// can move them by an ulp: 300 deg/s became 300.00000000000006)
	if (deg != shown) radians = deg * M_PI / 180.0;
}

void CSectionReader::text(const std::string& key, std::string& value)
{
	const auto raw = rawValue(key);
	if (raw) value = *raw;
}

void CSectionReader::checkNoUnknownKeys() const
{
	std::vector<std::string> keys;
	m_cfg.getAllKeys(m_section, keys);
	std::vector<std::string> unknown;
	for (const auto& key : keys)
		if (!m_knownKeys.count(key)) unknown.push_back(key);
	if (unknown.empty()) return;
	std::vector<std::string> known(m_knownKeys.begin(), m_knownKeys.end());
	throw config_error("[" + m_section + "] unknown key(s): " + joined(unknown) + " (known keys: " + joined(known) + ")");
}

CSectionWriter::CSectionWriter(mrpt::config::CConfigFileBase& cfg, std::string section)
	: m_cfg(cfg), m_section(std::move(section))
{
}

void CSectionWriter::real(const std::string& key, double& value, double, double)
{
	m_cfg.write(m_section, key, formatExactly(value, value, [](double v) { return v; }));
}
void CSectionWriter::integer(const std::string& key, int& value, int, int) { m_cfg.write(m_section, key, std::to_string(value)); }
void CSectionWriter::flag(const std::string& key, bool& value) { m_cfg.write(m_section, key, value ? "true" : "false"); }
void CSectionWriter::choice(const std::string& key, std::string& value, const std::vector<std::string>&)
{
	m_cfg.write(m_section, key, value);
}
void CSectionWriter::degrees(const std::string& key, double& radians, double, double)
{
	m_cfg.write(m_section, key,
				formatExactly(radians * 180.0 / M_PI, radians, [](double deg) { return deg * M_PI / 180.0; }));
}
void CSectionWriter::text(const std::string& key, std::string& value) { m_cfg.write(m_section, key, value); }

void checkKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& knownSections)
{
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& section : sections)
	{
		if (section.empty()) continue;
		if (std::find(knownSections.begin(), knownSections.end(), section) == knownSections.end())
			throw config_error("unknown section [" + section + "] (known sections: " + joined(knownSections) + ")");
	}
}

}  // namespace hslam::common
