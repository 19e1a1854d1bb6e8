// A scene as the user described it: plain data, every path resolved and every mesh loaded and
// placed in world space. The renderer builds its acceleration structures from this.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "base/Spectrum.h"
#include "tet/Tetrahedralizer.h"
#include "tet/TriangleMesh.h"

namespace tetglow {

// Which way the image's x axis runs: Right: along cross(view, up), the usual right-handed
// camera; Left: along cross(up, view), as pbrt's LookAt builds it (the mirror image).
enum class Handedness { Right, Left };

inline constexpr int kMaxResolution = 16384;  // pixels along either image axis, in every front end
// The other counts every front end bounds the same way: samples (passes) per pixel, events per
// path, photon paths per pass (these also checked against the machine's memory).
inline constexpr int kMaxSpp = 1 << 20, kMaxDepth = 1 << 20;
inline constexpr int64_t kMaxPhotons = int64_t(1) << 40;
inline constexpr int kMaxFrames = 1000000;  // frames of an animation

struct CameraDesc {
    glm::dvec3 position{0, 0, 5}, lookAt{0}, up{0, 1, 0};
    double fov = 40;  // degrees across the shorter image axis (pbrt's convention)
    int width = 400, height = 400;
    Handedness handedness = Handedness::Right;
};

enum class LightType { Point, Spot, Distant, Quad, Mesh, Environment };

struct LightDesc {
    LightType type = LightType::Point;
    RGB intensity{0};                          // point, spot: radiant intensity (W/sr)
    RGB radiance{0};                           // quad, mesh, environment: emitted radiance
    glm::dvec3 position{0}, lookAt{0, -1, 0};  // point, spot (spot axis: lookAt - position)
    // Spot: pbrt-v3's cone. Full intensity within coneAngle - coneDelta of the axis, none
    // beyond coneAngle, smoothstep-like falloff ((cos - cosTotal) / (cosStart - cosTotal))^4 between.
    double coneAngle = 30, coneDelta = 5;  // degrees
    // Spot: 0 is a point; > 0 makes it a disk of this radius facing the axis, with the same
    // intensity profile, so paths through specular surfaces can reach it.
    double radius = 0;
    glm::dvec3 direction{0, -1, 0};                        // distant: the direction the light travels
    RGB irradiance{0};                                     // distant: on a surface facing the light
    glm::dvec3 corner{0}, edge0{1, 0, 0}, edge1{0, 0, 1};  // quad: emits along cross(edge0, edge1)
    TriangleMesh mesh;      // mesh: world space; each triangle emits along cross(p1 - p0, p2 - p0)
    bool twoSided = false;  // quad, mesh
    bool on = true;         // false: the light is in the scene but emits nothing (its values kept)
};

// A light's emitted quantity and its key in scene files: "intensity" for point and spot lights,
// "irradiance" for distant ones, "radiance" for the others.
inline const char* emissionKey(LightType t) {
    return t == LightType::Point || t == LightType::Spot ? "intensity"
           : t == LightType::Distant                     ? "irradiance"
                                                         : "radiance";
}
inline RGB& emissionOf(LightDesc& l) {
    return l.type == LightType::Point || l.type == LightType::Spot ? l.intensity
           : l.type == LightType::Distant                          ? l.irradiance
                                                                   : l.radiance;
}
inline const RGB& emissionOf(const LightDesc& l) { return emissionOf(const_cast<LightDesc&>(l)); }

enum class MaterialType {
    Diffuse,     // Lambertian, reflectance per channel
    Dielectric,  // smooth glass-like interface with index of refraction `ior`
    Interface,   // index-matched: light passes unchanged (only a medium boundary)
};

struct MaterialDesc {
    MaterialType type = MaterialType::Diffuse;
    RGB reflectance{0.5};
    double ior = 1.5;
};

struct SurfaceDesc {
    std::string name;   // for messages: the JSON path or the mesh file
    TriangleMesh mesh;  // world space
    MaterialDesc material;
};

// Per-vertex density: evaluated at every tet vertex and interpolated linearly inside each tet.
struct DensityDesc {
    enum class Type { Constant, Linear, Noise } type = Type::Constant;
    double offset = 1;                      // constant value; linear: offset + dot(gradient, x)
    glm::dvec3 gradient{0};                 // linear
    double frequency = 4, amplitude = 0.5;  // noise: offset * (1 + amplitude * noise(frequency * x))
    uint32_t seed = 1;                      // noise
    bool isConstant() const { return type == Type::Constant; }
};

struct MediumDesc {
    std::string name;          // for messages
    std::string label;         // what the user calls it: the file's "name", else its mesh's file name ("" from pbrt)
    TriangleMesh boundary;     // world space, closed; tetrahedralized when the scene is built
    RGB sigmaA{0}, sigmaS{1};  // per unit length, already multiplied by `scale`
    double g = 0;              // Henyey-Greenstein asymmetry, in (-1, 1)
    RGB emission{0};           // emitted radiance per unit length (times density)
    DensityDesc density;
    MaterialDesc boundaryMaterial{MaterialType::Interface};  // Dielectric or Interface
    TetOptions tetOptions;                                   // Steiner points only when asked (heterogeneous density)
    // A cavity: a region with no medium (a bubble, an eye socket), its coefficients all zero;
    // it must lie inside a medium.
    bool cavity = false;
};

enum class IntegratorType { VolPath, Single, Photon };
enum class BoundaryMode { Tet, Parity, Bbox };
// The photon integrator's volume estimate along eye rays: the parity baseline's ray march with a k-NN
// lookup per step, or the beam radiance estimate (Jarosz, Zwicker, Jensen 2008).
enum class PhotonEstimate { KnnMarch, Beam };

// What scene files and `render`'s options call each value: one table each for the loader, the
// writer and the command line.
template <class T, size_t N>
using NameTable = std::array<std::pair<std::string_view, T>, N>;
inline constexpr NameTable<IntegratorType, 3> kIntegratorNames{
    {{"volpath", IntegratorType::VolPath}, {"single", IntegratorType::Single}, {"photon", IntegratorType::Photon}}};
inline constexpr NameTable<BoundaryMode, 3> kBoundaryNames{
    {{"tet", BoundaryMode::Tet}, {"parity", BoundaryMode::Parity}, {"bbox", BoundaryMode::Bbox}}};
inline constexpr NameTable<PhotonEstimate, 2> kEstimateNames{
    {{"knn-march", PhotonEstimate::KnnMarch}, {"beam", PhotonEstimate::Beam}}};

template <class T, size_t N>
std::string_view nameOf(const NameTable<T, N>& table, T value) {
    for (const auto& [name, v] : table)
        if (v == value) return name;
    return {};
}
template <class T, size_t N>
std::optional<T> valueOf(const NameTable<T, N>& table, std::string_view name) {
    for (const auto& [n, value] : table)
        if (n == name) return value;
    return std::nullopt;
}
template <class T, size_t N>
std::vector<std::string> namesOf(const NameTable<T, N>& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) names.emplace_back(entry.first);
    return names;
}

