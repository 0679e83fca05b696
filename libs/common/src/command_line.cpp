#include <hslam/common/command_line.h>

#include <string>

namespace hslam::common
{
int exitCodeAfterParseStop(int argc, char** argv)
{
	for (int i = 1; i < argc; ++i)
	{
		const std::string arg = argv[i];
		if (arg == "-h" || arg == "--help" || arg == "--version") return 0;
	}
	return 1;
}
}  // namespace hslam::common
