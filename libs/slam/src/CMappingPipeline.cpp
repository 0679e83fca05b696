#include <hslam/common/options_io.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/slam/CLocalMapPoseEstimator.h>
#include <hslam/slam/CScanMatchingPoseEstimator.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/system/datetime.h>

namespace hslam::slam
{
namespace
{
/** [laser_model]: the grid inserter's keys with the pipeline's default range,
 * 8 m (chosen by map quality, config_ini/hslam-default.ini; the library keeps
 * the thesis's 3 m), so a key left out means the shipped default. */
maps::CLaserGridInserter::TOptions laserModelOptions(const mrpt::config::CConfigFileBase& cfg)
{
	maps::CLaserGridInserter::TOptions options;
	options.max_range_m = 8.0;
	common::loadOptions(options, cfg, "laser_model");
	return options;
}

common::TTimedPose2D timedPose(const mrpt::obs::CObservation& obs, const mrpt::poses::CPose2D& pose)
{
	return {mrpt::Clock::toDouble(obs.timestamp), {pose.x(), pose.y(), pose.phi()}};
}
}  // namespace

std::vector<std::string> CMappingPipeline::sections()
{
	std::vector<std::string> s{"process", "grid", "laser_model", "pose_estimation", "dynamic_objects",
							   "sonar_model", "tbf", "vision", "odometry_correction", "odometry_timing", "odometry_scale_check",
							   "odometry_self_calibration",
							   "graph", "loop_closure"};
	for (const auto& e : CScanMatchingPoseEstimator::sections()) s.push_back(e);
	for (const auto& e : CLocalMapPoseEstimator::sections())
		if (std::find(s.begin(), s.end(), e) == s.end()) s.push_back(e);
	return s;
}

namespace
{
/** The dynamic object filter, or null when [dynamic_objects] is disabled. */
std::unique_ptr<dynamic::CDynamicObjectFilter> createDynamicFilter(const dynamic::CDynamicObjectFilter::TOptions& o)
{
	if (!o.enabled) return nullptr;
	try
	{
		return std::make_unique<dynamic::CDynamicObjectFilter>(o);
	}
	catch (const std::invalid_argument& e)
	{
		throw common::config_error(std::string("[dynamic_objects] ") + e.what());
	}
	catch (const std::runtime_error& e)  // classifier_model missing or not a model
	{
		throw common::config_error(std::string("[dynamic_objects] classifier_model: ") + e.what());
	}
}
}  // namespace

CMappingPipeline::CMappingPipeline(const mrpt::config::CConfigFileBase& cfg)
	: m_processOptions(common::loadedOptions<TProcessOptions>(cfg, "process")),
	  m_poseOptions(common::loadedOptions<TPoseEstimationOptions>(cfg, "pose_estimation")),
	  m_grid(common::loadedOptions<maps::CTiledOccupancyGrid::TOptions>(cfg, "grid")),
	  m_laserInserter(laserModelOptions(cfg)),
	  m_sonar(common::loadedOptions<TSonarMappingOptions>(cfg, "sonar_model"), common::loadedOptions<TTbfStageOptions>(cfg, "tbf")),
	  m_vision(cfg),
	  m_dynamicOptions(common::loadedOptions<dynamic::CDynamicObjectFilter::TOptions>(cfg, "dynamic_objects")),
	  m_dynamicStage(m_laserInserter, createDynamicFilter(m_dynamicOptions)),
	  m_estimator(createPoseEstimator(m_poseOptions, cfg, m_timer)),
	  m_odometry(common::loadedOptions<calib::TOdometryCorrection>(cfg, "odometry_correction"),
				 common::loadedOptions<TOdometryTiming>(cfg, "odometry_timing")),
	  m_timeOffset(m_odometry.timing().estimation),
	  m_odometryCalibration(common::loadedOptions<calib::TOdometryScaleCheck>(cfg, "odometry_scale_check"),
							common::loadedOptions<calib::TOdometrySelfCalibration>(cfg, "odometry_self_calibration"),
							m_odometry.correction().nominal_wheelbase_m),
	  m_loopOptions(common::loadedOptions<TLoopClosureStageOptions>(cfg, "loop_closure")),
	  m_graphOptions(common::loadedOptions<graph::TGraphBackendOptions>(cfg, "graph"))
{
	if (m_loopOptions.enabled)
		m_loop = std::make_unique<CLoopClosureStage>(m_loopOptions, m_graphOptions, m_grid.geometry());
	if (m_poseOptions.method != "map" && m_poseOptions.method != "lines+map")
	{  // checks and records the local-map front-end's sections too (config_used.ini holds every section)
		TPoseEstimationOptions other = m_poseOptions;
		other.method = "map";
		m_localMapDefaults = std::make_unique<CLocalMapPoseEstimator>(other, cfg, m_timer);
	}
	m_dynamicStage.addGrid(m_grid);
}

void CMappingPipeline::saveOptions(mrpt::config::CConfigFileBase& out) const
{
	common::saveOptions(m_processOptions, out, "process");
	common::saveOptions(m_grid.options(), out, "grid");
	common::saveOptions(m_laserInserter.options(), out, "laser_model");
	common::saveOptions(m_poseOptions, out, "pose_estimation");
	common::saveOptions(m_odometry.correction(), out, "odometry_correction");
	common::saveOptions(m_odometry.timing(), out, "odometry_timing");
	common::saveOptions(m_odometryCalibration.scaleCheck().options(), out, "odometry_scale_check");
	common::saveOptions(m_odometryCalibration.calibration().options(), out, "odometry_self_calibration");
	if (m_localMapDefaults) m_localMapDefaults->saveOptions(out);  // sections of the other front-end
	m_estimator->saveOptions(out);
	common::saveOptions(m_dynamicOptions, out, "dynamic_objects");
	common::saveOptions(m_sonar.mappingOptions(), out, "sonar_model");
	common::saveOptions(m_sonar.tbfOptions(), out, "tbf");
	common::saveOptions(m_vision.options(), out, "vision");
	common::saveOptions(m_graphOptions, out, "graph");
	common::saveOptions(m_loopOptions, out, "loop_closure");
}

void CMappingPipeline::keepSensorMaps()
{
	m_keepSensorMaps = true;
	if (m_sonar.mappingOptions().enabled && !m_laserOnly)
	{
		m_laserOnly = std::make_unique<maps::CTiledOccupancyGrid>(m_grid.options());
		m_laserOnlyIndex = m_dynamicStage.addGrid(*m_laserOnly);
	}
	if (!m_sonar.sonarOnlyMap()) m_sonar.keepSonarOnlyMap(m_grid.options());
}

const maps::CTiledOccupancyGrid* CMappingPipeline::laserOnlyMap() const
{
	return m_sonar.sawSonar() ? m_laserOnly.get() : nullptr;
}

void CMappingPipeline::processEntry(const io::TRawlogEntry& entry)
{
	++m_counters.entries;
	if (entry.actions)
	{
		common::CStageTimer::CScope t(m_timer, "odometry");
		if (auto move = entry.actions->getActionByClass<mrpt::obs::CActionRobotMovement2D>())
		{
			m_odometry.addAction(*move);
			++m_counters.odometry_readings;
		}
	}
	if (entry.frame)
		for (const auto& obs : *entry.frame) processObservation(obs);
	if (entry.observation) processObservation(entry.observation);
}

void CMappingPipeline::processObservation(const mrpt::obs::CObservation::Ptr& obs)
{
	const double t_s = mrpt::Clock::toDouble(obs->timestamp);
	if (std::isfinite(t_s)) m_latestArrival_s = std::max(m_latestArrival_s, t_s);
	const bool odometry = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs) != nullptr;
	if (!odometry && (!m_waiting.empty() || !m_odometry.readingTimeAfter(t_s)))
		m_waiting.push_back(obs);
	else
		dispatchObservation(obs);
	releaseWaiting(false);
}

