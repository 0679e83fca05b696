/* hslam: the mapping pipeline, the one place where the stages of thesis
 * figure 55 are wired together and timed. Per laser scan:
 *     odometry increment -> pose estimation -> dynamic-mapping stage
 *     (CDynamicMappingStage: dynamic object filter, thesis 4.7 -> late
 *     exclusions undone exactly -> tiled grid update (laser), beams hitting
 *     confirmed moving people not marked occupied)
 * Per sonar ring observation (CObservationRange, CSonarMappingStage):
 *     pose = estimate at the latest laser scan + odometry since that scan
 *     -> sonar grid update (4.6.2 iii-iv, weighted against the laser)
 *     -> TBF sonar corners (4.3)
 * The sonar pose is the latest estimate composed with the odometry pending
 * for the next scan (not re-estimated: pose estimation is laser-driven). With
 * the simulator and the Pioneer driver sonars arrive in the same SIP cycle as
 * the odometry, i.e. up to 100 ms after a scan; composing the pending
 * odometry removes the up to 0.08 m / several degrees the robot moves in that
 * time, which the latest estimate alone would smear into the sonar arcs.
 * Across an odometry gap the pose is unknown and the reading is skipped.
 *
 * With [loop_closure] enabled = true, every scan also goes to the
 * loop-closure stage (CLoopClosureStage: keyframes -> pose graph -> loop
 * closure -> optimisation) and into a compact scan archive (CScanArchive);
 * finish() then re-inserts every scan at its corrected pose into a fresh grid
 * if the graph was optimised (the same CDynamicMappingStage path as online).
 *
 * INI sections read (see config_ini/hslam-default.ini): [process], [grid],
 * [laser_model], [pose_estimation], [dynamic_objects], [sonar_model], [tbf],
 * [graph], [loop_closure]; unknown keys in them are errors. */
#pragma once

#include <hslam/common/CStageTimer.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/dynamic_outputs.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <hslam/slam/CDynamicMappingStage.h>
#include <hslam/slam/CLoopClosureStage.h>
#include <hslam/slam/COdometryCalibrationStage.h>
#include <hslam/slam/COdometryTracker.h>
#include <hslam/slam/CScanArchive.h>
#include <hslam/slam/CPoseEstimator.h>
#include <hslam/slam/CSonarMappingStage.h>
#include <hslam/slam/CVisionStage.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/config/CConfigFileBase.h>

#include <deque>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <hslam/common/range_data.h>

namespace hslam::slam
{
struct TProcessOptions
{
	std::string laser_label;  //!< only scans with this sensor label are used; empty = all 2D scans
	std::string sonar_label;  //!< only CObservationRange with this label are used; empty = all
	/** Laser returns inside the robot are not the world (Pioneer 3-DX:
	 * ARIA's p3dx.p RobotLengthFront 210 mm, RobotLengthRear 301 mm,
	 * RobotWidth 425 mm); all 0 = keep every return. */
	common::TRobotFootprint footprint{0.21, 0.301, 0.2125};

	template <class V>
	void visit(V& v)
	{
		v.text("laser_label", laser_label);
		v.text("sonar_label", sonar_label);
		v.real("footprint_front_m", footprint.front_m, 0.0, 10.0);
		v.real("footprint_rear_m", footprint.rear_m, 0.0, 10.0);
		v.real("footprint_half_width_m", footprint.half_width_m, 0.0, 10.0);
	}
};

struct TPipelineCounters
{
	size_t entries = 0;  //!< rawlog entries processed
	size_t laser_scans = 0;  //!< scans used for mapping
	size_t laser_scans_ignored = 0;  //!< scans with another sensor label
	size_t laser_returns_inside_robot = 0;  //!< returns dropped inside [process] footprint_*
	size_t odometry_readings = 0;  //!< odometry actions or observations
	size_t odometry_gaps = 0;  //!< intervals with unknown motion
	size_t sonar_observations = 0;  //!< sonar ring observations used (grid and/or TBF)
	size_t sonar_observations_ignored = 0;  //!< another label, or taken across an odometry gap
	size_t sonar_readings_inserted = 0;  //!< single sonar readings inserted into the grid
	size_t other_observations = 0;  //!< observations no stage uses yet
	size_t odometry_offset_changes = 0;  //!< times the estimated odometry time offset was applied
};

class CMappingPipeline
{
   public:
	/** Loads and checks all pipeline sections from `cfg`; throws
	 * common::config_error with "[section] key" on a bad value. */
	explicit CMappingPipeline(const mrpt::config::CConfigFileBase& cfg);
	/** Not copyable nor movable: the dynamic-mapping stage points at the grids. */
	CMappingPipeline(const CMappingPipeline&) = delete;
	CMappingPipeline& operator=(const CMappingPipeline&) = delete;

