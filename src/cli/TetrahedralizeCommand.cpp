// tetglow tetrahedralize MESH [-o FILE] [--json]: validate, tetrahedralize, report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string mesh, output;
    bool json = false, noCache = false;
    TetOptions tet;
};

void writeVtk(const TetMesh& m, std::ostream& out) {
    out.precision(9);
    out << "# vtk DataFile Version 3.0\ntetglow tetrahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << m.vertices.size() << " double\n";
    for (const auto& v : m.vertices) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
    out << "CELLS " << m.tets.size() << ' ' << 5 * m.tets.size() << '\n';
    for (const auto& t : m.tets) out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    out << "CELL_TYPES " << m.tets.size() << '\n';
    for (size_t i = 0; i < m.tets.size(); ++i) out << "10\n";
}

void run(const Options& o) {
    if (!o.output.empty()) prepareOutput(o.output, {o.mesh});
    std::vector<std::string> warnings;
    TriangleMesh surface = readMesh(o.mesh, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "tetglow: warning: %s\n", w.c_str());
    TetOptions tetOptions = o.tet;
    tetOptions.useCache = !o.noCache;
    TetStats stats;
    ValidationReport report;
    const TetMesh mesh = tetrahedralize(std::move(surface), tetOptions, &stats, &report);
    const double tetVolume = mesh.volume(), meshVolume = report.volume;
    const double relError = std::abs(tetVolume - meshVolume) / meshVolume;
    if (!o.output.empty()) {
        const std::string ext = std::filesystem::path(o.output).extension().string();
        if (ext == ".vtk")
            writeStream(o.output, [&](std::ostream& out) { writeVtk(mesh, out); });
        else
            writeAtomically(o.output, [&](const std::string& temporary) { writeTetMesh(mesh, 0, temporary); });
    }
    const size_t steiner = mesh.vertices.size() - mesh.surfaceVertexCount;
    if (o.json) {
        nlohmann::json j = {{"mesh", o.mesh},
                            {"switches", tetOptions.switches()},
                            {"tets", mesh.tets.size()},
                            {"vertices", mesh.vertices.size()},
                            {"steiner_points", steiner},
                            {"boundary_faces", mesh.surface.size()},
                            {"components", report.components},
                            {"mesh_volume", meshVolume},
                            {"tet_volume", tetVolume},
                            {"volume_relative_error", relError},
                            {"bytes_per_tet", mesh.bytesPerTet()},
                            {"seconds", stats.seconds},
                            {"from_cache", stats.fromCache},
                            {"repairs", report.notes},
                            {"output", o.output}};
        std::cout << j.dump(2) << '\n';
        return;
    }
    std::printf("mesh             %s\n", o.mesh.c_str());
    for (const auto& n : report.notes) std::printf("repaired         %s\n", n.c_str());
    std::printf("tetrahedra       %zu (%zu bytes each + vertices)\n", mesh.tets.size(), mesh.bytesPerTet());
    std::printf("vertices         %zu (%zu Steiner points)\n", mesh.vertices.size(), steiner);
    std::printf("boundary faces   %zu (one per input triangle)\n", mesh.surface.size());
    std::printf("volume           mesh %.12g, tets %.12g, relative difference %.2e\n", meshVolume, tetVolume, relError);
    std::printf("time             %.3f s%s\n", stats.seconds, stats.fromCache ? " (from cache)" : "");
    if (!o.output.empty()) std::printf("written          %s\n", o.output.c_str());
}

}  // namespace

void addTetrahedralizeCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    CLI::App* cmd = app.add_subcommand("tetrahedralize", "Validate a closed mesh and tetrahedralize its interior");
    cmd->add_option("mesh", o->mesh, "Closed triangle mesh (OBJ or OFF)")->required();
    cmd->add_option("-o,--output", o->output, "Write the tet mesh (.vtk: legacy VTK for ParaView; else tetglow's binary)")->check(kNonEmpty);
    cmd->add_flag("--json", o->json, "Print the report as one JSON object");
    cmd->add_option("--quality", o->tet.radiusEdgeRatio, "Radius-edge ratio bound (TetGen -q); adds Steiner points")
        ->check(inRange({.lo = 1, .hi = 1e9}));
    cmd->add_option("--max-volume", o->tet.maxVolume, "Largest tet volume (TetGen -a); adds Steiner points")
        ->check(inRange(kPositive));
    cmd->add_flag("--no-cache", o->noCache, "Always run TetGen, do not read or write the cache");
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
