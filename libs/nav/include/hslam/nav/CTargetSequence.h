/* hslam nav: an ordered list of targets (x, y in m, world frame) visited in
 * turn; the controller advances when the current one is reached. */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <optional>
#include <string>
#include <vector>

namespace hslam::nav
{
class CTargetSequence
{
   public:
	CTargetSequence() = default;
	explicit CTargetSequence(std::vector<mrpt::math::TPoint2D> targets) : m_targets(std::move(targets)) {}

	std::optional<mrpt::math::TPoint2D> current() const
	{
		if (m_next >= m_targets.size()) return std::nullopt;
		return m_targets[m_next];
	}
	void advance() { ++m_next; }
	bool finished() const { return m_next >= m_targets.size(); }
	size_t reachedCount() const { return m_next; }
	const std::vector<mrpt::math::TPoint2D>& targets() const { return m_targets; }

   private:
	std::vector<mrpt::math::TPoint2D> m_targets;
	size_t m_next = 0;
};

/** Parses "x y; x y; ..." (m); throws std::runtime_error naming `what` on bad input. */
std::vector<mrpt::math::TPoint2D> parseTargetList(const std::string& text, const std::string& what);

}  // namespace hslam::nav