	void processEntry(const io::TRawlogEntry& entry);
	/** End of the input: with the loop-closure stage on and the graph
	 * optimised, rebuilds the grid from every scan at its corrected pose
	 * (not with [sonar_model] enabled: sonar readings are not archived). */
	void finish();

	const maps::CTiledOccupancyGrid& grid() const { return m_grid; }
	/** Also keep a sonar-only grid and, if sonar readings go into the main
	 * grid, a laser-only grid (map_sonar_only.png, map_laser_only.png). */
	void keepSensorMaps();
	/** Grid of the laser scans alone; null unless kept, sonar mapping is on
	 * and the log had sonar (otherwise grid() is the laser-only map). */
	const maps::CTiledOccupancyGrid* laserOnlyMap() const;
	/** Grid of the sonar readings alone (weight 1); null unless kept and the
	 * log had sonar (a log without would give an empty picture). */
	const maps::CTiledOccupancyGrid* sonarOnlyMap() const
	{
		return m_sonar.sawSonar() ? m_sonar.sonarOnlyMap() : nullptr;
	}
	const CSonarMappingStage& sonarStage() const { return m_sonar; }
	const CVisionStage& visionStage() const { return m_vision; }
	/** Estimated robot pose at each scan, online (the front-end's filtered estimate). */
	const common::TTrajectory2D& trajectory() const { return m_trajectory; }
	/** The run's best trajectory: corrected by the pose graph when the
	 * loop-closure stage is on, else trajectory(). */
	common::TTrajectory2D finalTrajectory() const;
	/** Loop-closure stage ([loop_closure] enabled = true), else null. */
	const CLoopClosureStage* loopClosureStage() const { return m_loop.get(); }
	/** finish() rebuilt the grid from the optimised graph. */
	bool mapRerendered() const { return m_mapRerendered; }
	const calib::COdometrySelfCalibration& odometryCalibration() const { return m_odometryCalibration.calibration(); }
	const calib::COdometryScaleCheck& odometryScaleCheck() const { return m_odometryCalibration.scaleCheck(); }
	/** [odometry_timing]: the offset's fit so far, and the offset in use (s). */
	const calib::COdometryTimeOffset& odometryTimeOffset() const { return m_timeOffset; }
	double odometryOffsetInUse_s() const { return m_odometry.timing().offset_s; }
	const TOdometryTiming& odometryTiming() const { return m_odometry.timing(); }
	/** Dead-reckoning pose at each scan (same timestamps), for comparison. */
	const common::TTrajectory2D& odometryTrajectory() const { return m_odometryTrajectory; }
	common::CStageTimer& timer() { return m_timer; }
	const common::CStageTimer& timer() const { return m_timer; }
	const TPipelineCounters& counters() const { return m_counters; }
	const TProcessOptions& processOptions() const { return m_processOptions; }
	std::string poseEstimatorName() const { return m_estimator->name(); }

	/** Dynamic object filter ([dynamic_objects] enabled = true), else null. */
	const dynamic::CDynamicObjectFilter* dynamicFilter() const { return m_dynamicStage.filter(); }
	/** Live leg and person tracks after every scan (for tracks.csv). */
	const std::vector<dynamic::TTrackRow>& trackRows() const { return m_trackRows; }
	/** A scan and the filter state after it, kept for debug images. */
	struct TDebugFrame
	{
		size_t scan_index = 0;  //!< 0-based among the mapped scans
		mrpt::obs::CObservation2DRangeScan scan;
		dynamic::TDynamicFrame frame;
	};
	/** Keep the first `maxFrames` scans in which the filter found legs (0 = none). */
	void keepDynamicDebugFrames(size_t maxFrames) { m_debugFramesMax = maxFrames; }
	const std::vector<TDebugFrame>& dynamicDebugFrames() const { return m_debugFrames; }

	/** Called for every mapped scan with the pose it was inserted at
	 * (benchmarks, debug images, live viewers). */
	using TScanObserver = std::function<void(const mrpt::obs::CObservation2DRangeScan&, const mrpt::poses::CPose2D&)>;
	void addScanObserver(TScanObserver observer) { m_scanObservers.push_back(std::move(observer)); }
	/** Same, with everything the pose estimator reported (covariance, match, lines). */
	using TEstimateObserver = std::function<void(const mrpt::obs::CObservation2DRangeScan&, const TPoseEstimate&)>;
	void addEstimateObserver(TEstimateObserver observer) { m_estimateObservers.push_back(std::move(observer)); }