void CMappingPipeline::releaseWaiting(bool all)
{
	while (!m_waiting.empty())
	{
		const auto obs = m_waiting.front();
		const double t_s = mrpt::Clock::toDouble(obs->timestamp);
		const bool waitedEnough = m_latestArrival_s - t_s > m_odometry.timing().max_wait_s;
		if (!all && !waitedEnough && !m_odometry.readingTimeAfter(t_s)) return;
		m_waiting.pop_front();
		dispatchObservation(obs);
	}
}

void CMappingPipeline::dispatchObservation(const mrpt::obs::CObservation::Ptr& obs)
{
	if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs))
	{
		if (!m_processOptions.laser_label.empty() && scan->sensorLabel != m_processOptions.laser_label)
			++m_counters.laser_scans_ignored;
		else
			processScan(*scan);
	}
	else if (auto range = std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(obs))
		processSonar(*range);
	else if (auto image = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs))
	{
		const TOdometryIncrement pending = m_odometry.pendingIncrement(mrpt::Clock::toDouble(image->timestamp));
		const size_t visionRows = m_vision.rows().size();
		m_vision.process(*image, pending.known ? std::optional(m_deadReckoningPose + pending.delta) : std::nullopt, m_timer);
		if (m_dynamicStage.filter() && m_dynamicOptions.camera_cues.enabled && m_vision.rows().size() > visionRows)
			m_dynamicStage.filter()->addCameraCues(cameraCues(m_vision.rows().back()), m_vision.rows().back().t_s);
	}
	else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
	{
		common::CStageTimer::CScope t(m_timer, "odometry");
		m_odometry.addOdometryObservation(*odo);
		m_timeOffset.addReading(mrpt::Clock::toDouble(odo->timestamp), odo->odometry);
		++m_counters.odometry_readings;
	}
	else if (auto comment = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obs);
			 comment && COdometryTracker::isGapMarker(*comment))
	{
		m_odometry.markGap();
		++m_counters.odometry_gaps;
	}
	else
		++m_counters.other_observations;
}

