// The Slurm batch scripts of `tetglow farm`: one job that fills the tet cache, a job array with
// one task per frame x part, and a merge job after all of them. Two parsers read each script:
// sbatch reads the #SBATCH lines (its own quoting: a backslash escapes the next character even
// inside single quotes, and `%` in --output is a pattern), bash reads the rest. Every value is
// quoted for the parser that reads its line; checkScriptValue (FarmChecks.h) refuses what
// neither needs.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tetglow::cli {

// What every job is submitted with, beside what farm sets itself.
struct SbatchOptions {
    std::string partition, account, walltime, memory;  // "": the cluster's default
    std::vector<std::string> extra;                    // --sbatch-arg: long options, passed on as given
};

struct FarmPlan {
    std::string binary, scene;            // absolute paths
    std::vector<std::string> renderArgs;  // the render options as given, handed on to every task
    int totalPasses = 1, parts = 1, cpusPerTask = 1;
    int firstFrame = 0, frames = 1;    // frames firstFrame .. firstFrame + frames - 1
    std::vector<std::string> outputs;  // per frame
    std::vector<std::string> inputs;   // every file the scene reads: no output may name one
    std::string workDir;
    SbatchOptions sbatch;
    // Shell lines every job runs first (--preamble, --setup: `module load`, environment), each
    // line ending in a newline; written after the #SBATCH lines, as they are.
    std::string preamble;
    std::pair<int, int> passRange(int part) const;  // part p of `parts`: passes as even as can be
    std::string partPath(int frame, int part) const;
    int64_t tasks() const { return int64_t(frames) * parts; }  // frames and parts are ints: no overflow
};

struct BatchScripts {
    std::string prepare, render, merge;
};

// The merge job writes its exit status to this file (the last thing it does).
std::string mergeStatusPath(const FarmPlan& plan);
BatchScripts batchScripts(const FarmPlan& plan);

// The sbatch command line that submits `script`, after the jobs in `dependency` (Slurm's
// --dependency value, "" for none); `killOnInvalid` cancels the job when a dependency failed.
std::string sbatchCommand(const std::string& script, const std::string& dependency, bool killOnInvalid);

// `s` quoted for bash (single quotes).
std::string shellQuote(const std::string& s);
// `s` quoted for sbatch's #SBATCH parser (double quotes, `\` before `"` and `\`).
std::string sbatchQuote(const std::string& s);
// A path as Slurm's --output pattern that names exactly that path (`%` doubled).
std::string literalOutputPattern(const std::string& path);

}  // namespace tetglow::cli
