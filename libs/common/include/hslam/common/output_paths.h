/* hslam: guards for the paths an app writes (issue 15, items 5 and 6).
 *
 * - refuseOutputOverInput(): an output path that resolves to an input (same
 *   file, through symlinks, "./", hard links) is refused before anything is
 *   opened for writing, so a slip like `hslam-carmen2rawlog IN IN` or
 *   `hslam-evaluate --json EST` cannot destroy the input.
 * - printableName(): a file name or label from input data with control
 *   characters (terminal escape codes) replaced by '?', for messages. */
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace hslam::common
{
class output_path_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** Throws output_path_error ("<what> 'OUT' is the input 'IN'") if `output`
 * names the same file as one of `inputs`. */
void refuseOutputOverInput(const std::string& output, const std::string& what, const std::vector<std::string>& inputs);

/** Throws output_path_error if two outputs name the same file. */
void refuseSameOutputs(const std::string& a, const std::string& b);

/** `text` with every control character (< 0x20, 0x7f) replaced by '?'. */
std::string printableName(const std::string& text);

}  // namespace hslam::common