	/** Per scan: time stamp (s) and the estimator's report (without lines). */
	struct TTimedEstimate
	{
		double t_s = 0;
		TPoseEstimate estimate;
	};
	const std::vector<TTimedEstimate>& estimates() const { return m_estimates; }

	/** Writes the effective value of every pipeline option (defaults included). */
	void saveOptions(mrpt::config::CConfigFileBase& out) const;

	/** INI sections the pipeline reads. */
	static std::vector<std::string> sections();

   private:
	/** Hands `obs` on in arrival order; a sensor reading with no odometry
	 * reading after it yet waits for one ([odometry_timing] interpolate). */
	void processObservation(const mrpt::obs::CObservation::Ptr& obs);
	/** Dispatches waiting readings that have their odometry now, or that
	 * waited max_wait_s of later data, or all of them. */
	void releaseWaiting(bool all);
	void dispatchObservation(const mrpt::obs::CObservation::Ptr& obs);
	void processScan(const mrpt::obs::CObservation2DRangeScan& scan);
	/** Feeds the scan's estimate to the odometry time offset's fit and applies the fit when confident. */
	void observeTiming(double t_s, const TPoseEstimate& estimate);
	void processSonar(const mrpt::obs::CObservationRange& obs);
	/** Beams on people predicted from the filter's earlier tracks (empty: none). */
	std::vector<bool> peopleBeforeMatching(const common::TRangeData& scan, const TOdometryIncrement& increment) const;
	static constexpr double kPredictedPoseMargin_m = 0.2;  //!< odometry error over one scan interval, generously
	/** Runs the dynamic object filter; returns what the grids receive with the scan. */
	const TDynamicMapUpdate& filterDynamicObjects(const mrpt::obs::CObservation2DRangeScan& scan,
												  const mrpt::poses::CPose2D& pose);
	/** Hands the scan to the loop-closure stage and the scan archive. */
	void updateLoopClosure(const mrpt::obs::CObservation2DRangeScan& scan, const common::TRangeData& rangeData,
						   const TPoseEstimate& estimate, const std::vector<bool>& onPeople,
						   const TDynamicMapUpdate& update);

	common::CStageTimer m_timer;  // first: the estimator keeps a reference to it
	TProcessOptions m_processOptions;
	TPoseEstimationOptions m_poseOptions;
	maps::CTiledOccupancyGrid m_grid;
	maps::CLaserGridInserter m_laserInserter;
	std::unique_ptr<maps::CTiledOccupancyGrid> m_laserOnly;  //!< kept only with sonar mapping on
	CSonarMappingStage m_sonar;
	CVisionStage m_vision;  //!< camera branch ([vision], CObservationImage)
	bool m_keepSensorMaps = false;
	mrpt::poses::CPose2D m_lastEstimate;  //!< pose at the latest scan (origin before the first)
	dynamic::CDynamicObjectFilter::TOptions m_dynamicOptions;
	CDynamicMappingStage m_dynamicStage;  //!< filter -> late exclusions -> insertion, into m_grid (and m_laserOnly)
	size_t m_laserOnlyIndex = 0;  //!< m_laserOnly's grid in m_dynamicStage
	std::vector<dynamic::TTrackRow> m_trackRows;
	size_t m_debugFramesMax = 0;
	std::vector<TDebugFrame> m_debugFrames;
	std::unique_ptr<CPoseEstimator> m_estimator;
	std::unique_ptr<CPoseEstimator> m_localMapDefaults;  //!< unused estimator whose options config_used.ini records
	COdometryTracker m_odometry;
	calib::COdometryTimeOffset m_timeOffset;  //!< [odometry_timing] estimate_offset
	std::deque<mrpt::obs::CObservation::Ptr> m_waiting;  //!< sensor readings waiting for the odometry after them
	double m_latestArrival_s = -std::numeric_limits<double>::infinity();  //!< newest stamp seen
	COdometryCalibrationStage m_odometryCalibration;  //!< [odometry_self_calibration]
	mrpt::poses::CPose2D m_deadReckoningPose;
	common::TTrajectory2D m_trajectory, m_odometryTrajectory;
	std::vector<TTimedEstimate> m_estimates;
	TPipelineCounters m_counters;
	std::vector<TScanObserver> m_scanObservers;
	std::vector<TEstimateObserver> m_estimateObservers;
	std::unique_ptr<CLoopClosureStage> m_loop;  //!< null unless [loop_closure] enabled
	size_t m_loopCallsTimed = 0;  //!< back-end thread calls already in m_timer (finish() may run again)
	TLoopClosureStageOptions m_loopOptions;
	graph::TGraphBackendOptions m_graphOptions;
	CScanArchive m_scanArchive;  //!< filled only with the loop-closure stage on
	bool m_mapRerendered = false;
};

}  // namespace hslam::slam
