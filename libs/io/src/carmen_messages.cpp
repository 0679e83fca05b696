/* hslam: helpers on CARMEN message structs. */
#include <hslam/io/carmen_messages.h>

namespace hslam::io
{
std::string carmenMessageName(const TCarmenMessage& message)
{
	struct
	{
		std::string operator()(const TCarmenLaser& m) const { return m.name; }
		std::string operator()(const TCarmenOdometry&) const { return "ODOM"; }
		std::string operator()(const TCarmenParam&) const { return "PARAM"; }
		std::string operator()(const TCarmenSkipped& m) const { return m.name; }
	} nameOf;
	return std::visit(nameOf, message);
}

}  // namespace hslam::io
