/* hslam: strict parser of one CARMEN log line into a message struct
 * (formats in carmen_messages.h). Every number must be a complete number
 * token and the declared beam / remission counts must match the number of
 * values exactly; anything else is a carmen_format_error. */
#pragma once

#include <hslam/io/carmen_messages.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace hslam::io
{
/** A malformed line; what() says what is wrong (the caller adds "file:line:"). */
class carmen_format_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

class CCarmenLineParser
{
   public:
	/** Parses one line; nullopt for a blank line. Unknown message names and
	 * '#' comments become TCarmenSkipped. Throws carmen_format_error. */
	std::optional<TCarmenMessage> parse(const std::string& line) const;
};

}  // namespace hslam::io
