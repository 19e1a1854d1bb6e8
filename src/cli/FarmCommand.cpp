// tetglow farm SCENE --parts N -o OUT.exr: the render split over a Slurm job array and merged
// (FarmScripts.h). Slurm's sbatch and squeue do all the scheduling.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <thread>

#include "base/InputFile.h"
#include "base/OutputFile.h"
#include "cli/Commands.h"
#include "cli/FarmChecks.h"
#include "cli/FarmScripts.h"
#include "cli/MediaReport.h"
#include "cli/RenderArgs.h"
#include "tet/CacheDirectory.h"
#include "tet/TriangleMesh.h"

namespace tetglow::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
    RenderArgs args;
    std::vector<CLI::Option*> renderOptions;
    std::string output, frames;
    SbatchOptions sbatch;
    int parts = 0, cpusPerTask = 1;
    bool wait = false, dryRun = false;
    int maxArray = 0;  // 0: the cluster's MaxArraySize
    std::string preamble;
    std::vector<std::string> setup;
};

// stdout of a shell command, and its exit status.
std::pair<std::string, int> capture(const std::string& command) {
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) throw InputError("farm: cannot run " + command);
    std::string out;
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    const int status = ::pclose(pipe);
    return {out, WIFEXITED(status) ? WEXITSTATUS(status) : 128};
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

std::string lastLine(std::string s) {
    while (!s.empty() && s.back() == '\n') s.pop_back();
    return s.substr(s.rfind('\n') + 1);
}

// Submits a script (sbatchCommand); returns the job id.
std::string submit(const std::string& script, const std::string& dependency, bool killOnInvalid) {
    const std::string command = sbatchCommand(script, dependency, killOnInvalid);
    const auto [out, status] = capture(command);
    const std::string dryRun = ": where Slurm is not set up, --dry-run prints the scripts and the sbatch commands";
    if (status == 127) throw InputError("farm: sbatch not found (" + command + ")" + dryRun);
    if (status != 0) throw InputError("farm: " + command + " failed: " + lastLine(out) + dryRun);
    const std::string id = lastLine(out);  // "id" or "id;cluster", after any warnings
    return id.substr(0, id.find(';'));
}

constexpr int kSlurmDefaultMaxArraySize = 1001;

// The most tasks a job array may have: --max-array, else the cluster's MaxArraySize (the
// largest task index is one less), else Slurm's default; and where that number comes from.
std::pair<int64_t, std::string> maxArraySize(int given) {
    if (given > 0) return {given, "--max-array"};
    const auto [out, status] = capture("timeout 10 scontrol show config");
    std::smatch m;
    if (status == 0 && std::regex_search(out, m, std::regex("MaxArraySize\\s*=\\s*([0-9]{1,9})")))
        return {std::stoll(m[1]), "the cluster's MaxArraySize, from scontrol show config"};
    return {kSlurmDefaultMaxArraySize, "Slurm's default MaxArraySize"};
}

