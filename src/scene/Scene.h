// The scene ready to render: camera, lights, surfaces and tetrahedralized media. Embree holds
// the surfaces and area lights; where a ray enters a medium comes from the tets' exact tests
// (TetTraversal::firstEntry), and where it leaves from the walk, so no float hit ever places a
// medium's boundary.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <embree3/rtcore.h>

#include "media/Volume.h"
#include "scene/Camera.h"
#include "scene/Light.h"
#include "scene/SceneDescription.h"
#include "tet/FrontExtent.h"

namespace tetglow {

enum class HitKind { Surface, MediumBoundary, Light };

struct Intersection {
    double t = 0;
    glm::dvec3 p{0}, n{0};  // n: unit geometric normal, outward for a medium boundary
    uint32_t triangle = 0;
    HitKind kind = HitKind::Surface;
    uint32_t index = 0;  // which surface, volume or light
    bool touch = false;  // a walk found that the ray only touches this volume here: it passes
};

// The volume a path is in, and where its next walk through that volume's tets begins.
struct VolumeState {
    int volume = -1;  // -1: outside every medium
    WalkStart start;
    // Outside: the surface triangle `leftThrough` of volume `left` (-1: none) the path last
    // crossed on its way out of it. A ray meets that volume again only before the plane of the
    // triangle's FrontExtent, whatever its origin, so the triangle stays after later bounces.
    int left = -1;
    uint32_t leftThrough = 0;
    bool inside() const { return volume >= 0; }
};

// A medium of the description (or a cavity: a region with no medium), as a region of a volume.
struct MediumPlace {
    std::string name;
    int volume = 0;
    int32_t region = 0;
};

// Media that nest or touch, found from their meshes and tetrahedralized together: one Volume
// whose region r is the scene medium regionMedium[r]. A medium apart from all others is a volume alone.
struct SceneVolume {
    std::string name;                // its media's names, joined by " + "
    std::unique_ptr<Volume> volume;  // the tets, and each region's medium on them
    std::vector<int> regionMedium;   // per region: its medium's place in the description
    TetStats stats;
    std::vector<ValidationReport> repairs;  // per region: what validation welded, flipped or repaired
    size_t steinerPoints = 0;
    // Per surface triangle, what lies between the regions on its two sides: index-matched where
    // their indices of refraction are equal, else a dielectric with their ratio.
    std::vector<uint32_t> triangleMaterial;  // into materials
    std::vector<MaterialDesc> materials;
    std::vector<glm::dvec3> normals;  // per surface triangle, unit
    FrontExtent front;                // how far the volume reaches in front of each surface triangle
};

class Scene {
public:
    explicit Scene(const SceneDesc& desc);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    const SceneDesc& desc() const { return desc_; }
    // New coefficients and densities for every medium, on the tets it has (the boundary meshes
    // and TetGen options must be the ones it was built with); integrators made before are stale.
    void retuneMedia(const std::vector<MediumDesc>& media);
    // New emission (the emitted quantity and whether each light is on) for every light; their
    // types, places and shapes stay the scene's. Integrators made before are stale.
    void retuneLights(const std::vector<LightDesc>& lights);
    // Another image size or view: the scene is then as one built with this camera (its ray
    // epsilon included), so that it renders bit for bit the same.
    void setCamera(const CameraDesc& camera);
    const Camera& camera() const { return camera_; }
    const std::vector<std::unique_ptr<Light>>& lights() const { return lights_; }
    const std::vector<MediumPlace>& media() const { return media_; }
    const std::vector<SceneVolume>& volumes() const { return volumes_; }
    const Light* environment() const { return environment_; }
    double tetrahedralizeSeconds() const { return tetSeconds_; }
    // Rays leave a surface this far beyond it, so they do not hit it again.
    double rayEpsilon() const { return epsilon_; }

