#include <hslam/common/output_folder.h>
#include <hslam/slam/loop_closure_outputs.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hslam::slam
{
std::map<std::string, size_t> rejectedClosuresByReason(const CLoopClosureStage& stage)
{
	std::map<std::string, size_t> counts;
	for (const auto& c : stage.backend().closures())
		if (!c.accepted) ++counts[c.reason];
	return counts;
}

void printLoopClosureTiming(const CLoopClosureStage& stage, std::ostream& out)
{
	const auto& t = stage.backend().timing();
	size_t rejected = 0;
	for (const auto& [reason, n] : rejectedClosuresByReason(stage)) rejected += n;
	out << "Loop closure back-end (libs/graph):\n"
		<< "  keyframes:              " << t.keyframes << "\n"
		<< "  closures tested:        " << t.candidates_tested << " (accepted " << t.closures_accepted
		<< ", rejected " << rejected << ")\n"
		<< "  not tested, little information: " << stage.backend().detector().skippedLittleInformation() << "\n"
		<< "  not tested, low score just before: " << stage.backend().detector().skippedRecentLowScore() << "\n"
		<< "  not tested, widest search low score just before: " << stage.backend().detector().skippedRecentWide()
		<< "\n"
		<< "  optimisations:          " << t.optimizations << " (closures that agreed and waited for one: "
		<< t.closures_deferred << ")\n"
		<< "  back-end total ms:      " << t.total_ms << " (detection " << t.detect_ms << ", optimisation "
		<< t.optimize_ms << ")\n"
		<< "  max ms per keyframe:    " << t.max_keyframe_ms << "\n"
		<< "  max ms per optimisation: " << t.max_optimize_ms << "\n";
}

size_t drawLoopClosures(mrpt::img::CImage& image, const maps::TImageFrame& frame, const CLoopClosureStage& stage)
{
	const auto& nodes = stage.backend().graph().nodes();
	const auto& closures = stage.backend().closures();
	const mrpt::img::TColor rejected{80, 80, 255}, accepted{0, 180, 0}, dropped{255, 140, 0};
	size_t drawn = 0;
	for (const bool verifiedPass : {false, true})
		for (const auto& c : closures)
		{
			const bool wasDropped = c.reason == "dropped by optimiser", verified = c.accepted || wasDropped;
			if (verified != verifiedPass || c.query_node >= nodes.size() || c.anchor_node >= nodes.size()) continue;
			double x0, y0, x1, y1;
			frame.worldToPixel(nodes[c.anchor_node].pose.x, nodes[c.anchor_node].pose.y, x0, y0);
			frame.worldToPixel(nodes[c.query_node].pose.x, nodes[c.query_node].pose.y, x1, y1);
			image.line(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1), static_cast<int>(y1),
					   c.accepted ? accepted : wasDropped ? dropped : rejected, verified ? 2 : 1);
			++drawn;
		}
	return drawn;
}

void writeLoopClosureOutputs(const CMappingPipeline& pipeline, const std::string& dir,
							 std::vector<std::string>& written)
{
	const CLoopClosureStage* stage = pipeline.loopClosureStage();
	if (!stage) return;
	common::writeTumFile(dir + "/trajectory_online.tum", pipeline.trajectory());
	written.push_back(dir + "/trajectory_online.tum");

	const std::string csvPath = dir + "/loop_closures.csv";
	common::writeStreamAtomically(csvPath, [stage](std::ostream& csv) {
		csv << graph::loopClosureCsvHeader() << '\n';
		for (const auto& c : stage->backend().closures()) csv << graph::loopClosureCsvRow(c) << '\n';
	});
	written.push_back(csvPath);

	common::writeStreamAtomically(dir + "/graph.graph",
								  [stage](std::ostream& out) { stage->backend().graph().writeGraphText(out); });
	written.push_back(dir + "/graph.graph");

	// timing.txt (written just before) gets the back-end's lines appended; the
	// whole file is rewritten atomically.
	std::ifstream before(dir + "/timing.txt");
	std::ostringstream text;
	text << before.rdbuf() << '\n';
	printLoopClosureTiming(*stage, text);
	text << "  map re-rendered from the optimised graph: " << (pipeline.mapRerendered() ? "yes" : "no") << "\n";
	common::writeTextFileAtomically(dir + "/timing.txt", text.str());
}

}  // namespace hslam::slam
