// tetglow tetrahedralize MESH... [--node NAME] [-o FILE] [--json]: validate, tetrahedralize (several meshes
// together, as regions), report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "scene/MeshFile.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::vector<std::string> meshes;
    std::string output, node;
    bool json = false, noCache = false;
    TetOptions tet;
};

// The tets as cells of type 10, then the faces a repair spanned across holes as triangles
// (type 5, region -1, spanned 1), so that ParaView shows the repairs.
void writeVtk(const TetMesh& m, const std::vector<uint32_t>& spanned, std::ostream& out) {
    out.precision(9);
    out << "# vtk DataFile Version 3.0\ntetglow tetrahedral mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << m.vertices.size() << " double\n";
    for (const auto& v : m.vertices) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
    const size_t cells = m.tets.size() + spanned.size();
    out << "CELLS " << cells << ' ' << 5 * m.tets.size() + 4 * spanned.size() << '\n';
    for (const auto& t : m.tets) out << "4 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << t[3] << '\n';
    for (uint32_t s : spanned)
        out << "3 " << m.surface[s][0] << ' ' << m.surface[s][1] << ' ' << m.surface[s][2] << '\n';
    out << "CELL_TYPES " << cells << '\n';
    for (size_t i = 0; i < m.tets.size(); ++i) out << "10\n";
    for (size_t i = 0; i < spanned.size(); ++i) out << "5\n";
    out << "CELL_DATA " << cells << "\nSCALARS region int 1\nLOOKUP_TABLE default\n";
    for (uint32_t t = 0; t < m.tets.size(); ++t) out << m.region(t) << '\n';
    for (size_t i = 0; i < spanned.size(); ++i) out << "-1\n";
    if (spanned.empty()) return;
    out << "SCALARS spanned int 1\nLOOKUP_TABLE default\n";
    for (size_t i = 0; i < cells; ++i) out << (i >= m.tets.size()) << '\n';
}

// The boundary triangles (of the tet mesh) that repairs spanned across holes.
std::vector<uint32_t> spannedFaces(const TetMesh& mesh, const std::vector<ValidationReport>& reports) {
    std::set<std::array<uint32_t, 2>> spanned;
    for (uint32_t i = 0; i < reports.size(); ++i)
        for (uint32_t t : reports[i].repair.spannedTriangles) spanned.insert({i, t});
    std::vector<uint32_t> faces;
    for (uint32_t s = 0; s < mesh.surfaceSource.size(); ++s)
        if (spanned.count(mesh.surfaceSource[s])) faces.push_back(s);
    return faces;
}

nlohmann::json positions(const std::vector<glm::dvec3>& list) {
    nlohmann::json j = nlohmann::json::array();
    for (const auto& p : list) j.push_back({p.x, p.y, p.z});
    return j;
}

// What a repair did, with positions (null where the mesh took the exact path).
nlohmann::json repairJson(const RepairReport& r) {
    if (!r.applied) return nullptr;
    nlohmann::json holes = nlohmann::json::array();
    for (const auto& h : r.holes)
        holes.push_back({{"centre", {h.centre.x, h.centre.y, h.centre.z}}, {"area", h.area}, {"faces", h.faces}});
    return {{"reason", r.reason},
            {"summary", r.summary()},
            {"holes", holes},
            {"spanned_area", r.spannedArea},
            {"boundary_area", r.boundaryArea},
            {"hole_edges", r.holeEdges},
            {"lattice_points", r.latticePoints},
            {"non_manifold_edges", r.nonManifoldEdges},
            {"crossing_pairs", r.crossingPairs},
            {"crossings_at", positions(r.crossingAt)},
            {"unsplit_triangles", r.unsplitTriangles},
            {"parts_unioned", r.partsUnioned},
            {"flipped_faces", r.flippedTriangles},
            {"flipped_at", positions(r.flippedAt)},
            {"duplicate_faces_dropped", r.duplicatesDropped},
            {"duplicates_at", positions(r.duplicateAt)},
            {"zero_area_dropped", r.degenerateDropped},
            {"zero_area_at", positions(r.degenerateAt)},
            {"winding_number_range", {r.minWinding, r.maxWinding}}};
}

