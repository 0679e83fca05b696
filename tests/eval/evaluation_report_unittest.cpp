/* hslam tests: JSON and table output of an evaluation. */
#include <gtest/gtest.h>
#include <hslam/eval/evaluation_json.h>
#include <hslam/eval/evaluation_table.h>
#include <hslam/testing/temp_dir.h>

#include <mrpt/containers/yaml.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "trajectory_fixtures.h"

using namespace hslam::eval;

namespace
{
/** 3 m straight line, estimate 1 cm to the side: 5 m RPE has no pairs. */
TTrajectoryErrors shortRunErrors()
{
	const auto ref = fixtures::straightLine(31, 0.1);
	auto est = fixtures::transformed(ref, mrpt::poses::CPose2D(0, 0.01, 0));
	est[10].pose.x += 0.05;
	TEvaluationOptions options;
	options.reference_label = "dir/ref \"quoted\".tum";
	return evaluateTrajectory(ref, est, options);
}

}  // namespace

TEST(EvaluationJson, HasRequiredKeysAndParses)
{
	const TTrajectoryErrors e = shortRunErrors();
	const std::string json = evaluationToJson(e);
	for (const char* key : {"matched", "ate_rmse_m", "ate_mean_m", "ate_max_m", "rpe_consecutive_trans_rmse_m",
							"rpe_consecutive_rot_rmse_deg", "rpe_consecutive_pairs", "rpe_1m_trans_rmse_m",
							"rpe_1m_rot_rmse_deg", "rpe_1m_trans_mean_m", "rpe_1m_pairs", "rpe_5m_trans_rmse_m",
							"rpe_5m_rot_rmse_deg", "rpe_5m_pairs", "unmatched_estimate", "unmatched_reference"})
		EXPECT_NE(json.find(std::string("\"") + key + "\": "), std::string::npos) << key << " missing in\n" << json;

	const auto doc = mrpt::containers::yaml::FromText(json);  // MRPT's parser reads JSON too
	EXPECT_EQ(doc["matched"].as<int>(), 31);
	EXPECT_EQ(doc["rpe_1m_pairs"].as<int>(), 21);
	EXPECT_EQ(doc["rpe_5m_pairs"].as<int>(), 0);
	EXPECT_NEAR(doc["ate_rmse_m"].as<double>(), e.ate.position_m.rmse, 1e-9);
	EXPECT_NEAR(doc["rpe_1m_trans_rmse_m"].as<double>(), e.rpe[1].errors.trans_m.rmse, 1e-9);
	EXPECT_EQ(doc["reference"].as<std::string>(), "dir/ref \"quoted\".tum");
	EXPECT_NE(json.find("\"rpe_5m_trans_rmse_m\": null"), std::string::npos);
	EXPECT_NE(json.find("\"rpe_5m_rot_rmse_deg\": null"), std::string::npos);
}

TEST(EvaluationJson, WritesFileAndNamesUnwritablePath)
{
	hslam::testing::CTempDir dir;
	const TTrajectoryErrors e = shortRunErrors();
	writeEvaluationJson(dir.file("e.json"), e);
	std::ifstream in(dir.file("e.json"));
	std::stringstream text;
	text << in.rdbuf();
	EXPECT_EQ(text.str(), evaluationToJson(e));
	try
	{
		writeEvaluationJson(dir.file("no/such/dir/e.json"), e);
		FAIL();
	}
	catch (const std::runtime_error& err)
	{
		EXPECT_NE(std::string(err.what()).find("no/such/dir/e.json"), std::string::npos);
	}
}

TEST(EvaluationTable, ShowsFiguresAndMissingPairsWithoutTouchingStreamFlags)
{
	std::ostringstream os;
	os << std::setprecision(2);
	printEvaluation(os, shortRunErrors());
	const std::string table = os.str();
	for (const char* part : {"matched   31 poses", "ATE", "consecutive", "1m", "5m", "within 0.02 s", "never covers 5 m"})
		EXPECT_NE(table.find(part), std::string::npos) << part << " not in\n" << table;
	EXPECT_EQ(os.precision(), 2);
	EXPECT_FALSE(os.flags() & std::ios::fixed);
}
