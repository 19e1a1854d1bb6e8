// tetglow init MESH -o DIR/scene.json: a first scene around a mesh of one's own: the mesh as a
// glowing, scattering medium on a floor, a point light above it and a camera framed on its bounds.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "cli/Commands.h"
#include "scene/MeshFile.h"
#include "tet/TriangleMesh.h"

namespace tetglow::cli {
namespace {

namespace fs = std::filesystem;

// Four significant digits: a scene file one reads and edits, not one that records a computation.
double tidy(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return std::stod(text);
}

nlohmann::json vec(const glm::dvec3& v) { return {tidy(v.x), tidy(v.y), tidy(v.z)}; }

nlohmann::json firstScene(const Bounds3& box, const std::string& meshFile) {
    const glm::dvec3 center = (box.lo + box.hi) * 0.5;
    const double r = std::max(box.diagonal() / 2, 1e-9);  // the mesh's bounding sphere, about
    constexpr double kFov = 40;
    // Far enough for the bounding sphere to fill the frame with a margin, seen from above in front.
    const glm::dvec3 view = glm::normalize(glm::dvec3(0.35, 0.45, 1));
    const glm::dvec3 eye = center + view * (1.15 * r / std::sin(glm::radians(kFov / 2)));
    const double floorY = box.lo.y - 0.01 * r;  // just under the mesh: surfaces lie outside media
    const glm::dvec3 lamp = center + glm::dvec3(0.8 * r, 3 * r, 1.2 * r);
    const double lampDistance2 = glm::dot(lamp - center, lamp - center);
    // Optical depths and glow that do not depend on the mesh's units: sigma in 1/r, emission so
    // that a chord through the middle glows with a radiance of about one.
    return {
        {"camera", {{"position", vec(eye)}, {"look_at", vec(center)}, {"fov", kFov}, {"resolution", {320, 240}}}},
        {"integrator", {{"type", "volpath"}, {"spp", 64}, {"seed", 1}}},
        {"lights",
         {{{"type", "point"},
           {"position", vec(lamp)},
           {"intensity", {tidy(lampDistance2 * 0.8), tidy(lampDistance2 * 0.76), tidy(lampDistance2 * 0.68)}}},
          {{"type", "environment"}, {"radiance", {0.01, 0.02, 0.04}}}}},
        {"surfaces",
         {{{"shape",
            {{"type", "quad"},
             {"corner", vec(glm::dvec3(center.x - 6 * r, floorY, center.z - 6 * r))},
             {"edge0", vec(glm::dvec3(0, 0, 12 * r))},
             {"edge1", vec(glm::dvec3(12 * r, 0, 0))}}},
           {"material", {{"type", "diffuse"}, {"reflectance", {0.5, 0.5, 0.5}}}}}}},
        {"media",
         {{{"shape", {{"type", "mesh"}, {"file", meshFile}}},
           {"sigma_a", {tidy(0.4 / r), tidy(0.3 / r), tidy(0.2 / r)}},
           {"sigma_s", tidy(2 / r)},
           {"g", 0.3},
           {"emission", {tidy(0.1 / r), tidy(0.8 / r), tidy(2 / r)}},
           {"boundary", {{"type", "interface"}}}}}},
    };
}

void run(const std::string& mesh, const std::string& output) {
    if (fs::path(output).extension() != ".json") throw InputError(output + ": the scene must be a .json file");
    if (fs::exists(output)) throw InputError(output + ": already exists; init does not overwrite a scene");
    const Bounds3 box = bounds(readMesh(mesh));
    if (box.empty()) throw InputError(mesh + ": no triangles");
    prepareOutput(output, {mesh});
    // Scenes name their files relative to their own folder.
    const fs::path folder = fs::absolute(output).parent_path();
    const std::string meshFile = fs::relative(fs::absolute(mesh), folder).generic_string();
    writeStream(output, [&](std::ostream& out) { out << firstScene(box, meshFile).dump(2) << '\n'; });
    std::printf(
        "%s: %s as a glowing medium on a floor; render it with `tetglow render %s`, tune it live with `tetglow preview "
        "%s`\n",
        output.c_str(), mesh.c_str(), output.c_str(), output.c_str());
}

}  // namespace

void addInitCommand(CLI::App& app) {
    auto mesh = std::make_shared<std::string>(), output = std::make_shared<std::string>("scene.json");
    auto* cmd = app.add_subcommand(
        "init", "Write a first scene around a mesh of your own: a glowing medium on a floor, lit and framed");
    cmd->add_option("mesh", *mesh, "Closed triangle mesh, OBJ or OFF")->required()->check(CLI::ExistingFile);
    cmd->add_option("-o,--output", *output,
                    "Scene file to write (default: scene.json); the mesh is named relative to it")
        ->check(kNonEmpty);
    cmd->callback([mesh, output] { run(*mesh, *output); });
}

}  // namespace tetglow::cli