    // Closest hit with t in (rayEpsilon, tMax), a medium's entry exact; the ray's direction is
    // unit length.
    std::optional<Intersection> intersect(const Ray& ray, double tMax = INFINITY) const;
    // The closest hit for a path in `state`: outside the media every surface (a volume just left
    // searched only as far as it reaches); inside a volume only the surfaces and lights, as the
    // walk finds its boundary and interfaces exactly.
    std::optional<Intersection> intersect(const Ray& ray, const VolumeState& state, double tMax = INFINITY) const;
    // Where a walk through volume v left it or stopped at an interface: the point, normal and
    // triangle of the walk's exit face, not a float hit.
    Intersection boundaryHit(int v, const Ray& ray, const WalkExit& exit) const;
    // The material at a hit (surfaces and medium boundaries; lights are black diffuse).
    const MaterialDesc& material(const Intersection& hit) const;
    // The medium state after the path leaves `hit` in direction `d`, having been in `before`.
    VolumeState afterHit(const Intersection& hit, const glm::dvec3& d, const VolumeState& before) const;
    // Whether `hit` is index-matched (material "interface"): every ray crosses it unchanged.
    bool indexMatched(const Intersection& hit) const { return material(hit).type == MaterialType::Interface; }
    // Passes an index-matched boundary: when `hit` is one, updates `state` and the ray and
    // returns true. Entering a volume from outside keeps the ray, so that the walk finds the
    // exact entry on it (Embree's float hit only says which triangle); anywhere else the ray
    // restarts at the hit, and *moved receives how far along it that is (else 0).
    bool crossInterface(const Intersection& hit, Ray& ray, VolumeState& state, double* moved = nullptr) const;
    // Radiance reaching ray.o from an emitter the ray ends at: the environment where it
    // escapes (hit null), an area light it hit. (A camera path's weight applies.)
    RGB emitted(const Ray& ray, const Intersection* hit) const;
    // Whether every way out of volume v crosses a refracting (dielectric) boundary and no light
    // lies in its bounding box: no shadow ray from inside reaches a light, so next-event
    // estimation there is exactly 0 and is skipped; light gets in along specular paths only.
    bool sealed(int v) const { return sealed_[size_t(v)]; }
    // The volume and tet that hold point p (the camera), for starting paths.
    VolumeState volumeAt(const glm::dvec3& p) const;
    // The closest hit that is not an index-matched boundary (those pass light unchanged), as
    // the parity baseline found it: Embree's float hits on every surface, media boundaries and interfaces
    // included, whatever medium the ray is in (for the single-scattering baseline).
    std::optional<Intersection> intersectOpaque(const Ray& ray, double tMax = INFINITY) const;
    // No surface but index-matched boundaries between ray.o and ray.at(tMax) (media ignored).
    bool unoccluded(const Ray& ray, double tMax) const { return !intersectOpaque(ray, tMax); }

private:
    struct Geometry {
        HitKind kind;
        uint32_t index;
        uint32_t shape;  // a surface's or area light's place in normals_ (unused for a medium boundary)
    };
    std::vector<std::vector<glm::dvec3>> normals_;  // per surface and area light: unit, per triangle
    const std::vector<glm::dvec3>& normals(const Geometry& g) const {
        return g.kind == HitKind::MediumBoundary ? volumes_[g.index].normals : normals_[g.shape];
    }
    std::optional<Intersection> intersect(RTCScene scene, const std::vector<Geometry>& geometries, const Ray& ray,
                                          double tMax) const;
    void buildVolumes();
    // surfacesWithin_ and sealed_, from the surfaces' and area lights' bounds and the lights.
    void classifyVolumes();
    void setCoefficients(SceneVolume& volume) const;
    void makeLights();  // lights_ and environment_ from desc_.lights

    SceneDesc desc_;
    Camera camera_;
    std::vector<std::unique_ptr<Light>> lights_;
    const Light* environment_ = nullptr;
    Bounds3 geometry_;          // of the surfaces and media: where lights at infinity aim their photons
    bool lightsAlone_ = false;  // no surface or medium: geometry_ is the camera's position
    std::vector<std::pair<Bounds3, HitKind>> shapeBounds_;  // the surfaces' and area lights' meshes
    std::vector<MediumPlace> media_;
    std::vector<SceneVolume> volumes_;
    // By Embree geometry id in surfaces_ and in all_: kind and index, and per triangle the unit
    // normal (for a medium boundary, the volume's own).
    std::vector<Geometry> surfaceGeometries_, allGeometries_;
    RTCScene surfaces_ = nullptr;  // surfaces and area lights
    RTCScene all_ = nullptr;       // those and the media's boundaries: intersectOpaque only
    // Per volume: whether a surface or area light reaches into its bounding box. A path inside a
    // volume that none reaches meets nothing before the walk leaves it, so no Embree call is made.
    std::vector<bool> surfacesWithin_;
    std::vector<bool> sealed_;  // per volume, see sealed()
    double epsilon_ = 1e-6, tetSeconds_ = 0;
};

}  // namespace tetglow
