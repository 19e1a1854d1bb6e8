// Each `tetglow` subcommand lives in its own file and registers itself here.
#pragma once
#include <charconv>
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "base/OutputFile.h"   // prepareOutput: every command checks its outputs with it
#include "scene/JsonReader.h"  // Range

namespace tetglow::cli {

void addInitCommand(CLI::App& app);
void addTetrahedralizeCommand(CLI::App& app);
void addGenerateCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addDiffCommand(CLI::App& app);
void addValidateCommand(CLI::App& app);
void addCompareBoundaryCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);
void addPreviewCommand(CLI::App& app);
void addMergeCommand(CLI::App& app);
void addFarmCommand(CLI::App& app);

// Every subcommand, in the order `tetglow --help` lists them, one of them required (for main
// and the command-line fuzzer).
inline void addCommands(CLI::App& app) {
    app.require_subcommand(1);
    addInitCommand(app);
    addTetrahedralizeCommand(app);
    addGenerateCommand(app);
    addRenderCommand(app);
    addDiffCommand(app);
    addValidateCommand(app);
    addCompareBoundaryCommand(app);
    addConvertCommand(app);
    addPreviewCommand(app);
    addMergeCommand(app);
    addFarmCommand(app);
}

// The first argument CLI11 would report badly, as a one-line message ("" when there is none): an
// unknown subcommand (CLI11 says only "A subcommand is required") or an unknown option (CLI11
// checks the other arguments first, so `render --frob x` was reported as a missing file "x").
std::string unknownArgument(CLI::App& app, int argc, char** argv);

// A number in `range` (the ranges scene files use), said in plain numbers:
//   --step: expected a finite positive number, got '-1'
// CLI11's own range checks let NaN through and print the largest double in full.
inline CLI::Validator inRange(const Range& range) {
    return {[range](std::string& s) -> std::string {
                double v = 0;
                if (!CLI::detail::lexical_cast(s, v) || !range.contains(v))
                    return "expected a " + range.describe() + ", got '" + shorten(s) + "'";
                return {};
            },
            range.describe()};
}
inline const CLI::Validator kFinite = inRange({});

// An integer in lo..hi, said in plain numbers (CLI11's own checks pass a value that then fails
// to convert, or say only that it did not):
//   --seed: expected an integer in 0..9223372036854775807, got '9223372036854775808'
inline CLI::Validator inIntegers(int64_t lo, int64_t hi) {
    const std::string range = std::to_string(lo) + ".." + std::to_string(hi);
    return {[lo, hi, range](std::string& s) -> std::string {
                int64_t v = 0;
                const char* end = s.data() + s.size();
                const auto read = std::from_chars(s.data(), end, v);
                if (read.ec != std::errc() || read.ptr != end || v < lo || v > hi)
                    return "expected an integer in " + range + ", got '" + shorten(s) + "'";
                return {};
            },
            "INTEGER in " + range};
}

// An empty value would read as "not given" and be ignored.
inline const CLI::Validator kNonEmpty{
    [](std::string& s) { return s.empty() ? std::string("expected a value, got ''") : std::string(); }, "NONEMPTY"};

}  // namespace tetglow::cli
