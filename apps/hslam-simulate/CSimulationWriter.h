/* hslam-simulate: the sink that writes what the simulator produces into the
 * output folder: the rawlog (observations-only, gz) and the ground truth of
 * every laser scan (TUM poses, people positions CSV, per-beam labels CSV),
 * and keeps the tracks for the overview picture. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogObservationWriter.h>
#include <hslam/sim/CSimulator.h>
#include <hslam/sim/scene_rendering.h>

#include <fstream>
#include <string>

class CSimulationWriter : public hslam::sim::ISimulationSink
{
   public:
	/** Opens the files in `dir` (which must exist). */
	CSimulationWriter(const std::string& dir, size_t peopleCount);

	void onOdometry(const mrpt::obs::CObservationOdometry& obs, const hslam::sim::TSimulationFrame& frame) override;
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan& obs, const std::vector<hslam::sim::TObjectTag>& beamTags,
					 const hslam::sim::TSimulationFrame& frame) override;
	void onSonar(const mrpt::obs::CObservationRange& obs, const std::vector<hslam::sim::TSonarEcho>& echoes,
				 const hslam::sim::TSimulationFrame& frame) override;

	/** Writes an ODOMETRY_GAP comment, as hslam-carmen2rawlog does for missing odometry. */
	void onOdometryGap(const hslam::sim::TSimulationFrame& frame) override;
	/** Writes the image and the true camera pose (camera_truth.tum). */
	void onCamera(const mrpt::obs::CObservation& obs, const hslam::sim::TSimulationFrame& frame) override;

	void onWaypointReached(size_t index, const hslam::sim::TSimulationFrame& frame) override;

	/** Closes the rawlog and writes the TUM files. */
	void finish();

	const hslam::sim::TOverviewTracks& tracks() const { return m_tracks; }
	size_t scans() const { return m_scans; }
	size_t personBeams() const { return m_personBeams; }
	size_t sonarEchoes() const { return m_sonarEchoes; }
	size_t sonarReadings() const { return m_sonarReadings; }
	size_t sonarMultipath() const { return m_sonarMultipath; }
	const hslam::io::CRawlogObservationWriter& rawlog() const { return m_rawlog; }

   private:
	std::string m_dir;
	hslam::io::CRawlogObservationWriter m_rawlog;
	std::ofstream m_people, m_labels, m_sonar, m_waypoints;
	std::ofstream m_cameraTruth;  //!< opened at the first image
	hslam::common::TTrajectory2D m_truth, m_odometry;
	hslam::sim::TOverviewTracks m_tracks;
	size_t m_scans = 0, m_personBeams = 0, m_sonarEchoes = 0, m_sonarReadings = 0, m_sonarMultipath = 0;
};
