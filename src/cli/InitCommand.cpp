// tetglow init MESH -o DIR/scene.json: a first scene around a mesh of one's own: the mesh as a
// glowing, scattering medium on a floor, a point light above it and a camera framed on the bounds
// of its used vertices, all turned to the mesh's up axis (--up, else the file's, else y).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string_view>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "scene/MeshFile.h"
#include "scene/SceneLoader.h"
#include "tet/MeshValidation.h"
#include "tet/TriangleMesh.h"

namespace tetglow::cli {
namespace {

namespace fs = std::filesystem;

// Four significant digits at the mesh's size `r`: a scene file one reads and edits, not one that
// records a computation, yet a mesh far from the origin keeps its place to a ten-thousandth of its size.
double tidy(double v, double r) {
    if (v == 0) return 0;
    const int digits = 4 + int(std::clamp(std::ceil(std::log10(std::abs(v) / r)), 0.0, 13.0));
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    return std::stod(text);
}

nlohmann::json vec(const glm::dvec3& v, double r) { return {tidy(v.x, r), tidy(v.y, r), tidy(v.z, r)}; }

// The six axes --up names, and the axis the camera looks along from in front of the mesh.
struct Axes {
    glm::dvec3 up, front;
};
const std::pair<std::string_view, Axes> kUpAxes[] = {{"y", {{0, 1, 0}, {0, 0, 1}}},  {"-y", {{0, -1, 0}, {0, 0, 1}}},
                                                     {"z", {{0, 0, 1}, {0, -1, 0}}}, {"-z", {{0, 0, -1}, {0, 1, 0}}},
                                                     {"x", {{1, 0, 0}, {0, 0, 1}}},  {"-x", {{-1, 0, 0}, {0, 0, 1}}}};

std::string_view axisName(const glm::dvec3& up) {
    for (const auto& [name, axes] : kUpAxes)
        if (axes.up == up) return name;
    return "";
}

// How far from `from` along the unit `direction` the scene's coordinate range reaches (with a
// margin for the rounding of tidy()).
double reach(const glm::dvec3& from, const glm::dvec3& direction) {
    double most = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
        if (direction[i] != 0)
            most = std::min(most, ((direction[i] > 0 ? 0.99 : -0.99) * kMaxCoordinate - from[i]) / direction[i]);
    return most;
}

// The box of the vertices the triangles use: a stray vertex elsewhere must not take the frame.
Bounds3 usedBounds(const TriangleMesh& mesh) {
    Bounds3 box;
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) box.extend(mesh.positions[v]);
    return box;
}

// The sizes init frames a mesh at as it is: ray offsets and the tet walk's tolerances have an
// absolute floor (about 1e-5) that a smaller mesh vanishes under, and a larger one leaves the
// camera and the floor no room within the scene's coordinate range.
inline constexpr double kSmallestAsIs = 1e-2, kLargestAsIs = 1e8;

// A mesh outside those sizes, scaled by a power of ten to a size near 1 and moved to the origin:
// the shape's "transform", in the order the loader applies it. Null where the mesh is framed as it is.
nlohmann::json normalizing(const TriangleMesh& mesh, TriangleMesh& placed) {
    const Bounds3 box = usedBounds(mesh);
    const double r = box.diagonal() / 2;
    if (r >= kSmallestAsIs && r <= kLargestAsIs) return nullptr;
    // Scaled first, so that the translation is of the scaled mesh and within the coordinate range.
    const double scale = std::pow(10.0, -std::round(std::log10(r)));
    const glm::dvec3 shift = -(box.lo + box.hi) * 0.5 * scale;
    for (auto& p : placed.positions) p = p * scale + shift;
    return {{{"scale", scale}}, {{"translate", {shift.x, shift.y, shift.z}}}};
}

nlohmann::json firstScene(const TriangleMesh& mesh, const Axes& axes, const std::string& meshFile,
                          const nlohmann::json& transform) {
    const Bounds3 box = usedBounds(mesh);
    const glm::dvec3 center = (box.lo + box.hi) * 0.5, up = axes.up, front = axes.front;
    const glm::dvec3 right = glm::cross(up, front);
    const double r = box.diagonal() / 2;  // the mesh's bounding sphere, about
    auto tidyVec = [r](const glm::dvec3& v) { return vec(v, r); };
    auto tidyNum = [](double v) { return tidy(v, std::abs(v)); };
    // Far enough for the bounding sphere to fill the frame with a margin, seen from above in front;
    // nearer with a wider view where that would leave the scene's coordinate range (a huge mesh).
    const glm::dvec3 view = glm::normalize(0.35 * right + 0.45 * up + front);
    double fov = 40, distance = 1.15 * r / std::sin(glm::radians(fov / 2));
    if (const double most = reach(center, view); distance > most && most > 1.2 * r) {
        distance = most;
        fov = std::min(2 * glm::degrees(std::asin(1.15 * r / distance)), 150.0);
    }
    const glm::dvec3 eye = center + view * distance;
    // The floor just under the mesh's lowest used vertex: surfaces lie outside media.
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) lowest = std::min(lowest, glm::dot(mesh.positions[v], up));
    const glm::dvec3 floorCenter = center + (lowest - glm::dot(center, up) - 0.01 * r) * up;
    // As large as the scene's coordinate range leaves it around a huge mesh.
    const double far = std::max({std::abs(floorCenter.x), std::abs(floorCenter.y), std::abs(floorCenter.z)});
    const double half = std::min({6 * r, 0.99 * kMaxCoordinate - far, 0.99 * kMaxCoordinate / 2});
    const glm::dvec3 toLamp = glm::normalize(0.8 * right + 3.0 * up + 1.2 * front);
    const glm::dvec3 lamp = center + toLamp * std::min(r * std::sqrt(0.64 + 9 + 1.44), reach(center, toLamp));
    const double lampDistance2 = glm::dot(lamp - center, lamp - center);
    // Optical depths and glow that do not depend on the mesh's units: sigma in 1/r, emission so
    // that a chord through the middle glows with a radiance of about one.
    return {
        {"camera",
         {{"position", tidyVec(eye)},
          {"look_at", tidyVec(center)},
          {"up", vec(up, 1)},
          {"fov", tidy(fov, fov)},
          {"resolution", {320, 240}}}},
        {"integrator", {{"type", "volpath"}, {"spp", 64}, {"seed", 1}}},
        {"lights",
         {{{"type", "point"},
           {"position", tidyVec(lamp)},
           {"intensity", {tidyNum(lampDistance2 * 0.8), tidyNum(lampDistance2 * 0.76), tidyNum(lampDistance2 * 0.68)}}},
          {{"type", "environment"}, {"radiance", {0.01, 0.02, 0.04}}}}},
        {"surfaces",
         {{{"shape",
            {{"type", "quad"},
             {"corner", tidyVec(floorCenter - half * (front + right))},
             {"edge0", tidyVec(2 * half * front)},
             {"edge1", tidyVec(2 * half * right)}}},
           {"material", {{"type", "diffuse"}, {"reflectance", {0.5, 0.5, 0.5}}}}}}},
        {"media",
         {{{"shape", transform.is_null()
                         ? nlohmann::json{{"type", "mesh"}, {"file", meshFile}}
                         : nlohmann::json{{"type", "mesh"}, {"file", meshFile}, {"transform", transform}}},
           {"sigma_a", {tidyNum(0.4 / r), tidyNum(0.3 / r), tidyNum(0.2 / r)}},
           {"sigma_s", tidyNum(2 / r)},
           {"g", 0.3},
           {"emission", {tidyNum(0.1 / r), tidyNum(0.8 / r), tidyNum(2 / r)}},
           {"boundary", {{"type", "interface"}}}}}},
    };
}