// Per region: its tets, their volume against the volume its surfaces enclose (its mesh's
// minus the meshes nested in it), and the surface triangles on its boundary.
struct RegionReport {
    size_t tets = 0, boundaryFaces = 0;
    double tetVolume = 0, enclosedVolume = 0, relError = 0;
};

std::vector<RegionReport> regionReports(const TetMesh& mesh) {
    std::vector<RegionReport> regions(mesh.regionCount());
    for (int32_t r = 0; r < int32_t(regions.size()); ++r) {
        RegionReport& g = regions[r];
        g.tets = mesh.regionTets[r + 1] - mesh.regionTets[r];
        g.tetVolume = mesh.regionVolume(r);
        g.enclosedVolume = mesh.regionSurfaceVolume(r);
        g.relError = std::abs(g.tetVolume - g.enclosedVolume) / g.enclosedVolume;
    }
    for (const auto& sides : mesh.surfaceRegions)
        for (int32_t r : sides)
            if (r >= 0) ++regions[r].boundaryFaces;
    return regions;
}

void run(const Options& o) {
    if (!o.output.empty()) prepareOutput(o.output, o.meshes);
    std::vector<TriangleMesh> surfaces;
    for (const auto& path : o.meshes) {
        std::vector<std::string> warnings;
        surfaces.push_back(readMesh(path, &warnings, o.node));
        for (const auto& w : warnings) std::fprintf(stderr, "tetglow: warning: %s\n", w.c_str());
    }
    TetOptions tetOptions = o.tet;
    tetOptions.useCache = !o.noCache;
    TetStats stats;
    std::vector<ValidationReport> reports;
    const TetMesh mesh = tetrahedralize(std::move(surfaces), o.meshes, tetOptions, &stats, &reports);
    double meshVolume = 0;
    size_t components = 0;
    std::vector<std::string> notes;
    for (size_t i = 0; i < reports.size(); ++i) {
        if (mesh.regionParent[i] < 0) meshVolume += reports[i].volume;
        components += reports[i].components;
        for (const auto& n : reports[i].notes) notes.push_back(o.meshes.size() == 1 ? n : o.meshes[i] + ": " + n);
    }
    const double tetVolume = mesh.volume();
    const double relError = std::abs(tetVolume - meshVolume) / meshVolume;
    const auto regions = regionReports(mesh);
    if (!o.output.empty()) {
        const std::string ext = std::filesystem::path(o.output).extension().string();
        if (ext == ".vtk")
            writeStream(o.output, [&](std::ostream& out) { writeVtk(mesh, spannedFaces(mesh, reports), out); });
        else
            writeTetMesh(mesh, 0, o.output);
    }
    const size_t steiner = mesh.vertices.size() - mesh.surfaceVertexCount;
    if (o.json) {
        nlohmann::json regionList = nlohmann::json::array();
        for (size_t r = 0; r < regions.size(); ++r)
            regionList.push_back({{"mesh", o.meshes[r]},
                                  {"inside", mesh.regionParent[r] < 0 ? nlohmann::json(nullptr)
                                                                      : nlohmann::json(o.meshes[mesh.regionParent[r]])},
                                  {"tets", regions[r].tets},
                                  {"tet_volume", regions[r].tetVolume},
                                  {"enclosed_volume", regions[r].enclosedVolume},
                                  {"volume_relative_error", regions[r].relError},
                                  {"boundary_faces", regions[r].boundaryFaces},
                                  {"repair", repairJson(reports[r].repair)}});
        nlohmann::json j = {{"mesh", o.meshes.size() == 1 ? nlohmann::json(o.meshes[0]) : nlohmann::json(o.meshes)},
                            {"switches", tetOptions.switches()},
                            {"tets", mesh.tets.size()},
                            {"vertices", mesh.vertices.size()},
                            {"steiner_points", steiner},
                            {"boundary_faces", mesh.surface.size()},
                            {"components", components},
                            {"mesh_volume", meshVolume},
                            {"tet_volume", tetVolume},
                            {"volume_relative_error", relError},
                            {"bytes_per_tet", mesh.bytesPerTet()},
                            {"regions", regionList},
                            {"seconds", stats.seconds},
                            {"from_cache", stats.fromCache},
                            {"repairs", notes},
                            {"output", o.output}};
        std::cout << j.dump(2) << '\n';
        return;
    }
    for (const auto& m : o.meshes) std::printf("mesh             %s\n", m.c_str());
    for (const auto& n : notes) std::printf("repaired         %s\n", n.c_str());
    std::printf("tetrahedra       %zu (%zu bytes each + vertices)\n", mesh.tets.size(), mesh.bytesPerTet());
    std::printf("vertices         %zu (%zu Steiner points)\n", mesh.vertices.size(), steiner);
    const size_t spanned = spannedFaces(mesh, reports).size();
    if (spanned)
        std::printf("boundary faces   %zu (%zu input triangles or their pieces, %zu tet faces across holes)\n",
                    mesh.surface.size(), mesh.surface.size() - spanned, spanned);
    else
        std::printf("boundary faces   %zu (one per input triangle or piece%s)\n", mesh.surface.size(),
                    o.meshes.size() > 1 ? "; shared triangles once" : "");
    std::printf("volume           mesh %.12g, tets %.12g, relative difference %.2e\n", meshVolume, tetVolume, relError);
    if (o.meshes.size() > 1) {
        std::printf("regions          (volume enclosed: the mesh's minus the meshes nested in it)\n");
        for (size_t r = 0; r < regions.size(); ++r) {
            const auto& g = regions[r];
            std::printf(
                "  %s%s%s\n      tets %zu, volume: enclosed %.12g, tets %.12g, relative difference %.2e, boundary "
                "faces %zu\n",
                o.meshes[r].c_str(), mesh.regionParent[r] < 0 ? "" : " inside ",
                mesh.regionParent[r] < 0 ? "" : o.meshes[mesh.regionParent[r]].c_str(), g.tets, g.enclosedVolume,
                g.tetVolume, g.relError, g.boundaryFaces);
        }
    }
    std::printf("time             %.3f s%s\n", stats.seconds, stats.fromCache ? " (from cache)" : "");
    if (!o.output.empty()) std::printf("written          %s\n", o.output.c_str());
}

}  // namespace

void addTetrahedralizeCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    CLI::App* cmd =
        app.add_subcommand("tetrahedralize", "Validate closed meshes and tetrahedralize their interiors as regions");
    cmd->add_option("mesh", o->meshes,
                    "Closed triangle meshes (OBJ, OFF, PLY, STL, glTF, GLB, FBX, Collada), nested or touching along "
                    "shared triangles")
        ->required();
    cmd->add_option("-o,--output", o->output,
                    "Write the tet mesh (.vtk: legacy VTK for ParaView; else tetglow's binary)")
        ->check(kNonEmpty);
    cmd->add_option("--node", o->node,
                    "Only the meshes of this node and the nodes below it (glTF, GLB, FBX, Collada), as a scene "
                    "file's \"node\"")
        ->check(kNonEmpty);
    cmd->add_flag("--json", o->json, "Print the report as one JSON object");
    cmd->add_option("--quality", o->tet.radiusEdgeRatio, "Radius-edge ratio bound (TetGen -q); adds Steiner points")
        ->check(inRange({.lo = 1, .hi = 1e9}));
    cmd->add_option("--max-volume", o->tet.maxVolume, "Largest tet volume (TetGen -a); adds Steiner points")
        ->check(inRange(kPositive));
    cmd->add_flag("--no-cache", o->noCache, "Always run TetGen, do not read or write the cache");
    cmd->add_flag("--strict", o->tet.strict,
                  "Refuse a mesh that is not closed, manifold and free of self-intersections "
                  "instead of repairing it; the error counts and locates every problem");
    cmd->add_option("--repair-time-limit", o->tet.repairTimeLimit,
                    "Seconds the repair of a broken mesh may take before the mesh is approximated by its winding "
                    "number on a grid instead, with a warning naming the stage reached (0: approximate at once)")
        ->check(inRange({.lo = 0, .hi = 1e6}));
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