// The shell lines every job runs first: the --preamble file, then each --setup line.
std::string preamble(const Options& o) {
    std::string text;
    if (!o.preamble.empty()) {
        text = readInputFile(o.preamble, kMaxSceneFileBytes, "a farm preamble");
        checkPreambleText(o.preamble, text);
        if (!text.empty() && text.back() != '\n') text += '\n';
    }
    for (const auto& line : o.setup) {
        checkScriptText("the --setup line", line);
        text += line + "\n";
    }
    return text;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Frame outputs: OUT itself for a still, OUT's stem with a 4-digit frame number for an animation.
std::string frameOutput(const std::string& output, int frame, bool animated) {
    if (!animated) return output;
    char number[16];
    std::snprintf(number, sizeof number, ".%04d", frame);
    return fs::path(output).replace_extension().string() + number + ".exr";
}

FarmPlan plan(const Options& o) {
    const SceneDesc desc = loadSceneWith(o.args);
    if (desc.integrator.timeLimit > 0)
        throw InputError("farm: " + o.args.scene +
                         " renders for a time (\"time\"), which cannot be split into parts: give --spp or --passes");
    printRepairs(desc);  // what every task's render would say, said once here
    const std::string given = o.output.empty() ? defaultOutput(o.args, desc) : o.output;
    if (fs::path(given).extension() != ".exr") throw InputError(given + ": the output must be an .exr file");
    FarmPlan p;
    p.binary = fs::read_symlink("/proc/self/exe").string();
    p.scene = fs::absolute(o.args.scene).string();
    for (const CLI::Option* option : o.renderOptions)
        for (const auto& value : option->results())
            p.renderArgs.insert(p.renderArgs.end(), {option->get_name(), value});
    p.totalPasses = desc.integrator.spp;
    p.inputs = desc.inputs;
    if (o.parts > p.totalPasses)
        throw InputError("farm: --parts " + std::to_string(o.parts) + " is more than the " +
                         std::to_string(p.totalPasses) + " passes to split");
    p.parts = o.parts;
    p.cpusPerTask = o.cpusPerTask;
    const int frames = desc.turntable.frames;
    const auto [first, end] =
        o.frames.empty() ? std::pair{0, frames} : parseRange("--frames", o.frames, frames, "frames");
    p.firstFrame = first;
    p.frames = end - first;
    if (const auto [most, source] = maxArraySize(o.maxArray); p.tasks() > most)
        throw InputError("farm: " + std::to_string(p.tasks()) + " tasks (" + std::to_string(p.frames) + " frame(s) x " +
                         std::to_string(p.parts) + " parts) are more than the " + std::to_string(most) +
                         " a job array may have (" + source + "): give fewer --parts or --frames" +
                         (o.maxArray > 0 ? "" : ", or --max-array N where the cluster allows more"));
    const std::string output = fs::absolute(given).string();
    for (int f = first; f < end; ++f) p.outputs.push_back(frameOutput(output, f, frames > 1));
    p.workDir = fs::path(output).replace_extension(".farm").string();
    p.sbatch = o.sbatch;
    p.preamble = preamble(o);
    checkScriptText("the tetglow binary", p.binary);
    checkScriptText("the scene path", p.scene);
    checkScriptText("the output path", output, true);
    for (const auto& arg : p.renderArgs) checkScriptText("the render option", arg);
    return p;
}

// The parts, the output and the tet cache must be where every node reads and writes the same files.
void warnAboutLocalPaths(const FarmPlan& p) {
    for (const auto& [what, path] : {std::pair{"the output", p.outputs.front()},
                                     {"the parts' folder", p.workDir},
                                     {"the tet cache", cacheDirectory().string()}})
        if (const std::string warning = path.empty() ? "" : localPathWarning(what, path); !warning.empty())
            std::fprintf(stderr, "%s\n", warning.c_str());
}

// Polls squeue (faster than sbatch --wait) until the job has left the queue or ended.
void waitFor(const std::string& job) {
    for (;;) {
        const auto [out, status] = capture("squeue -h -j " + job + " -o %T");
        const std::string state = firstLine(out);
        if (status != 0 || state.empty() ||
            (state != "PENDING" && state != "RUNNING" && state != "CONFIGURING" && state != "COMPLETING"))
            return;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
}

void run(const Options& o) {
    const FarmPlan p = plan(o);
    const BatchScripts scripts = batchScripts(p);
    const std::string prepare = p.workDir + "/prepare.sh", render = p.workDir + "/render.sh",
                      merge = p.workDir + "/merge.sh";
    // Each job after the ones it needs: the array only when the cache is filled, the merge after everything.
    auto renderAfter = [](const std::string& prepareJob) { return "afterok:" + prepareJob; };
    auto mergeAfter = [](const std::string& prepareJob, const std::string& renderJob) {
        return "afterany:" + prepareJob + ":" + renderJob;
    };
    warnAboutLocalPaths(p);
    if (o.dryRun) {
        std::printf(
            "# %s\n%s\n# %s (after %s)\n%s\n# %s (after every task)\n%s\n"
            "# Submitted with these commands, each job's id in place of $prepare and $render:\n"
            "prepare=$(%s)\nrender=$(%s)\n%s\n",
            prepare.c_str(), scripts.prepare.c_str(), render.c_str(), prepare.c_str(), scripts.render.c_str(),
            merge.c_str(), scripts.merge.c_str(), sbatchCommand(prepare, "", false).c_str(),
            sbatchCommand(render, renderAfter("$prepare"), true).c_str(),
            sbatchCommand(merge, mergeAfter("$prepare", "$render"), false).c_str());
        return;
    }
    for (const auto& output : p.outputs) prepareOutput(output, p.inputs);
    for (const auto& script : {prepare, render, merge}) prepareOutput(script, p.inputs);
    // Parts and status of an earlier run must not stand in for this one's.
    std::error_code ignored;
    for (int f = 0; f < p.frames; ++f)
        for (int part = 0; part < p.parts; ++part) fs::remove(p.partPath(p.firstFrame + f, part), ignored);
    fs::remove(mergeStatusPath(p), ignored);
    for (const auto& script : {std::pair{prepare, scripts.prepare}, {render, scripts.render}, {merge, scripts.merge}})
        writeStream(script.first, [&](std::ostream& out) { out << script.second; });
    // A job submitted before another's submission failed would run for nothing: it is cancelled.
    std::vector<std::string> submitted;
    const auto submitAfter = [&](const std::string& script, const std::string& dependency, bool killOnInvalid) {
        try {
            submitted.push_back(submit(script, dependency, killOnInvalid));
            return submitted.back();
        } catch (const InputError&) {
            for (const auto& job : submitted) capture("scancel " + job);
            throw;
        }
    };
    const std::string prepareJob = submitAfter(prepare, "", false);
    const std::string renderJob = submitAfter(render, renderAfter(prepareJob), true);
    const std::string mergeJob = submitAfter(merge, mergeAfter(prepareJob, renderJob), false);
    std::printf(
        "farm: submitted job %s (tet cache), array %s (%lld tasks: %d frame(s) x %d parts), merge %s -> %s%s\n"
        "farm: scripts and logs in %s; watch with: squeue -j %s,%s,%s\n",
        prepareJob.c_str(), renderJob.c_str(), (long long)p.tasks(), p.frames, p.parts, mergeJob.c_str(),
        p.outputs.front().c_str(), p.frames > 1 ? " ..." : "", p.workDir.c_str(), prepareJob.c_str(), renderJob.c_str(),
        mergeJob.c_str());
    if (!o.wait) return;
    std::fflush(stdout);
    waitFor(mergeJob);
    const std::string status = slurp(mergeStatusPath(p));
    if (status != "0\n") {
        const std::string log = slurp(p.workDir + "/merge.log");
        throw InputError("farm: the merge job " + mergeJob +
                         (status.empty() ? " ended without a status (cancelled?)" : " failed") +
                         (log.empty() ? std::string() : ": " + firstLine(log)));
    }
    std::printf("farm: done: %s\n", p.outputs.back().c_str());
}

}  // namespace

void addFarmCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "farm", "Render on a Slurm cluster: a job array of parts (render --pass-range) and a merge job");
    o->renderOptions = addRenderArgs(cmd, o->args);
    // render's --time cannot be split into parts, and each task's threads are its --cpus-per-task:
    // farm's own options take those names.
    std::erase_if(o->renderOptions, [&](CLI::Option* option) {
        return (option->check_name("--time") || option->check_name("--threads")) && cmd->remove_option(option);
    });
    cmd->add_option("--parts", o->parts, "Parts to split the passes of each frame into (one array task each)")
        ->required()
        ->check(CLI::Range(1, 100000));
    cmd->add_option("-o,--output", o->output,
                    "Output .exr (an animation: OUT.0000.exr, OUT.0001.exr, ...; default: the scene's \"output\", "
                    "else SCENE.exr)")
        ->check(kNonEmpty);
    cmd->add_option("--frames", o->frames, "Frames A..B-1 of the scene's turntable (A:B; default: all)");
    cmd->add_option("--cpus-per-task,--threads", o->cpusPerTask,
                    "Cores Slurm gives each task, and its render threads (default 1)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--partition", o->sbatch.partition, "Slurm partition(s), comma-separated (default: the cluster's)")
        ->check(slurmName(true));
    cmd->add_option("--account", o->sbatch.account, "Slurm account the jobs are charged to (default: yours)")
        ->check(slurmName(false));
    cmd->add_option(
           "--time", o->sbatch.walltime,
           "Time limit of each job as sbatch --time takes it, e.g. 90 or 1-12:00:00 (default: the partition's)")
        ->check(kWalltime);
    cmd->add_option("--mem", o->sbatch.memory,
                    "Memory per node of each job as sbatch --mem takes it, e.g. 8G (default: the partition's)")
        ->check(kMemory);
    cmd->add_option("--sbatch-arg", o->sbatch.extra,
                    "One more sbatch option for every job, as --sbatch-arg=--NAME=VALUE (repeatable)")
        ->allow_extra_args(false)  // one value each time: the scene after it stays the scene
        ->check(kSbatchArg);
    cmd->add_option("--max-array", o->maxArray,
                    "The most tasks a job array may have (default: the cluster's MaxArraySize from scontrol show "
                    "config, else Slurm's default 1001)")
        ->check(CLI::Range(1, 4000001));
    cmd->add_option("--preamble", o->preamble,
                    "A file of shell lines every job runs first (module load, environment), written into each script")
        ->check(kNonEmpty);
    cmd->add_option(
           "--setup", o->setup,
           "One shell line every job runs first, after --preamble, e.g. --setup 'module load gcc' (repeatable)")
        ->allow_extra_args(false);
    cmd->add_flag("--wait", o->wait, "Return when the merge is done; exit 1 if any task or the merge failed");
    cmd->add_flag("--dry-run", o->dryRun, "Print the batch scripts and the sbatch commands, submit nothing");
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
