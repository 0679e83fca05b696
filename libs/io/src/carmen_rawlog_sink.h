/* hslam io (internal): where the CARMEN converter puts its observations - an
 * observations-only rawlog or an actions + sensory-frames rawlog. Both give an
 * odometry gap the same meaning: no odometry for that scan, never zero motion
 * and never the difference across the gap. */
#pragma once

#include <hslam/io/CCarmenOdometryTracker.h>
#include <hslam/io/CRawlogFramesWriter.h>
#include <hslam/io/CRawlogObservationWriter.h>

#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservationComment.h>

#include <memory>
#include <string>

namespace hslam::io::detail
{
class CCarmenRawlogSink
{
   public:
	virtual ~CCarmenRawlogSink() = default;
	/** A scan or a comment, in file order. */
	virtual void write(const mrpt::obs::CObservation::Ptr& observation) = 0;
	/** Odometry known before a front scan (or the first front scan). */
	virtual void odometry(const TCarmenOdometryStep& step, double t_s) = 0;
	/** Odometry missing before a front scan; `marker` is the ODOMETRY_GAP comment. */
	virtual void gap(const mrpt::obs::CObservationComment::Ptr& marker) = 0;
	/** Flushes and closes; safe to call twice. */
	virtual void close() = 0;
};

/** `format`: "observations" or "frames" (TCarmenImportOptions::format). */
std::unique_ptr<CCarmenRawlogSink> makeCarmenRawlogSink(const std::string& format, const std::string& path);

}  // namespace hslam::io::detail
