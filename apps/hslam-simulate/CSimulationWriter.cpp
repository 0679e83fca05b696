/* hslam-simulate: CSimulationWriter. */
#include "CSimulationWriter.h"

#include <hslam/io/carmen_observations.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DQuat.h>

#include <iomanip>
#include <stdexcept>

namespace
{
std::ofstream openCsv(const std::string& path, const std::string& header)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot open for writing");
	f << std::fixed << std::setprecision(4) << header << "\n";
	return f;
}
}  // namespace

CSimulationWriter::CSimulationWriter(const std::string& dir, size_t peopleCount)
	: m_dir(dir),
	  m_rawlog(dir + "/sim.rawlog"),
	  m_people(openCsv(dir + "/people.csv",
					   "scan,t_s,person,x_m,y_m,heading_deg,leg0_x_m,leg0_y_m,leg1_x_m,leg1_y_m,leg0_stance,leg1_stance")),
	  m_labels(openCsv(dir + "/beam_labels.csv", "scan,t_s,beam,angle_deg,range_m,kind,object,part")),
	  m_sonar(openCsv(dir + "/sonar_truth.csv", "t_s,sonar,range_m,echo,bounces,kind,object")),
	  m_waypoints(openCsv(dir + "/waypoints.csv",
						  "waypoint,t_s,true_x_m,true_y_m,true_yaw_deg,odometry_x_m,odometry_y_m,odometry_yaw_deg"))
{
	m_tracks.people.resize(peopleCount);
}

void CSimulationWriter::onOdometry(const mrpt::obs::CObservationOdometry& obs, const hslam::sim::TSimulationFrame&)
{
	m_rawlog.write(obs);
}

void CSimulationWriter::onOdometryGap(const hslam::sim::TSimulationFrame& frame)
{
	// Same marker text as the CARMEN importer (hslam::slam::COdometryTracker::kGapMarker).
	m_rawlog.write(*hslam::io::makeComment(
		"ODOMETRY_GAP", "ODOMETRY_GAP: simulated odometry reading withheld ([odometry] fault = drop)", frame.t_s));
}

void CSimulationWriter::onLaserScan(const mrpt::obs::CObservation2DRangeScan& obs,
									const std::vector<hslam::sim::TObjectTag>& tags,
									const hslam::sim::TSimulationFrame& frame)
{
	m_rawlog.write(obs);
	const size_t scan = m_scans++;
	m_truth.push_back({frame.t_s, frame.true_pose});
	m_odometry.push_back({frame.t_s, frame.odometry_pose});
	m_tracks.true_path.push_back(frame.true_pose);
	m_tracks.odometry_path.push_back(frame.odometry_pose);
	const double t = frame.t_s;
	for (const auto& p : frame.people)
	{
		m_people << scan << "," << std::setprecision(3) << t << std::setprecision(4) << "," << p.id << "," << p.body.x
				 << "," << p.body.y << "," << p.heading_rad * 180.0 / M_PI << "," << p.legs[0].x << "," << p.legs[0].y
				 << "," << p.legs[1].x << "," << p.legs[1].y << "," << p.stance[0] << "," << p.stance[1] << "\n";
		if (static_cast<size_t>(p.id) < m_tracks.people.size()) m_tracks.people[p.id].push_back(p.body);
	}
	const size_t n = obs.getScanSize();
	for (size_t i = 0; i < n && i < tags.size(); ++i)
	{
		const auto kind = tags[i].kind;
		if (kind != hslam::sim::EObjectKind::person_leg && kind != hslam::sim::EObjectKind::furniture) continue;
		if (kind == hslam::sim::EObjectKind::person_leg) ++m_personBeams;
		const double angle = -0.5 * obs.aperture + obs.aperture * static_cast<double>(i) / static_cast<double>(n - 1);
		m_labels << scan << "," << std::setprecision(3) << t << "," << i << "," << std::setprecision(2)
				 << angle * 180.0 / M_PI << "," << std::setprecision(3) << obs.getScanRange(i) << ","
				 << hslam::sim::objectKindName(kind) << "," << tags[i].group << "," << tags[i].part << "\n";
	}
	m_labels << std::setprecision(4);
}

void CSimulationWriter::onSonar(const mrpt::obs::CObservationRange& obs,
								const std::vector<hslam::sim::TSonarEcho>& echoes,
								const hslam::sim::TSimulationFrame& frame)
{
	m_rawlog.write(obs);
	for (size_t k = 0; k < echoes.size(); ++k)
	{
		const auto& e = echoes[k];
		++m_sonarReadings;
		if (e.echo) ++m_sonarEchoes;
		if (e.echo && e.bounces > 0) ++m_sonarMultipath;
		m_sonar << std::setprecision(3) << frame.t_s << "," << k << "," << e.range_m << "," << e.echo << ","
				<< e.bounces << "," << hslam::sim::objectKindName(e.tag.kind) << "," << e.tag.group << "\n";
	}
}

void CSimulationWriter::onWaypointReached(size_t index, const hslam::sim::TSimulationFrame& frame)
{
	const auto& a = frame.true_pose;
	const auto& o = frame.odometry_pose;
	m_waypoints << index << "," << std::setprecision(3) << frame.t_s << std::setprecision(4) << "," << a.x << "," << a.y
				<< "," << a.phi * 180.0 / M_PI << "," << o.x << "," << o.y << "," << o.phi * 180.0 / M_PI << "\n";
}

void CSimulationWriter::onCamera(const mrpt::obs::CObservation& obs, const hslam::sim::TSimulationFrame& frame)
{
	m_rawlog.write(obs);
	if (!m_cameraTruth.is_open())
		m_cameraTruth = openCsv(m_dir + "/camera_truth.tum", "# t x y z qx qy qz qw (camera frame: z forward, x right, y down)");
	mrpt::poses::CPose3D sensor;
	obs.getSensorPose(sensor);
	const auto& p = frame.true_pose;
	const mrpt::poses::CPose3D cam = mrpt::poses::CPose3D(p.x, p.y, 0, p.phi, 0, 0) + sensor;
	const mrpt::poses::CPose3DQuat q(cam);
	m_cameraTruth << std::setprecision(6) << frame.t_s << " " << q.x() << " " << q.y() << " " << q.z() << " "
				  << q.quat().x() << " " << q.quat().y() << " " << q.quat().z() << " " << q.quat().r() << "\n";
}

void CSimulationWriter::finish()
{
	m_rawlog.close();
	hslam::common::writeTumFile(m_dir + "/ground_truth.tum", m_truth);
	hslam::common::writeTumFile(m_dir + "/odometry.tum", m_odometry);
	for (auto* f : {&m_people, &m_labels, &m_sonar, &m_waypoints, &m_cameraTruth})
	{
		if (!f->is_open()) continue;  // camera_truth.tum exists only with a camera
		f->flush();
		if (!*f) throw std::runtime_error(m_dir + ": write error in a CSV file");
	}
}
