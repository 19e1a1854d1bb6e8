// Each `tetglow` subcommand lives in its own file and registers itself here.
#pragma once
#include <cmath>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

namespace tetglow::cli {

void addTetrahedralizeCommand(CLI::App& app);
void addGenerateCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addDiffCommand(CLI::App& app);
void addValidateCommand(CLI::App& app);
void addCompareBoundaryCommand(CLI::App& app);
void addConvertCommand(CLI::App& app);

// Every subcommand, in the order `tetglow --help` lists them, one of them required (for main
// and the command-line fuzzer).
inline void addCommands(CLI::App& app) {
    app.require_subcommand(1);
    addTetrahedralizeCommand(app);
    addGenerateCommand(app);
    addRenderCommand(app);
    addDiffCommand(app);
    addValidateCommand(app);
    addCompareBoundaryCommand(app);
    addConvertCommand(app);
}

// Creates the folder an output file goes into, if it names one.
inline void createParentFolder(const std::string& path) {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
}

// CLI11's range checks let NaN through (every comparison with NaN is false).
inline const CLI::Validator kFinite{[](std::string& s) -> std::string {
                                        double v = 0;
                                        if (!CLI::detail::lexical_cast(s, v) || !std::isfinite(v))
                                            return "value must be a finite number, got '" + s + "'";
                                        return {};
                                    },
                                    "FINITE"};

}  // namespace tetglow::cli
