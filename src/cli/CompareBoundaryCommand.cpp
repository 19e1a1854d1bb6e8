// tetglow compare-boundary MESH|SCENE: the tets against the parity baseline's test and the bounding
// box on the same points and rays (classification error and time per query, optical-depth error
// and time per ray), and optionally the parity baseline's red/green debug picture.
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/BoundaryReport.h"
#include "cli/Commands.h"
#include "evidence/BoundaryPicture.h"
#include "render/ImageIO.h"
#include "scene/MeshFile.h"
#include "scene/Scene.h"
#include "scene/SceneLoader.h"
#include "tet/Tetrahedralizer.h"

namespace tetglow::cli {
namespace {

struct Options {
    std::string input, csv, picture;
    ComparisonOptions comparison;
    int pictureWidth = 0;
    bool json = false, strict = false;
};

// The media to compare, with what the picture needs: a camera, a step and rays per parity test.
struct Subject {
    std::unique_ptr<Scene> scene;          // SCENE input
    std::unique_ptr<TetTraversal> mesh;    // MESH input
    std::unique_ptr<TriangleMesh> broken;  // MESH input as read, where it was repaired
    std::vector<const TetTraversal*> volumes;
    std::vector<MediumReport> reports;
    CameraDesc camera;
    double step = 0;
    int parityRays = 1;
};

MediumReport describe(const std::string& name, const TetTraversal& v) {
    MediumReport r;
    r.name = name;
    r.tets = v.mesh().tets.size();
    r.triangles = v.mesh().surface.size();
    r.diagonal = v.bounds().diagonal();
    return r;
}

Subject loadSceneSubject(const std::string& path) {
    Subject s;
    const SceneDesc desc = loadScene(path);
    if (desc.media.empty()) throw InputError(path + ": the scene has no media to compare");
    s.scene = std::make_unique<Scene>(desc);
    for (const auto& m : s.scene->volumes()) {
        s.volumes.push_back(&m.volume->traversal());
        MediumReport r = describe(m.name, m.volume->traversal());
        r.sigmaT = average(m.volume->region(0).sigmaT);
        r.sigmaSource = "the mean over R, G, B";
        r.homogeneous = m.volume->homogeneous();
        s.reports.push_back(std::move(r));
    }
    s.camera = desc.camera;
    s.step = desc.integrator.stepSize;
    s.parityRays = desc.integrator.parityRays;
    return s;
}

Subject loadMeshSubject(const std::string& path, bool strict) {
    Subject s;
    std::vector<std::string> warnings;
    TriangleMesh surface = readMesh(path, &warnings);
    for (const auto& w : warnings) std::fprintf(stderr, "tetglow: warning: %s\n", w.c_str());
    TetOptions options;
    options.strict = strict;
    ValidationReport report;
    const TriangleMesh input = surface;
    try {
        s.mesh = std::make_unique<TetTraversal>(tetrahedralize(std::move(surface), options, nullptr, &report));
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what());
    }
    if (report.repair.applied) {
        std::fprintf(stderr, "%s: repaired: %s\n", path.c_str(), report.repair.summary().c_str());
        s.broken = std::make_unique<TriangleMesh>(input);
    }
    s.volumes.push_back(s.mesh.get());
    s.reports.push_back(describe(std::filesystem::path(path).filename().string(), *s.mesh));
    // A three-quarter view from +z (the fish's side) that holds the whole bounding box.
    const Bounds3 box = s.mesh->bounds();
    const glm::dvec3 centre = 0.5 * (box.lo + box.hi);
    s.camera.lookAt = centre;
    s.camera.position = centre + box.diagonal() * glm::dvec3(0.35, 0.3, 1.4);
    s.camera.width = s.camera.height = 320;
    s.step = box.diagonal() / 200;
    return s;
}

void writePicture(const Options& o, Subject& s) {
    CameraDesc camera = s.camera;
    if (o.pictureWidth > 0) {
        camera.height = std::max(1, int(std::lround(double(camera.height) * o.pictureWidth / camera.width)));
        camera.width = o.pictureWidth;
    }
    const BoundaryPicture picture = renderBoundaryPicture(Camera(camera), s.volumes, s.step, s.parityRays);
    writeExr(o.picture, picture.image);
    writePng(previewPath(o.picture), picture.image);
    std::fprintf(
        stderr,
        "picture %s: %dx%d, step %.4g, %d parity ray(s) per sample: %zu samples, %zu disagree (%zu magenta pixels)\n",
        o.picture.c_str(), camera.width, camera.height, s.step, s.parityRays, picture.samples, picture.disagreements,
        picture.pixelsWithDisagreement);
}

void run(const Options& o) {
    if (!o.picture.empty() && std::filesystem::path(o.picture).extension() != ".exr")
        throw InputError(o.picture + ": the picture must be an .exr file");
    for (const auto& path : {o.picture, o.picture.empty() ? "" : previewPath(o.picture), o.csv})
        if (!path.empty()) prepareOutput(path, {o.input});
    Subject s = std::filesystem::path(o.input).extension() == ".json" ? loadSceneSubject(o.input)
                                                                      : loadMeshSubject(o.input, o.strict);
    for (size_t m = 0; m < s.volumes.size(); ++m)
        s.reports[m].comparison = compareBoundary(*s.volumes[m], o.comparison, s.broken.get());
    if (!o.picture.empty()) writePicture(o, s);
    if (!o.csv.empty()) {
        writeStream(o.csv, [&](std::ostream& csv) {
            csv << csvHeader();
            for (const auto& r : s.reports) csv << csvRows(r);
        });
    }
    if (o.json) {
        nlohmann::json media = nlohmann::json::array();
        for (const auto& r : s.reports) media.push_back(toJson(r));
        const nlohmann::json j = {{"input", o.input},
                                  {"points_per_region", o.comparison.points},
                                  {"rays", o.comparison.rays},
                                  {"seed", o.comparison.seed},
                                  {"media", media}};
        std::cout << j.dump(2) << '\n';
        return;
    }
    std::printf("compare-boundary %s: %zu points per region, %zu lines, seed %llu, one thread\n\n", o.input.c_str(),
                o.comparison.points, o.comparison.rays, (unsigned long long)o.comparison.seed);
    for (const auto& r : s.reports) printText(stdout, r);
}

}  // namespace

void addCompareBoundaryCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand("compare-boundary",
                                   "Compare the tets with the parity test and the bounding box: inside/outside errors, "
                                   "optical-depth errors, time per query");
    cmd->add_option("input", o->input,
                    "Closed mesh (OBJ, OFF, PLY, STL, glTF, GLB, FBX, Collada) or scene (.json: every medium in it)")
        ->required();
    cmd->add_option("--points", o->comparison.points, "Random points per region (the box and each shell)")
        ->check(CLI::Range(size_t(1), size_t(100000000)));
    cmd->add_option("--rays", o->comparison.rays, "Random lines across the bounding box")
        ->check(CLI::Range(size_t(1), size_t(100000000)));
    // Beyond a diagonal a shell lies wholly outside the box, and its points must stay rays Embree takes.
    cmd->add_option("--shells", o->comparison.shells,
                    "Shell offsets from the surface in diagonals, at most 1 (default: 1e-2 to 1e-7)")
        ->check(inRange({.lo = 0, .hi = 1, .loOpen = true}));
    cmd->add_option("--steps", o->comparison.steps,
                    "March steps in world units (default: the diagonal / 20, / 100, / 500)")
        ->check(inRange(kPositive));
    cmd->add_option("--seed", o->comparison.seed, "Random seed")->check(inIntegers(0, INT64_MAX));
    cmd->add_flag("--json", o->json, "Print one JSON object instead of the tables");
    cmd->add_option("--csv", o->csv, "Also write every row to this CSV file")->check(kNonEmpty);
    cmd->add_option("--picture", o->picture,
                    "Also write the debug picture (.exr, with a .png beside it): green inside by both tests, "
                    "dim red in the bounding box only, magenta where tets and parity disagree")
        ->check(kNonEmpty);
    cmd->add_option("--picture-width", o->pictureWidth, "Width of the picture (default: the scene's; 320 for a mesh)")
        ->check(CLI::Range(1, kMaxResolution));
    cmd->add_flag("--strict", o->strict,
                  "Refuse a broken mesh instead of repairing it (a repaired one is compared "
                  "with parity on the mesh as read and with its winding number)");
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
