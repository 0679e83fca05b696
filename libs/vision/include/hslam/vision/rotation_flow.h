/* hslam vision: the image flow a robot rotation causes (thesis 4.8.2 i-ii).
 *
 * Two models behind one interface:
 *  - CAnalyticRotationFlow: the rotation of the camera is the robot's yaw
 *    change seen through the camera mounting (sensorPose): R_c = rotation of
 *    (-S) + Rz(dyaw) + S. A pure camera rotation moves every image point by
 *    the infinite homography H = K R_c^T K^-1, independently of depth (eq. 95:
 *    the rotational terms have no Z). What a camera off the robot's axis adds
 *    is a translation of the lens (the lever arm, eq. 98); its flow depends
 *    on depth and cannot be predicted without it, so it is left in the
 *    residual, where it is part of the true camera translation and moves the
 *    FOE to where the camera really heads.
 *  - CLearnedRotationFlow: the thesis's network (figure 176, appendix I.1):
 *    inputs x/100, y/100 (pixels from the image centre) and the robot
 *    rotation in degrees, 5 tanh hidden neurons, outputs the flow u, v (px);
 *    cv::ml::ANN_MLP trained on tracked corners of image pairs taken while
 *    the robot turns, labelled with the odometry rotation. It learns the
 *    lever-arm flow averaged over the depths of the training scenes.
 *
 * A residual vector is (p1 - p0) - predicted(p0), based at p0 + predicted(p0):
 * after removing the rotation the second point is radial from the FOE of the
 * second image, K t / t_z with t the camera translation in its own frame. */
#pragma once

#include <hslam/vision/camera_geometry.h>
#include <hslam/vision/optical_flow.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::vision
{
class IRotationFlowModel
{
   public:
	virtual ~IRotationFlowModel() = default;
	/** Predicted flow (px) at each point of the first image for a robot yaw change. */
	virtual std::vector<cv::Point2f> predict(const std::vector<cv::Point2f>& p0, double robotYaw_rad) const = 0;
	virtual std::string name() const = 0;
};

class CAnalyticRotationFlow : public IRotationFlowModel
{
   public:
	explicit CAnalyticRotationFlow(TMountedCamera camera) : m_camera(std::move(camera)) {}
	/** H mapping first-image pixels to second-image pixels of points at infinity. */
	cv::Matx33d homography(double robotYaw_rad) const;
	std::vector<cv::Point2f> predict(const std::vector<cv::Point2f>& p0, double robotYaw_rad) const override;
	std::string name() const override { return "analytic"; }

   private:
	TMountedCamera m_camera;
};

/** One training example: a corner, its measured flow and the robot rotation. */
struct TRotationSample
{
	cv::Point2f p0;
	cv::Point2f flow;
	double robot_yaw_rad = 0;
};

struct TRotationTrainingOptions  //!< [vision_train]
{
	int hidden_neurons = 5;  //!< thesis figure 176
	int max_iterations = 2000;
	double max_angle_from_horizontal_deg = 30;  //!< appendix I.1 outlier rule (0 = off)
	int seed = 1;

	template <class V>
	void visit(V& v)
	{
		v.integer("hidden_neurons", hidden_neurons, 1, 100);
		v.integer("max_iterations", max_iterations, 10, 1000000);
		v.real("max_angle_from_horizontal_deg", max_angle_from_horizontal_deg, 0.0, 90.0);
		v.integer("seed", seed, 0, 1 << 30);
	}
};

/** The thesis's outlier rule (appendix I.1): keep a vector only if its x
 * component has the sign of the rotation's mean x flow and it is within
 * max_angle_from_horizontal_deg of horizontal; samples at zero rotation are kept. */
std::vector<TRotationSample> selectTrainingSamples(const std::vector<TRotationSample>& samples,
												   const TRotationTrainingOptions& options);

class CLearnedRotationFlow : public IRotationFlowModel
{
   public:
	CLearnedRotationFlow();
	~CLearnedRotationFlow() override;
	CLearnedRotationFlow(CLearnedRotationFlow&&) noexcept;
	CLearnedRotationFlow& operator=(CLearnedRotationFlow&&) noexcept;

	/** Trains on `samples` for images of `width` x `height` (throws
	 * std::invalid_argument for fewer than 10 samples). */
	void train(const std::vector<TRotationSample>& samples, int width, int height,
			   const TRotationTrainingOptions& options);
	bool trained() const;
	int imageWidth() const { return m_width; }
	int imageHeight() const { return m_height; }

	/** Throws std::logic_error if untrained. */
	std::vector<cv::Point2f> predict(const std::vector<cv::Point2f>& p0, double robotYaw_rad) const override;
	std::string name() const override { return "learned"; }

	/** The model as an OpenCV FileStorage YAML text (image size + ANN_MLP). */
	std::string toYaml() const;
	/** Inverse of toYaml(); throws std::runtime_error naming what is missing. */
	static CLearnedRotationFlow fromYaml(const std::string& yaml);

   private:
	struct TImpl;
	std::unique_ptr<TImpl> m_impl;
	int m_width = 0, m_height = 0;
};

/** Residual vectors: based at p0 + predicted, ending at p1. */
std::vector<TFlowVector> removeRotationFlow(const std::vector<TFlowVector>& flow,
											const std::vector<cv::Point2f>& predicted);

}  // namespace hslam::vision
