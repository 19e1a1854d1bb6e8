// The Slurm batch scripts of `tetglow farm`: one job that fills the tet cache, a job array with
// one task per frame x part, and a merge job after all of them.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace tetglow::cli {

struct FarmPlan {
    std::string binary, scene;              // absolute paths
    std::vector<std::string> renderArgs;    // the render options as given, handed on to every task
    int totalPasses = 1, parts = 1, cpusPerTask = 1;
    int firstFrame = 0, frames = 1;         // frames firstFrame .. firstFrame + frames - 1
    std::vector<std::string> outputs;       // per frame
    std::vector<std::string> inputs;        // every file the scene reads: no output may name one
    std::string workDir, partition;         // partition "": the cluster's default
    std::pair<int, int> passRange(int part) const;  // part p of `parts`: passes as even as can be
    std::string partPath(int frame, int part) const;
    int tasks() const { return frames * parts; }
};

struct BatchScripts {
    std::string prepare, render, merge;
};

// The merge job writes its exit status to this file (the last thing it does).
std::string mergeStatusPath(const FarmPlan& plan);
BatchScripts batchScripts(const FarmPlan& plan);

// `s` quoted for bash.
std::string shellQuote(const std::string& s);

}  // namespace tetglow::cli