struct IntegratorDesc {
    IntegratorType type = IntegratorType::VolPath;
    int spp = 16;
    // The file named the spp (a pbrt Sampler, a JSON "spp"): it then caps a render that runs for
    // a time or to a noise target; else those run until their own stop.
    bool sppGiven = false;
    int maxDepth = 64;  // volpath, photon: scattering and surface events per path
    uint64_t seed = 0;
    // single
    BoundaryMode boundary = BoundaryMode::Tet;
    double stepSize = 0.02;  // ray-march step, world units
    int parityRays = 1;      // parity boundary: rays per inside test (majority)
    // photon: `spp` passes, each with fresh photons and one eye sample per pixel
    uint64_t photons = 100000;  // photon paths per pass
    int k = 16;                 // neighbours that set the radius (k-NN lookups, beam discs)
    double radius = 0;          // > 0: this fixed radius instead of k neighbours
    PhotonEstimate estimate = PhotonEstimate::Beam;
    // Progressive radius reduction per pass (Knaus and Zwicker 2011); 0: 4 / (d + 4) for each
    // d-dimensional kernel, where squared bias and variance fall at the same rate.
    double alpha = 0;
    bool boundaryCorrection = true;  // k-NN: divide by the part of the ball inside the medium
    // Diffuse surfaces seen from the eye gather their indirect light by one more bounce instead
    // of estimating it from the surface photons (caustics, from lights by specular events only,
    // still come from photons): no kernel blur on a floor's indirect light, more noise.
    bool finalGather = false;
    double timeLimit = 0;  // > 0: stop starting passes after this many seconds
};

// An animation of the camera: frame k of `frames` sees the scene with the camera (position,
// look-at point and up) turned by k / frames of `degrees` about `axis` through `center`.
struct TurntableDesc {
    int frames = 1;
    glm::dvec3 center{0}, axis{0, 1, 0};
    double degrees = 360;
};

// How the media lie in one another, found exactly from their meshes (never stated).
struct MediaNesting {
    std::vector<int32_t> parent;                        // per medium: the medium around it, -1 none
    std::vector<std::pair<int32_t, int32_t>> touching;  // media that share boundary triangles
};

struct SceneDesc {
    std::string path;  // the scene file
    CameraDesc camera;
    TurntableDesc turntable;  // frames of the camera; 1 frame: a still
    std::vector<LightDesc> lights;
    std::vector<SurfaceDesc> surfaces;
    std::vector<MediumDesc> media;
    IntegratorDesc integrator;
    std::string output;               // default image path from the file ("" when not given)
    std::vector<std::string> inputs;  // every file read to build it: the scene, Includes, meshes
    // Found by a reader that needed it for its own checks (pbrt's MediumInterface), so that the
    // scene is not nested twice; null: found when the scene is built. Media's meshes fixed.
    std::shared_ptr<const MediaNesting> nesting;
};

}  // namespace tetglow
