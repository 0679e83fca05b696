/* hslam: readCarmenLog, first pass over a CARMEN log. */
#include <hslam/io/CCarmenLineParser.h>
#include <hslam/io/CGzLineReader.h>
#include <hslam/io/carmen_log.h>

namespace hslam::io
{
namespace
{
std::string located(const CGzLineReader& reader, const std::string& what)
{
	return reader.path() + ":" + std::to_string(reader.lineNumber()) + ": " + what;
}

void recordMalformed(TCarmenLog& log, const std::string& message, bool lenient)
{
	if (!lenient)
	{
		log.fatalError = message;
		return;
	}
	++log.malformedLines;
	if (log.malformedExamples.size() < kMaxMalformedExamples) log.malformedExamples.push_back(message);
}

void store(TCarmenLog& log, size_t line, TCarmenMessage&& message)
{
	const std::string name = carmenMessageName(message);
	if (const auto* skipped = std::get_if<TCarmenSkipped>(&message))
	{
		++log.skippedCounts[skipped->name];
		return;
	}
	++log.parsedCounts[name];
	if (const auto* param = std::get_if<TCarmenParam>(&message)) log.params[param->name] = {param->value, line};
	log.entries.push_back({line, std::move(message)});
}
}  // namespace

TCarmenLog readCarmenLog(const std::string& path, bool lenient)
{
	TCarmenLog log;
	log.path = path;
	CGzLineReader reader(path);
	const CCarmenLineParser parser;
	std::string line;
	while (!log.fatalError)
	{
		try
		{
			if (!reader.nextLine(line)) break;
		}
		catch (const std::runtime_error& e)  // corrupt/truncated gzip: keep what was read
		{
			recordMalformed(log, e.what(), lenient);
			break;
		}
		try
		{
			if (auto message = parser.parse(line)) store(log, reader.lineNumber(), std::move(*message));
		}
		catch (const carmen_format_error& e)
		{
			recordMalformed(log, located(reader, e.what()), lenient);
		}
	}
	return log;
}

}  // namespace hslam::io