void CMappingPipeline::processScan(const mrpt::obs::CObservation2DRangeScan& recorded)
{
	// Returns inside the robot are dropped once, here: every stage (range
	// data, grid, people, loop closure, observers) sees them invalid.
	mrpt::obs::CObservation2DRangeScan withoutRobot;
	const bool robotInView = common::hasReturnsInside(recorded, m_processOptions.footprint);
	if (robotInView)
	{
		withoutRobot = recorded;
		m_counters.laser_returns_inside_robot += common::invalidateReturnsInside(withoutRobot, m_processOptions.footprint);
	}
	const mrpt::obs::CObservation2DRangeScan& scan = robotInView ? withoutRobot : recorded;
	++m_counters.laser_scans;
	TOdometryIncrement increment;
	{
		common::CStageTimer::CScope t(m_timer, "odometry");
		increment = m_odometry.takeIncrement(mrpt::Clock::toDouble(scan.timestamp));
		if (increment.known) m_deadReckoningPose = m_deadReckoningPose + increment.delta;
	}
	const common::TRangeData rangeData = common::makeRangeData(scan);  // the one projection of this scan
	TPoseEstimate estimate;
	std::vector<bool> onPeople;
	{
		common::CStageTimer::CScope t(m_timer, "pose_estimation");
		onPeople = peopleBeforeMatching(rangeData, increment);
		estimate = m_estimator->update(m_odometryCalibration.correct(increment), rangeData,
									   onPeople.empty() ? nullptr : &onPeople);
		m_odometryCalibration.observe(increment, estimate);
		observeTiming(mrpt::Clock::toDouble(scan.timestamp), estimate);
	}
	const mrpt::poses::CPose2D pose = estimate.pose;
	const TDynamicMapUpdate& update = filterDynamicObjects(scan, pose);
	{
		common::CStageTimer::CScope t(m_timer, "grid_update");
		m_dynamicStage.insertScan(0, scan, pose, update);
	}
	if (m_laserOnly) m_dynamicStage.insertScan(m_laserOnlyIndex, scan, pose, update);  // untimed: images only
	if (m_loop) updateLoopClosure(scan, rangeData, estimate, onPeople, update);
	m_lastEstimate = pose;
	m_trajectory.push_back(timedPose(scan, pose));
	m_odometryTrajectory.push_back(timedPose(scan, m_deadReckoningPose));
	for (const auto& observer : m_scanObservers) observer(scan, pose);
	for (const auto& observer : m_estimateObservers) observer(scan, estimate);
	estimate.lines.clear();
	m_estimates.push_back({mrpt::Clock::toDouble(scan.timestamp), std::move(estimate)});
}

void CMappingPipeline::observeTiming(double t_s, const TPoseEstimate& estimate)
{
	// Weak matches count too: at in-place turns, where a late clock shows,
	// most matches are weak (floor sample, 0.3 s late: 1.7 rad of pairs
	// after the first corner with them, 0.3 rad without).
	const bool anchor = estimate.matched && estimate.match_accepted &&
						estimate.match_quality != matching::EMatchQuality::failed && estimate.motion_prior.empty();
	if (anchor)
		m_timeOffset.addMatchedHeading(t_s, estimate.pose.phi());
	else
		m_timeOffset.breakChain();
	if (const auto offset = m_timeOffset.offsetToApply(m_odometry.timing().offset_s))
	{
		m_odometry.setOffset(*offset);
		++m_counters.odometry_offset_changes;
	}
}