// The up axis: --up, else the one the file states, else +Y; `said` tells which, for the output.
Axes upAxes(const MeshFile& file, const std::string& mesh, const std::string& given, std::string& said) {
    std::string name = given;
    if (name.empty()) {
        name = std::string(axisName(file.up));
        if (!name.empty()) said = "up: " + name + " (" + file.upFrom + "); another with --up";
    }
    if (name.empty()) {
        name = "y";
        said = "up: y assumed (" + mesh +
               " states no up axis); if the mesh lies on its side, run init again with --up z, x, -y, ... (--up=-z "
               "for a negative one)";
    }
    for (const auto& [axis, axes] : kUpAxes)
        if (axis == name) return axes;
    throw CLI::ValidationError("--up", "expected x, y, z, -x, -y or -z, got '" + shorten(name) + "'");
}

struct Options {
    std::string mesh, output = "scene.json", up;
};

void run(const Options& o) {
    const std::string& mesh = o.mesh;
    const std::string& output = o.output;
    if (fs::path(output).extension() != ".json") throw InputError(output + ": the scene must be a .json file");
    if (fs::exists(output)) throw InputError(output + ": already exists; init does not overwrite a scene");
    const MeshFile file = readMeshFile(mesh);
    if (file.mesh.triangles.empty()) throw InputError(mesh + ": no triangles");
    try {
        // What render refuses first in a mesh (a NaN vertex, a mesh float coordinates cannot shape).
        checkFinite(file.mesh);
    } catch (const InputError& e) {
        throw InputError(mesh + ": " + e.what());
    }
    if (!(usedBounds(file.mesh).diagonal() > 0))
        throw InputError(mesh + ": mesh encloses no volume: every vertex its triangles use is one point");
    std::string said;
    const Axes axes = upAxes(file, mesh, o.up, said);
    prepareOutput(output, {mesh});
    // Scenes name their files relative to their own folder.
    const fs::path folder = fs::absolute(output).parent_path();
    const std::string meshFile = fs::relative(fs::absolute(mesh), folder).generic_string();
    TriangleMesh placed = file.mesh;
    const nlohmann::json transform = normalizing(file.mesh, placed);
    if (!transform.is_null()) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "size: %.3g across, so the scene scales the mesh by %g and moves it to the origin (its "
                      "\"transform\"): tetglow renders sizes from about 0.01 to 1e8 as they are",
                      usedBounds(file.mesh).diagonal(), transform[0]["scale"].get<double>());
        said += (said.empty() ? "" : "\n") + std::string(text);
    }
    const nlohmann::json scene = firstScene(placed, axes, meshFile, transform);
    // The loader's own checks, so that a scene init writes is one render reads.
    try {
        loadJsonScene(scene, output);
    } catch (const InputError& e) {
        throw InputError(mesh + ": render would refuse the scene init would write: " + e.what());
    }
    writeStream(output, [&](std::ostream& out) { out << scene.dump(2) << '\n'; });
    std::printf(
        "%s: %s as a glowing medium on a floor; render it with `tetglow render %s`, tune it live with `tetglow preview "
        "%s`\n",
        output.c_str(), mesh.c_str(), output.c_str(), output.c_str());
    if (!said.empty()) std::printf("%s\n", said.c_str());
}

}  // namespace

void addInitCommand(CLI::App& app) {
    auto o = std::make_shared<Options>();
    auto* cmd = app.add_subcommand(
        "init", "Write a first scene around a mesh of your own: a glowing medium on a floor, lit and framed");
    cmd->add_option("mesh", o->mesh, "Closed triangle mesh (OBJ, OFF, PLY, STL, glTF, GLB, FBX, Collada)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", o->output,
                    "Scene file to write (default: scene.json); the mesh is named relative to it")
        ->check(kNonEmpty);
    cmd->add_option("--up", o->up,
                    "The mesh's up axis: x, y, z, -x, -y or -z (--up=-z); default: the file's own (glTF: y; FBX, "
                    "Collada: as the file states), else y")
        ->check(CLI::IsMember({"x", "y", "z", "-x", "-y", "-z"}));
    cmd->callback([o] { run(*o); });
}

}  // namespace tetglow::cli
