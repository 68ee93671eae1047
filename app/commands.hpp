#pragma once
#include <string>
#include <vector>

namespace pbr {

// Each subcommand takes the arguments after its name and returns the process exit code:
// 0 success, 1 failure (bad input file, I/O), 2 usage error, 3 no OpenGL context.
int runRender(const std::vector<std::string>& args);
int runBench(const std::vector<std::string>& args);
int runBenchMerge(const std::vector<std::string>& args);
int runExperiment(const std::vector<std::string>& args);
int runReference(const std::vector<std::string>& args);
int runAccuracy(const std::vector<std::string>& args);
int runView(const std::vector<std::string>& args);

}  // namespace pbr
