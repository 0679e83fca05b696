/* hslam sim: closed-loop navigation runs (see closed_loop.h). */
#include <hslam/sim/clearance.h>
#include <hslam/sim/closed_loop.h>

#include <cmath>
#include <ctime>

namespace hslam::sim
{
namespace
{
/** Keeps the latest scan and sonar ring and forwards everything to an optional sink. */
class CLatestObservations : public ISimulationSink
{
   public:
	explicit CLatestObservations(ISimulationSink* next) : m_next(next) {}
	void onOdometry(const mrpt::obs::CObservationOdometry& o, const TSimulationFrame& f) override
	{
		if (m_next) m_next->onOdometry(o, f);
	}
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan& o, const std::vector<TObjectTag>& tags,
					 const TSimulationFrame& f) override
	{
		scan = o;
		haveScan = true;
		if (m_next) m_next->onLaserScan(o, tags, f);
	}
	void onSonar(const mrpt::obs::CObservationRange& o, const std::vector<TSonarEcho>& e,
				 const TSimulationFrame& f) override
	{
		sonar = o;
		haveSonar = true;
		if (m_next) m_next->onSonar(o, e, f);
	}
	void onCamera(const mrpt::obs::CObservation& o, const TSimulationFrame& f) override
	{
		if (m_next) m_next->onCamera(o, f);
	}
	mrpt::obs::CObservation2DRangeScan scan;
	mrpt::obs::CObservationRange sonar;
	bool haveScan = false, haveSonar = false;

   private:
	ISimulationSink* m_next;
};

double threadCpu_s()
{
	timespec ts{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
}  // namespace

TClosedLoopResult runClosedLoop(CSimulator& sim, IClosedLoopController& controller, const TClosedLoopOptions& o,
								ISimulationSink* sink)
{
	TClosedLoopResult res;
	CLatestObservations latest(sink);
	const double dt = sim.config().simulation.physics_dt_s;
	const long controlTicks = std::max(1L, std::lround(o.control_period_s / dt));
	double nextSample_s = 0;
	mrpt::math::TPose2D last = sim.robot().truePose();
	for (long tick = 0;; ++tick)
	{
		const double t = sim.elapsed_s();
		const auto truth = sim.robot().truePose();
		res.path_length_m += std::hypot(truth.x - last.x, truth.y - last.y);
		last = truth;
		const double clearance = clearance_m(sim.scene().world, {truth.x, truth.y});
		res.min_clearance_m = std::min(res.min_clearance_m, clearance);
		if (t >= nextSample_s)
		{
			res.path.push_back({t, truth, sim.robot().odometryVelocity().vx, clearance});
			nextSample_s += o.path_sample_period_s;
		}
		const double staticClearance = clearance_m(sim.scene().world, {truth.x, truth.y}, false);
		res.min_static_clearance_m = std::min(res.min_static_clearance_m, staticClearance);
		if (clearance < o.collision_radius_m)
		{
			if (staticClearance < o.collision_radius_m)
				res.collided = true;
			else if (tick % controlTicks == 0)
				++res.person_contacts;
		}
		if (t > o.timeout_s) res.timed_out = true;
		if (res.collided || res.timed_out || sim.done()) break;
		if (tick % controlTicks == 0)
		{
			TControlInput in{t, o.use_odometry_pose ? sim.robot().odometryPose() : truth,
							 latest.haveScan ? &latest.scan : nullptr, latest.haveSonar ? &latest.sonar : nullptr};
			const double c0 = threadCpu_s();
			const auto out = controller.control(in);
			res.cpu_s += threadCpu_s() - c0;
			++res.control_steps;
			sim.setExternalCommand({out.v_mps, out.w_rad_s});
			res.finished = out.finished;
			res.failed = out.failed;
			if (out.finished || out.failed) break;
		}
		sim.step(latest);
	}
	res.time_s = sim.elapsed_s();
	return res;
}

}  // namespace hslam::sim
