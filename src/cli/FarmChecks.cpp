#include "cli/FarmChecks.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "base/Error.h"

namespace tetglow::cli {
namespace {

bool isControl(char c) { return (unsigned char)c < 0x20 || c == 0x7f; }

// The value as it would be typed, control characters as \n, \t or \xNN, so that it prints on one line.
std::string visible(const std::string& s) {
    std::string v;
    for (char c : s) {
        if (c == '\n')
            v += "\\n";
        else if (c == '\t')
            v += "\\t";
        else if (isControl(c)) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", (unsigned char)c);
            v += hex;
        } else
            v += c;
    }
    return shorten(v);
}

CLI::Validator matching(const std::string& pattern, const std::string& description) {
    const std::regex re(pattern);
    return {[re, description](std::string& s) {
                return std::regex_match(s, re) ? std::string()
                                               : "expected " + description + ", got '" + visible(s) + "'";
            },
            ""};
}

// What farm writes into every script itself, or has an option of its own for: a --sbatch-arg
// naming one of these (or a prefix of one, which sbatch would take for it) is refused.
const char* const kFarmSets[] = {
    "--array",   "--output", "--error", "--dependency", "--job-name", "--cpus-per-task",      "--partition",
    "--account", "--time",   "--mem",   "--wrap",       "--parsable", "--kill-on-invalid-dep"};

}  // namespace

CLI::Validator slurmName(bool list) {
    return list ? matching("[A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*",
                           "names of letters, digits, '_', '-' and '.', separated by commas")
                : matching("[A-Za-z0-9_.-]+", "a name of letters, digits, '_', '-' and '.'");
}

const CLI::Validator kWalltime =
    matching("[0-9]+(:[0-9]+){0,2}|[0-9]+-[0-9]+(:[0-9]+){0,2}|UNLIMITED|INFINITE",
             "a Slurm time limit (MIN, MIN:SEC, H:MIN:SEC, D-H, D-H:MIN, D-H:MIN:SEC or UNLIMITED)");
const CLI::Validator kMemory =
    matching("[0-9]+[KMGTkmgt]?", "memory per node as sbatch --mem takes it (e.g. 4000, 500M, 16G)");

const CLI::Validator kSbatchArg{
    [](std::string& s) -> std::string {
        const std::string v = visible(s);
        if (!std::regex_match(s, std::regex("--[A-Za-z][A-Za-z0-9-]*(=.*)?")) ||
            std::any_of(s.begin(), s.end(), isControl))
            return "expected one long option of sbatch's, --NAME or --NAME=VALUE on one line, got '" + v + "'";
        const std::string name = s.substr(0, s.find('='));
        for (const std::string reserved : kFarmSets)
            if (reserved.starts_with(name))
                return "'" + v + "': farm sets " + reserved + " itself" +
                       (reserved == "--time" || reserved == "--mem" || reserved == "--partition" ||
                                reserved == "--account" || reserved == "--cpus-per-task"
                            ? " (give farm " + reserved + ")"
                            : "");
        return {};
    },
    ""};

void checkScriptText(const std::string& what, const std::string& value, bool logFolder) {
    if (std::any_of(value.begin(), value.end(), isControl))
        throw InputError("farm: " + what + " '" + visible(value) +
                         "' holds a control character: refusing to write it into a batch script");
    if (logFolder && value.find('\\') != std::string::npos)
        throw InputError(
            "farm: " + what + " '" + visible(value) +
            "' holds a backslash, which turns off Slurm's file name patterns (task-%a.log): choose another folder");
}

void checkPreambleText(const std::string& path, const std::string& text) {
    const auto bad =
        std::find_if(text.begin(), text.end(), [](char c) { return c != '\n' && c != '\t' && isControl(c); });
    if (bad != text.end())
        throw InputError("farm: " + path + ": line " + std::to_string(std::count(text.begin(), bad, '\n') + 1) +
                         " holds a control character other than a tab: refusing to write it into a batch script");
}

std::string localPathWarning(const std::string& what, const std::string& path, std::istream& mounts) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    if (ec) p = path;
    const std::string s = p.string();
    auto under = [&](const std::string& dir) { return s == dir || s.starts_with(dir + "/"); };
    std::string why;
    for (const char* dir : {"/tmp", "/var/tmp", "/dev/shm"})
        if (under(dir)) why = std::string("in ") + dir;
    // The longest mount point that holds the path says which file system it is on.
    std::string line, device, mountPoint, type, deepest, deepestType;
    while (std::getline(mounts, line)) {
        std::istringstream fields(line);
        if (fields >> device >> mountPoint >> type && (mountPoint == "/" || under(mountPoint)) &&
            mountPoint.size() >= deepest.size()) {
            deepest = mountPoint;
            deepestType = type;
        }
    }
    if (deepestType == "tmpfs" || deepestType == "ramfs")
        why += (why.empty() ? "on " : ", on ") + deepestType + " " + deepest;
    if (why.empty()) return {};
    return "farm: warning: " + what + " " + s + " lies " + why +
           ", which is local to each node: tasks on other nodes will not see it";
}

std::string localPathWarning(const std::string& what, const std::string& path) {
    std::ifstream mounts("/proc/mounts");
    return localPathWarning(what, path, mounts);
}

}  // namespace tetglow::cli
