#include "cli/FarmScripts.h"

#include <cstdio>

namespace tetglow::cli {
namespace {

std::string sbatchLine(const std::string& option, const std::string& value) {
    return "#SBATCH " + option + "=" + sbatchQuote(value) + "\n";
}

// The #SBATCH lines: sbatch reads them up to the first line that is not a comment, so the
// preamble comes after them.
std::string header(const FarmPlan& plan, const std::string& name, const std::string& log, int cpus) {
    const SbatchOptions& o = plan.sbatch;
    std::string s = "#!/bin/bash\n";
    s += sbatchLine("--job-name", name);
    s += sbatchLine("--output", literalOutputPattern(plan.workDir) + "/" + log);
    s += sbatchLine("--cpus-per-task", std::to_string(cpus));
    for (const auto& [option, value] :
         {std::pair{"--partition", o.partition}, {"--account", o.account}, {"--time", o.walltime}, {"--mem", o.memory}})
        if (!value.empty()) s += sbatchLine(option, value);
    for (const auto& arg : o.extra) s += "#SBATCH " + sbatchQuote(arg) + "\n";
    return s;
}

std::string renderCommand(const FarmPlan& plan) {
    std::string s = shellQuote(plan.binary) + " render " + shellQuote(plan.scene);
    for (const auto& arg : plan.renderArgs) s.append(" ").append(shellQuote(arg));
    return s;
}

const char* const kPartName = "part-%04d-%03d.exr";  // frame, part

std::string range(std::pair<int, int> r) { return std::to_string(r.first) + ":" + std::to_string(r.second); }

std::string escaped(const std::string& s, const std::string& special) {
    std::string q;
    for (char c : s) q += special.find(c) == std::string::npos ? std::string(1, c) : std::string{'\\', c};
    return q;
}

}  // namespace

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string sbatchQuote(const std::string& s) {
    std::string q = "\"";
    q += escaped(s, "\"\\");
    return q + "\"";
}

std::string literalOutputPattern(const std::string& path) {
    std::string p;
    for (char c : path) p += c == '%' ? std::string("%%") : std::string(1, c);
    return p;
}

std::pair<int, int> FarmPlan::passRange(int part) const {
    auto edge = [&](int p) { return int(int64_t(totalPasses) * p / parts); };
    return {edge(part), edge(part + 1)};
}

std::string FarmPlan::partPath(int frame, int part) const {
    char name[64];
    std::snprintf(name, sizeof name, kPartName, frame, part);
    return workDir + "/" + name;
}

std::string mergeStatusPath(const FarmPlan& plan) { return plan.workDir + "/merge.status"; }

std::string sbatchCommand(const std::string& script, const std::string& dependency, bool killOnInvalid) {
    std::string s = "sbatch --parsable";
    if (!dependency.empty()) s += " --dependency=" + dependency;
    if (killOnInvalid) s += " --kill-on-invalid-dep=yes";
    return s + " " + shellQuote(script);
}

BatchScripts batchScripts(const FarmPlan& plan) {
    BatchScripts b;
    // TetGen runs once, here; every task then reads the tets from the cache.
    b.prepare = header(plan, "tetglow-prepare", "prepare.log", 1) + plan.preamble + "exec " + renderCommand(plan) +
                " --tetrahedralize-only\n";

    std::string ranges;
    for (int p = 0; p < plan.parts; ++p) ranges.append(" ").append(range(plan.passRange(p)));
    // The part's name is formatted on its own and appended to the quoted folder: no path is
    // ever a printf format.
    b.render = header(plan, "tetglow-render", "task-%a.log", plan.cpusPerTask) + "#SBATCH --array=0-" +
               std::to_string(plan.tasks() - 1) + "\n" + plan.preamble +
               "# Task i renders part i % parts of frame first + i / parts.\n"
               "ranges=(" +
               ranges +
               " )\n"
               "frame=$((" +
               std::to_string(plan.firstFrame) + " + SLURM_ARRAY_TASK_ID / " + std::to_string(plan.parts) +
               "))\n"
               "part=$((SLURM_ARRAY_TASK_ID % " +
               std::to_string(plan.parts) +
               "))\n"
               "printf -v name '" +
               kPartName +
               "' \"$frame\" \"$part\"\n"
               "exec " +
               renderCommand(plan) + " --threads " + std::to_string(plan.cpusPerTask) +
               " --frame \"$frame\" --pass-range \"${ranges[part]}\" -o " + shellQuote(plan.workDir) + "/\"$name\"\n";

    // Runs after every task, failed or not, so that a failed task fails the merge with its own
    // error instead of leaving the farm waiting or a partial image behind.
    b.merge = header(plan, "tetglow-merge", "merge.log", 1) + plan.preamble +
              "status=0\n"
              "missing() {  # task, its log: the task's own error, else why it did not run\n"
              "  why=$(grep -h error \"$2\" 2>/dev/null | tail -n 1)\n"
              "  cache=$(grep -h error " +
              shellQuote(plan.workDir + "/prepare.log") +
              " 2>/dev/null | tail -n 1)\n"
              "  [ -n \"$why\" ] || why=\"it did not run${cache:+: the tet cache job failed: $cache}\"\n"
              "  echo \"tetglow farm: task $1 wrote no part: $why\" >&2\n"
              "  status=1\n"
              "}\n";
    for (int f = 0; f < plan.frames; ++f) {
        std::string parts;
        for (int p = 0; p < plan.parts; ++p) {
            const int task = f * plan.parts + p;
            const std::string part = shellQuote(plan.partPath(plan.firstFrame + f, p));
            b.merge += "[ -f " + part + " ] || missing " + std::to_string(task) + " " +
                       shellQuote(plan.workDir + "/task-" + std::to_string(task) + ".log") + "\n";
            parts += " " + part;
        }
        b.merge += "[ $status -ne 0 ] || " + shellQuote(plan.binary) + " merge" + parts + " -o " +
                   shellQuote(plan.outputs[size_t(f)]) + " || status=1\n";
    }
    b.merge += "echo $status > " + shellQuote(mergeStatusPath(plan)) + "\nexit $status\n";
    return b;
}

}  // namespace tetglow::cli
