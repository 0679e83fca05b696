#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace hslam::common
{
namespace
{
/** One logical line: physical lines joined where one ends in a backslash
 * (as MRPT joins them), numbered by its first physical line. */
struct TLogicalLine
{
	size_t number = 0;
	std::string text;  //!< joined, without the backslashes
	std::string raw;  //!< the physical lines as in the file, '\n'-separated
	size_t physical_lines = 0;
};

std::string lowered(std::string s)
{
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
	return s;
}

std::string where(const std::string& name, size_t line) { return name + ":" + std::to_string(line) + ": "; }

/** A binary file (NUL or other control bytes) is not an INI file. */
void checkTextBytes(const std::string& text, const std::string& name)
{
	size_t line = 1, column = 1;
	for (const unsigned char c : text)
	{
		if (c == '\n')
		{
			++line, column = 1;
			continue;
		}
		if ((c < 0x20 && c != '\t' && c != '\r' && c != '\f') || c == 0x7f)
		{
			char hex[8];
			std::snprintf(hex, sizeof(hex), "0x%02x", c);
			throw config_error(where(name, line) + "not an INI text file (control byte " + hex + " at column " +
							   std::to_string(column) + ")");
		}
		++column;
	}
}

std::vector<TLogicalLine> logicalLines(const std::string& text)
{
	std::vector<TLogicalLine> lines;
	std::istringstream in(text);
	std::string physical;
	size_t number = 0;
	bool continues = false;
	while (std::getline(in, physical))
	{
		++number;
		if (!continues) lines.push_back({number, "", "", 0});
		auto& line = lines.back();
		line.raw += (line.physical_lines++ ? "\n" : "") + physical;
		if (!physical.empty() && physical.back() == '\r') physical.pop_back();
		continues = !physical.empty() && physical.back() == '\\';
		line.text += continues ? physical.substr(0, physical.size() - 1) : physical;
	}
	return lines;
}

bool isComment(const std::string& trimmed)
{
	return trimmed.empty() || trimmed[0] == ';' || trimmed[0] == '#' || trimmed.rfind("//", 0) == 0;
}

/** Checks the structure line by line; remembers where each section and key
 * was first seen to report repetitions. */
class CIniStructureCheck
{
   public:
	explicit CIniStructureCheck(std::string name) : m_name(std::move(name)) {}

	/** False for a comment (to be blanked out), true for content. */
	bool check(const TLogicalLine& line)
	{
		const std::string t = trim(line.text);
		if (isComment(t)) return false;
		if (t.rfind("@define", 0) == 0) return true;  // MRPT variable definition
		if (t[0] == '[')
			section(t, line.number);
		else
			key(t, line.number);
		return true;
	}

   private:
	void section(const std::string& t, size_t number)
	{
		const auto close = t.find(']');
		if (close == std::string::npos) fail(number, "section header '" + t + "' has no closing ']'");
		const std::string name = trim(t.substr(1, close - 1));
		if (name.empty()) fail(number, "empty section name '" + t + "'");
		if (!isComment(trim(t.substr(close + 1)))) fail(number, "text after the section header '" + t + "'");
		const auto [it, isNew] = m_sections.emplace(lowered(name), number);
		if (!isNew)
			fail(number, "section [" + name + "] appears again (first at line " + std::to_string(it->second) +
							 "); merge the two into one");
		m_section = name;
	}

	void key(const std::string& t, size_t number)
	{
		const auto eq = t.find('=');
		if (eq == std::string::npos)
			fail(number, "'" + t + "' is neither '[section]' nor 'key = value' nor a comment (; # //)");
		const std::string name = trim(t.substr(0, eq));
		if (name.empty()) fail(number, "'" + t + "' has no key before '='");
		if (m_section.empty()) fail(number, "key '" + name + "' comes before any [section]");
		const auto [it, isNew] = m_keys.emplace(lowered(m_section) + "\n" + lowered(name), number);
		if (!isNew)
			fail(number, "key '" + name + "' appears again in [" + m_section + "] (first at line " +
							 std::to_string(it->second) + ")");
	}

	[[noreturn]] void fail(size_t number, const std::string& why) const { throw config_error(where(m_name, number) + why); }

	std::string m_name, m_section;
	std::map<std::string, size_t> m_sections, m_keys;  //!< lower-case name -> first line
};
}  // namespace

mrpt::config::CConfigFileMemory parseIniText(const std::string& text, const std::string& name)
{
	std::string body = text;
	if (body.rfind("\xEF\xBB\xBF", 0) == 0) body.erase(0, 3);  // UTF-8 byte order mark
	checkTextBytes(body, name);
	CIniStructureCheck check(name);
	std::string cleaned;  // comments blanked (MRPT would read "// a = b" as key "// a"), line numbers kept
	for (const auto& line : logicalLines(body))
		cleaned += check.check(line) ? line.raw + "\n" : std::string(line.physical_lines, '\n');
	mrpt::config::CConfigFileMemory cfg;
	try
	{
		cfg.setContent(cleaned);  // MRPT expands @define, ${...}, $eval{...} here
	}
	catch (const std::exception& e)
	{
		throw config_error(name + ": " + e.what());
	}
	return cfg;
}

mrpt::config::CConfigFileMemory loadIniFile(const std::string& path)
{
	if (std::filesystem::is_directory(path)) throw config_error(path + ": is a folder, not an INI file");
	std::ifstream in(path, std::ios::binary);
	if (!in) throw config_error(path + ": cannot open configuration file");
	std::stringstream contents;
	contents << in.rdbuf();
	if (in.bad()) throw config_error(path + ": read error");
	return parseIniText(contents.str(), path);
}

void checkKnownSectionsInFile(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& knownSections,
							  const std::string& iniFile)
{
	try
	{
		checkKnownSections(cfg, knownSections);
	}
	catch (const config_error& e)
	{
		std::ifstream in(iniFile, std::ios::binary);
		std::stringstream contents;
		contents << in.rdbuf();
		std::vector<std::string> sections;
		cfg.getAllSections(sections);
		for (const auto& line : logicalLines(contents.str()))
		{
			const std::string t = trim(line.text);
			const auto close = t.find(']');
			if (t.empty() || t[0] != '[' || close == std::string::npos) continue;
			const std::string name = trim(t.substr(1, close - 1));
			if (std::find(knownSections.begin(), knownSections.end(), name) == knownSections.end())
				throw config_error(where(iniFile, line.number) + e.what());
		}
		throw;  // the unknown section came from an override
	}
}

}  // namespace hslam::common
