/* hslam-vision-train: options of the trainer ([vision_train] of --config;
 * the synthetic pairs' camera from its [camera], the simulator's keys). */
#pragma once

#include <hslam/sim/CPinholeCameraSimulator.h>
#include <hslam/vision/rotation_flow.h>

#include <string>

namespace hslam::vision_train
{
struct TVisionTrainOptions  //!< [vision_train]
{
	vision::TRotationTrainingOptions network;  //!< hidden_neurons, max_iterations, outlier rule, seed
	double min_turn_deg = 0.5;  //!< rawlog: a pair is used if the robot turned at least this much ...
	double max_travel_m = 0.02;  //!< ... and moved at most this far (turning on the spot, thesis 4.8.2 i)
	int held_out_every = 5;  //!< every N-th pair is held out for the residual figure (not trained on)
	std::string camera_label;  //!< rawlog: only images with this label; empty = all

	template <class V>
	void visit(V& v)
	{
		network.visit(v);
		v.real("min_turn_deg", min_turn_deg, 0.0, 90.0);
		v.real("max_travel_m", max_travel_m, 0.0, 10.0);
		v.integer("held_out_every", held_out_every, 2, 1000);
		v.text("camera_label", camera_label);
	}
};

/** Loaded options: [vision_train] and, for synthetic pairs, [camera]
 * (sim::TCameraSimOptions: intrinsics and mount); an empty path gives the
 * defaults (the thesis camera at 640 x 480 on its off-axis mount). */
struct TLoadedTrainConfig
{
	TVisionTrainOptions train;
	sim::TCameraSimOptions camera;
};
TLoadedTrainConfig loadTrainConfig(const std::string& iniPath);

}  // namespace hslam::vision_train
