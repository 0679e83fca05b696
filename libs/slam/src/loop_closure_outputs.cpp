#include <hslam/slam/loop_closure_outputs.h>

#include <fstream>
#include <stdexcept>

namespace hslam::slam
{
void printLoopClosureTiming(const CLoopClosureStage& stage, std::ostream& out)
{
	const auto& t = stage.backend().timing();
	size_t rejected = 0;
	for (const auto& c : stage.backend().closures()) rejected += c.accepted ? 0 : 1;
	out << "Loop closure back-end (libs/graph):\n"
		<< "  keyframes:              " << t.keyframes << "\n"
		<< "  closures tested:        " << t.candidates_tested << " (accepted " << t.closures_accepted
		<< ", rejected " << rejected << ")\n"
		<< "  optimisations:          " << t.optimizations << "\n"
		<< "  back-end total ms:      " << t.total_ms << " (detection " << t.detect_ms << ", optimisation "
		<< t.optimize_ms << ")\n"
		<< "  max ms per keyframe:    " << t.max_keyframe_ms << "\n"
		<< "  max ms per optimisation: " << t.max_optimize_ms << "\n";
}

void writeLoopClosureOutputs(const CMappingPipeline& pipeline, const std::string& dir,
							 std::vector<std::string>& written)
{
	const CLoopClosureStage* stage = pipeline.loopClosureStage();
	if (!stage) return;
	common::writeTumFile(dir + "/trajectory_online.tum", pipeline.trajectory());
	written.push_back(dir + "/trajectory_online.tum");

	const std::string csvPath = dir + "/loop_closures.csv";
	std::ofstream csv(csvPath);
	csv << graph::loopClosureCsvHeader() << '\n';
	for (const auto& c : stage->backend().closures()) csv << graph::loopClosureCsvRow(c) << '\n';
	if (!csv) throw std::runtime_error(csvPath + ": cannot write");
	written.push_back(csvPath);

	stage->backend().graph().saveGraphFile(dir + "/graph.graph");
	written.push_back(dir + "/graph.graph");

	std::ofstream timing(dir + "/timing.txt", std::ios::app);
	timing << '\n';
	printLoopClosureTiming(*stage, timing);
	timing << "  map re-rendered from the optimised graph: " << (pipeline.mapRerendered() ? "yes" : "no") << "\n";
	if (!timing) throw std::runtime_error(dir + "/timing.txt: cannot append");
}

}  // namespace hslam::slam
