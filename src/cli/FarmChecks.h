// What `tetglow farm` lets into a batch script, checked before anything is written: a value no
// user needs there (a newline in a path or a partition name) is refused with one line rather
// than escaped, and a path that the nodes may not share is warned about.
#pragma once
#include <istream>
#include <string>

#include <CLI/CLI.hpp>

namespace tetglow::cli {

// Option checks, each saying what is allowed.
CLI::Validator slurmName(bool list);     // partition (list: comma-separated), account
extern const CLI::Validator kWalltime;   // sbatch --time: MIN, MIN:SEC, H:MIN:SEC, D-H, D-H:MIN, D-H:MIN:SEC, UNLIMITED
extern const CLI::Validator kMemory;     // sbatch --mem: a number with an optional K, M, G or T
extern const CLI::Validator kSbatchArg;  // one long option of sbatch's, not one farm sets itself

// InputError "farm: <what> '<value>' holds a control character ..." for a path or value written
// into a script; `logFolder` also refuses a backslash, which turns off Slurm's patterns in
// --output (every task would write one log named task-%a.log).
void checkScriptText(const std::string& what, const std::string& value, bool logFolder = false);

// InputError "farm: <path>: line 3 holds a control character ..." for a --preamble file: shell
// lines, with tabs and newlines only (a carriage return would end up in every command it ends).
void checkPreambleText(const std::string& path, const std::string& text);

// "" or a warning that `path` lies where other nodes do not see it (/tmp, /var/tmp, a tmpfs),
// the file systems read from `mounts` (lines as /proc/mounts gives them: DEVICE MOUNT-POINT TYPE
// ...), or from /proc/mounts itself.
std::string localPathWarning(const std::string& what, const std::string& path, std::istream& mounts);
std::string localPathWarning(const std::string& what, const std::string& path);

}  // namespace tetglow::cli