void CMappingPipeline::updateLoopClosure(const mrpt::obs::CObservation2DRangeScan& scan,
										 const common::TRangeData& rangeData, const TPoseEstimate& estimate,
										 const std::vector<bool>& onPeople, const TDynamicMapUpdate& update)
{
	// Beams on people (confirmed by the filter, or predicted before matching) are not keyframe points.
	std::vector<bool> notStatic = update.excluded;
	if (!onPeople.empty())
	{
		notStatic.resize(onPeople.size(), false);
		for (size_t b = 0; b < onPeople.size(); ++b) notStatic[b] = notStatic[b] || onPeople[b];
	}
	{
		// On the background thread the back-end's own time is added in finish();
		// here only what this thread spends handing keyframes over.
		common::CStageTimer::CScope t(m_timer,
									  m_loopOptions.background_thread ? "loop_closure_handover" : "loop_closure");
		const auto result = m_loop->process(estimate, rangeData, notStatic.empty() ? nullptr : &notStatic);
		if (result && result->optimized) m_timer.add("loop_closure_optimize", result->optimization.time_ms * 1e-3);
	}
	m_scanArchive.add(scan, update);
}

void CMappingPipeline::finish()
{
	releaseWaiting(true);
	if (m_loop)
	{
		const double flushMs = m_loop->flush();  // waits for the back-end thread
		if (flushMs >= 0) m_timer.add("loop_closure_optimize", flushMs * 1e-3);
		// the back-end thread's calls since the last finish()
		for (const auto& calls = m_loop->backgroundTimings(); m_loopCallsTimed < calls.size(); ++m_loopCallsTimed)
		{
			const TBackendCallTiming& call = calls[m_loopCallsTimed];
			m_timer.add("loop_closure", call.keyframe_ms * 1e-3);
			if (call.optimize_ms >= 0) m_timer.add("loop_closure_optimize", call.optimize_ms * 1e-3);
		}
	}
	if (!m_loop || !m_loop->optimized() || !m_loopOptions.rerender_map || m_sonar.mappingOptions().enabled) return;
	common::CStageTimer::CScope t(m_timer, "map_rerender");
	const auto poses = m_loop->correctedScanPoses();
	maps::CTiledOccupancyGrid fresh(m_grid.options());
	m_scanArchive.replay(fresh, poses, m_laserInserter);
	m_grid = std::move(fresh);
	m_mapRerendered = true;
}

common::TTrajectory2D CMappingPipeline::finalTrajectory() const
{
	if (!m_loop) return m_trajectory;
	common::TTrajectory2D out = m_trajectory;
	const auto poses = m_loop->correctedScanPoses();
	for (size_t i = 0; i < out.size() && i < poses.size(); ++i) out[i].pose = poses[i].asTPose();
	return out;
}

void CMappingPipeline::processSonar(const mrpt::obs::CObservationRange& obs)
{
	if (!m_sonar.active() && !m_keepSensorMaps)
	{
		++m_counters.other_observations;
		return;
	}
	const TOdometryIncrement pending =
		m_odometryCalibration.correct(m_odometry.pendingIncrement(mrpt::Clock::toDouble(obs.timestamp)));
	if ((!m_processOptions.sonar_label.empty() && obs.sensorLabel != m_processOptions.sonar_label) || !pending.known)
	{
		++m_counters.sonar_observations_ignored;
		return;
	}
	++m_counters.sonar_observations;
	m_sonar.process(obs, m_lastEstimate + pending.delta, m_grid, m_timer);
	m_counters.sonar_readings_inserted = m_sonar.counters().readings_inserted;
}

std::vector<bool> CMappingPipeline::peopleBeforeMatching(const common::TRangeData& scan,
														 const TOdometryIncrement& increment) const
{
	const dynamic::CDynamicObjectFilter* filter = m_dynamicStage.filter();
	if (!filter || !m_dynamicOptions.exclude_from_matching) return {};
	const mrpt::poses::CPose2D predicted = increment.known ? m_lastEstimate + increment.delta : m_lastEstimate;
	return filter->predictedDynamicBeams(scan, predicted, scan.t_s, kPredictedPoseMargin_m);
}

const TDynamicMapUpdate& CMappingPipeline::filterDynamicObjects(const mrpt::obs::CObservation2DRangeScan& scan,
																const mrpt::poses::CPose2D& pose)
{
	if (!m_dynamicStage.filter()) return m_dynamicStage.filterScan(scan, pose, 0.0);  // nothing to filter
	common::CStageTimer::CScope t(m_timer, "dynamic_objects");
	const auto& update = m_dynamicStage.filterScan(scan, pose, mrpt::Clock::toDouble(scan.timestamp));
	const auto& frame = m_dynamicStage.filter()->lastFrame();
	const size_t scanIndex = m_counters.laser_scans - 1;
	dynamic::appendTrackRows(frame, scanIndex, m_trackRows);
	if (m_debugFrames.size() < m_debugFramesMax && !frame.legs.empty()) m_debugFrames.push_back({scanIndex, scan, frame});
	return update;
}

}  // namespace hslam::slam
