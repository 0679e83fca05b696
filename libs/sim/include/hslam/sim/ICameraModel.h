/* hslam sim: seam for a camera model (the camera issue implements it).
 * A camera model renders an observation (e.g. an mrpt::obs::CObservationImage)
 * of the world from the robot's true pose; CSimulator calls it at its rate
 * and hands the observation to the sink like the other sensors. */
#pragma once

#include <hslam/sim/world.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation.h>

#include <random>

namespace hslam::sim
{
class ICameraModel
{
   public:
	virtual ~ICameraModel() = default;
	/** Frames per second. */
	virtual double rate_hz() const = 0;
	/** Renders one observation (timestamp set by the caller); may return nullptr. */
	virtual mrpt::obs::CObservation::Ptr render(const CWorld& world, const mrpt::math::TPose2D& robotTruePose,
												std::mt19937_64& rng) const = 0;
};

}  // namespace hslam::sim
