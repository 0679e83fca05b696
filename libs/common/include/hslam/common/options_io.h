/* hslam: loading, checking and saving option structs from MRPT INI files.
 *
 * Every option struct (TOptions) describes its fields once, in a template
 * member `visit(V& v)` that calls, per field:
 *
 *     v.real("max_range_m", max_range_m, 0.0, 80.0);
 *     v.integer("tile_size_cells", tile_size_cells, 10, 5000);
 *     v.flag("insert_free_beyond_range", insert_free_beyond_range);
 *     v.choice("method", method, {"odometry"});
 *     v.degrees("cone_deg", cone_rad, 1.0, 90.0);   // INI in deg, memory rad
 *     v.text("label", label);
 *
 * The same description then serves loading (with range checks and a clear
 * error naming [section] and key), saving and unknown-key detection, so load
 * and save can never disagree. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hslam::common
{
/** Thrown for any bad configuration value; the message names section/key. */
class config_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** Visitor that reads fields from one INI section, keeping defaults for
 * absent keys and throwing config_error for malformed or out-of-range values. */
class CSectionReader
{
   public:
	CSectionReader(const mrpt::config::CConfigFileBase& cfg, std::string section);

	void real(const std::string& key, double& value, double minValue, double maxValue);
	void integer(const std::string& key, int& value, int minValue, int maxValue);
	void flag(const std::string& key, bool& value);
	void choice(const std::string& key, std::string& value, const std::vector<std::string>& allowed);
	void degrees(const std::string& key, double& radians, double minDeg, double maxDeg);
	void text(const std::string& key, std::string& value);

	/** Throws config_error listing the keys of the section that no field read. */
	void checkNoUnknownKeys() const;

   private:
	/** Raw value of key without inline comment, or nullopt if absent. */
	std::optional<std::string> rawValue(const std::string& key);
	[[noreturn]] void fail(const std::string& key, const std::string& value, const std::string& why) const;

	const mrpt::config::CConfigFileBase& m_cfg;
	std::string m_section;
	std::set<std::string> m_knownKeys;
};

/** Visitor that writes fields into one INI section (the inverse of the reader). */
class CSectionWriter
{
   public:
	CSectionWriter(mrpt::config::CConfigFileBase& cfg, std::string section);

	void real(const std::string& key, double& value, double, double);
	void integer(const std::string& key, int& value, int, int);
	void flag(const std::string& key, bool& value);
	void choice(const std::string& key, std::string& value, const std::vector<std::string>&);
	void degrees(const std::string& key, double& radians, double, double);
	void text(const std::string& key, std::string& value);

   private:
	mrpt::config::CConfigFileBase& m_cfg;
	std::string m_section;
};

/** Loads `options` from `section` (absent keys keep their defaults) and
 * rejects keys the options do not know. */
template <class TOptionsType>
void loadOptions(TOptionsType& options, const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	CSectionReader reader(cfg, section);
	options.visit(reader);
	reader.checkNoUnknownKeys();
}

/** Writes every field of `options` into `section`. */
/** A default-constructed option struct loaded from `section` (for member
 * initialiser lists). */
template <class TOptionsType>
TOptionsType loadedOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	TOptionsType options;
	loadOptions(options, cfg, section);
	return options;
}

template <class TOptionsType>
void saveOptions(const TOptionsType& options, mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	TOptionsType copy = options;  // visit() takes non-const references
	CSectionWriter writer(cfg, section);
	copy.visit(writer);
}

/** Throws config_error if the file has a section not in `knownSections`. */
void checkKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& knownSections);

/** Strips an inline comment (" ; ...", " # ...") and blanks from an INI value.
 * MRPT itself only strips "//" comments. */
std::string stripInlineComment(const std::string& value);

}  // namespace hslam::common
