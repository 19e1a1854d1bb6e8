#include "scene/Scene.h"

#include <chrono>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "scene/DensityField.h"
#include "scene/VolumePartition.h"
#include "tet/SurfaceBVH.h"

namespace tetglow {

namespace {

std::vector<glm::dvec3> unitNormals(const std::vector<glm::dvec3>& positions,
                                    const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::vector<glm::dvec3> normals;
    normals.reserve(triangles.size());
    for (const auto& t : triangles)
        normals.push_back(
            glm::normalize(glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]])));
    return normals;
}

double sceneScale(const SceneDesc& desc) {
    double scale = glm::length(desc.camera.position);
    auto extend = [&](const TriangleMesh& mesh) {
        for (const auto& p : mesh.positions)
            scale = std::max(scale, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    };
    for (const auto& s : desc.surfaces) extend(s.mesh);
    for (const auto& m : desc.media) extend(m.boundary);
    return std::max(scale, 1.0);
}

// 64 float ulps at the scene's largest coordinate (the camera's included): beyond Embree's
// rounding of hit points.
double rayEpsilonOf(const SceneDesc& desc) { return 64 * 0x1.0p-23 * sceneScale(desc); }

}  // namespace

void Scene::setCoefficients(SceneVolume& volume) const {
    std::vector<MediumField> regions;
    for (int i : volume.regionMedium) {
        const MediumDesc& desc = desc_.media[i];
        MediumField r{{desc.sigmaA, desc.sigmaS, desc.g, desc.emission}, {}};
        if (desc.density.isConstant()) {
            // A constant density only scales the coefficients.
            r.params.sigmaA *= desc.density.offset;
            r.params.sigmaS *= desc.density.offset;
            r.params.emission *= desc.density.offset;
        } else {
            r.vertexDensity = evaluateDensity(desc.density, volume.volume->mesh().vertices);
        }
        regions.push_back(std::move(r));
    }
    volume.volume->setRegions(std::move(regions));
}

void Scene::buildVolumes() {
    const std::vector<MediumDesc>& media = desc_.media;
    media_.resize(media.size());
    for (const std::vector<int>& members : findVolumes(media, desc_.nesting.get())) {
        SceneVolume v;
        std::vector<TriangleMesh> surfaces;
        std::vector<std::string> names;
        for (int i : members) {
            surfaces.push_back(media[i].boundary);
            names.push_back(media[i].name);
            v.name += (v.name.empty() ? "" : " + ") + media[i].name;
            media_[i] = {media[i].name, int(volumes_.size()), int32_t(v.regionMedium.size())};
            v.regionMedium.push_back(i);
        }
        // One medium alone names itself in its errors (as the loader names it), a volume of several media each by its
        // mesh.
        try {
            TetMesh mesh =
                tetrahedralize(std::move(surfaces), members.size() == 1 ? std::vector<std::string>{""} : names,
                               volumeTetOptions(media, members), &v.stats, &v.repairs);
            v.steinerPoints = mesh.vertices.size() - mesh.surfaceVertexCount;
            interfaceMaterials(mesh, media, members, v.triangleMaterial, v.materials);
            std::vector<bool> stops;
            for (size_t s = 0; s < mesh.surface.size(); ++s)
                stops.push_back(mesh.surfaceRegions[s][1] >= 0 &&
                                v.materials[v.triangleMaterial[s]].type != MaterialType::Interface);
            v.volume = std::make_unique<Volume>(MediumParams{}, std::move(mesh));
            v.volume->setStops(std::move(stops));
        } catch (const InputError& e) {
            if (members.size() > 1) throw;
            throw InputError(media[members[0]].name + ": " + e.what());
        }
        setCoefficients(v);
        volumes_.push_back(std::move(v));
    }
}

void Scene::classifyVolumes() {
    surfacesWithin_.clear();
    sealed_.clear();
    for (const SceneVolume& v : volumes_) {
        const Bounds3& box = v.volume->traversal().bounds();
        bool within = false, lightWithin = false;
        for (const auto& [shape, kind] : shapeBounds_) {
            const bool overlaps = shape.overlaps(box, 4 * epsilon_);
            within = within || overlaps;
            lightWithin = lightWithin || (overlaps && kind == HitKind::Light);
        }
        for (const LightDesc& l : desc_.lights)
            if (l.type == LightType::Point || l.type == LightType::Spot) {
                Bounds3 at;
                at.extend(l.position);
                lightWithin = lightWithin || at.overlaps(box, l.radius + 4 * epsilon_);
            }
        surfacesWithin_.push_back(within);
        const TetMesh& mesh = v.volume->mesh();
        bool refracting = true;  // every outer boundary triangle
        for (size_t s = 0; s < mesh.surface.size() && refracting; ++s)
            if (mesh.surfaceRegions[s][1] < 0)
                refracting = v.materials[v.triangleMaterial[s]].type == MaterialType::Dielectric;
        sealed_.push_back(refracting && !lightWithin);
    }
}

Scene::Scene(const SceneDesc& desc) : desc_(desc), camera_(desc.camera) {
    epsilon_ = rayEpsilonOf(desc);
    const auto start = std::chrono::steady_clock::now();
    buildVolumes();
    tetSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& surface : desc.surfaces) geometry_.extend(bounds(surface.mesh));
    for (const auto& v : volumes_) geometry_.extend(v.volume->traversal().bounds());
    lightsAlone_ = geometry_.empty();
    if (lightsAlone_) geometry_.extend(desc.camera.position);
    makeLights();

    for (SceneVolume& v : volumes_) {
        v.normals = unitNormals(v.volume->mesh().vertices, v.volume->mesh().surface);
        v.front = FrontExtent(v.volume->mesh());
    }
    surfaces_ = rtcNewScene(embreeDevice());
    all_ = rtcNewScene(embreeDevice());
    for (RTCScene s : {surfaces_, all_}) rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    const auto attach = [](RTCScene scene, std::vector<Geometry>& table, const Geometry& g,
                           const std::vector<glm::dvec3>& positions,
                           const std::vector<std::array<uint32_t, 3>>& triangles) {
        const unsigned id = attachTriangles(scene, positions, triangles);
        if (table.size() <= id) table.resize(id + 1);
        table[id] = g;
    };
    std::vector<std::pair<HitKind, uint32_t>> shapes;
    std::vector<TriangleMesh> meshes;
    for (uint32_t i = 0; i < desc.surfaces.size(); ++i) {
        TriangleMesh mesh = desc.surfaces[i].mesh;
        for (auto& p : mesh.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
        shapes.push_back({HitKind::Surface, i});
        meshes.push_back(std::move(mesh));
    }
    for (uint32_t i = 0; i < lights_.size(); ++i) {
        if (const TriangleMesh* shape = lights_[i]->shape()) {
            shapes.push_back({HitKind::Light, i});
            meshes.push_back(*shape);
        }
    }
    for (const TriangleMesh& m : meshes) normals_.push_back(unitNormals(m.positions, m.triangles));
    for (size_t k = 0; k < meshes.size(); ++k) shapeBounds_.emplace_back(bounds(meshes[k]), shapes[k].first);
    classifyVolumes();
    for (size_t k = 0; k < meshes.size(); ++k) {
        const Geometry g{shapes[k].first, shapes[k].second, uint32_t(k)};
        attach(surfaces_, surfaceGeometries_, g, meshes[k].positions, meshes[k].triangles);
        attach(all_, allGeometries_, g, meshes[k].positions, meshes[k].triangles);
    }
    // The boundary exactly as the tets have it: surface triangle ids are Embree primitive ids.
    for (uint32_t i = 0; i < volumes_.size(); ++i)
        attach(all_, allGeometries_, {HitKind::MediumBoundary, i, 0}, volumes_[i].volume->mesh().vertices,
               volumes_[i].volume->mesh().surface);
    rtcCommitScene(surfaces_);
    rtcCommitScene(all_);
}

Scene::~Scene() {
    rtcReleaseScene(surfaces_);
    rtcReleaseScene(all_);
}

void Scene::retuneMedia(const std::vector<MediumDesc>& media) {
    if (media.size() != media_.size()) throw std::invalid_argument("Scene::retuneMedia: a different number of media");
    for (size_t i = 0; i < media.size(); ++i) {
        const MediumDesc& old = desc_.media[i];
        const MediumDesc& m = media[i];
        if (m.boundary.positions != old.boundary.positions || m.boundary.triangles != old.boundary.triangles ||
            m.tetOptions.radiusEdgeRatio != old.tetOptions.radiusEdgeRatio ||
            m.tetOptions.maxVolume != old.tetOptions.maxVolume || m.cavity != old.cavity)
            throw std::invalid_argument("Scene::retuneMedia: medium " + m.name + " has other tets");
        desc_.media[i] = m;
    }
    for (SceneVolume& v : volumes_) setCoefficients(v);
}

void Scene::makeLights() {
    lights_.clear();
    environment_ = nullptr;
    // A light that is off emits nothing, where it is (its shape still blocks rays).
    const auto lit = [](LightDesc l) {
        if (!l.on) l.intensity = l.radiance = l.irradiance = RGB(0);
        return l;
    };
    // Constant environments add up: they become one light with the summed radiance, in the
    // place of the first, so that rays escaping and light samples see the same sky.
    LightDesc sky;
    sky.type = LightType::Environment;
    for (const auto& l : desc_.lights)
        if (l.type == LightType::Environment) sky.radiance += lit(l).radiance;
    for (const auto& l : desc_.lights) {
        if (l.type != LightType::Environment)
            lights_.push_back(makeLight(lit(l), geometry_));
        else if (!environment_) {
            lights_.push_back(makeLight(sky, geometry_));
            environment_ = lights_.back().get();
        }
    }
}

void Scene::retuneLights(const std::vector<LightDesc>& lights) {
    if (lights.size() != desc_.lights.size())
        throw std::invalid_argument("Scene::retuneLights: a different number of lights");
    for (size_t i = 0; i < lights.size(); ++i) {
        LightDesc& l = desc_.lights[i];
        if (lights[i].type != l.type)
            throw std::invalid_argument("Scene::retuneLights: light " + std::to_string(i) + " has another type");
        emissionOf(l) = emissionOf(lights[i]);
        l.on = lights[i].on;
    }
    makeLights();
}

void Scene::setCamera(const CameraDesc& camera) {
    desc_.camera = camera;
    camera_ = Camera(camera);
    // What a scene built with this camera has: the ray epsilon (the camera's distance from the
    // origin may set it), the volumes' classification that uses it, and in a scene of lights
    // alone, the bounds that lights at infinity aim their photons at.
    epsilon_ = rayEpsilonOf(desc_);
    classifyVolumes();
    if (lightsAlone_) {
        geometry_ = Bounds3();
        geometry_.extend(camera.position);
        makeLights();
    }
}

std::optional<Intersection> Scene::intersect(RTCScene scene, const std::vector<Geometry>& geometries, const Ray& ray,
                                             double tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = float(ray.o.x);
    rh.ray.org_y = float(ray.o.y);
    rh.ray.org_z = float(ray.o.z);
    rh.ray.dir_x = float(ray.d.x);
    rh.ray.dir_y = float(ray.d.y);
    rh.ray.dir_z = float(ray.d.z);
    rh.ray.tnear = float(epsilon_);
    rh.ray.tfar = tMax < 1e30 ? float(tMax) : INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const Geometry& g = geometries[rh.hit.geomID];
    Intersection hit;
    hit.t = rh.ray.tfar;
    hit.p = ray.at(hit.t);
    hit.triangle = rh.hit.primID;
    hit.kind = g.kind;
    hit.index = g.index;
    hit.n = normals(g)[rh.hit.primID];
    return hit;
}

std::optional<Intersection> Scene::intersect(const Ray& ray, double tMax) const {
    return intersect(ray, VolumeState{}, tMax);
}

std::optional<Intersection> Scene::intersect(const Ray& ray, const VolumeState& state, double tMax) const {
    if (state.inside())
        return surfacesWithin_[size_t(state.volume)] ? intersect(surfaces_, surfaceGeometries_, ray, tMax)
                                                     : std::nullopt;
    auto hit = intersect(surfaces_, surfaceGeometries_, ray, tMax);
    for (size_t v = 0; v < volumes_.size(); ++v) {
        double tFar = hit ? hit->t : tMax;
        if (state.left == int(v)) tFar = std::min(tFar, volumes_[v].front.reentryBefore(state.leftThrough, ray));
        if (!(tFar >= epsilon_)) continue;  // it cannot meet the volume again
        const auto entry = volumes_[v].volume->traversal().firstEntry(ray, epsilon_, tFar);
        if (!entry) continue;
        hit = Intersection{entry->exitT(),         ray.at(entry->exitT()),  volumes_[v].normals[entry->entryTriangle()],
                           entry->entryTriangle(), HitKind::MediumBoundary, uint32_t(v)};
    }
    return hit;
}

Intersection Scene::boundaryHit(int v, const Ray& ray, const WalkExit& exit) const {
    Intersection hit;
    hit.t = exit.t;
    hit.p = ray.at(exit.t);
    hit.triangle = exit.triangle;
    hit.touch = exit.tet == WalkExit::kTouch;
    hit.kind = HitKind::MediumBoundary;
    hit.index = uint32_t(v);
    hit.n = volumes_[v].normals[exit.triangle];
    return hit;
}

const MaterialDesc& Scene::material(const Intersection& hit) const {
    static const MaterialDesc black{MaterialType::Diffuse, RGB(0)}, pass{MaterialType::Interface};
    if (hit.touch) return pass;
    switch (hit.kind) {
        case HitKind::Surface: return desc_.surfaces[hit.index].material;
        case HitKind::MediumBoundary: {
            const SceneVolume& v = volumes_[hit.index];
            return v.materials[v.triangleMaterial[hit.triangle]];
        }
        case HitKind::Light: return black;
    }
    return black;
}

VolumeState Scene::afterHit(const Intersection& hit, const glm::dvec3& d, const VolumeState& before) const {
    if (hit.touch) return {};
    if (hit.kind == HitKind::MediumBoundary) {
        const TetMesh& mesh = volumes_[hit.index].volume->mesh();
        const bool behind = glm::dot(d, hit.n) < 0;
        if (mesh.surfaceRegions[hit.triangle][behind ? 0 : 1] < 0)
            return behind ? VolumeState{} : VolumeState{-1, {}, int(hit.index), hit.triangle};
        // From outside, the walk enters through the triangle by its exact tests; from a walk's
        // exit face, it starts in the tet on the chosen side.
        if (!before.inside() && mesh.surfaceRegions[hit.triangle][1] < 0)
            return {int(hit.index), WalkStart::surface(hit.triangle)};
        const uint32_t face = behind ? mesh.surfaceFace[hit.triangle] : mesh.surfaceFaceFront[hit.triangle];
        return {int(hit.index), WalkStart::inside(face >> 2)};
    }
    if (!before.inside()) return before;
    // A surface inside a medium: the path goes on in the same volume, from the tet at the hit.
    const int64_t tet = volumes_[before.volume].volume->traversal().locate(hit.p);
    return tet >= 0 ? VolumeState{before.volume, WalkStart::inside(uint32_t(tet))} : VolumeState{};
}

bool Scene::crossInterface(const Intersection& hit, Ray& ray, VolumeState& state, double* moved) const {
    if (moved) *moved = 0;
    if (!indexMatched(hit)) return false;
    const bool entering = !state.inside();
    state = afterHit(hit, ray.d, state);
    if (entering && state.inside() && state.start.throughSurface) return true;
    ray.o = hit.p;
    if (moved) *moved = hit.t;
    return true;
}

RGB Scene::emitted(const Ray& ray, const Intersection* hit) const {
    if (!hit) return environment_ ? environment_->emitted(ray.d, 0) : RGB(0);
    return hit->kind == HitKind::Light ? lights_[hit->index]->emitted(ray.d, hit->triangle) : RGB(0);
}

VolumeState Scene::volumeAt(const glm::dvec3& p) const {
    for (size_t v = 0; v < volumes_.size(); ++v)
        if (const int64_t tet = volumes_[v].volume->traversal().locate(p); tet >= 0)
            return {int(v), WalkStart::inside(uint32_t(tet))};
    return {};
}

std::optional<Intersection> Scene::intersectOpaque(const Ray& ray, double tMax) const {
    double t0 = 0;
    for (int crossings = 0; crossings < 256; ++crossings) {
        auto hit = intersect(all_, allGeometries_, Ray{ray.at(t0), ray.d}, tMax - t0);
        if (!hit) return std::nullopt;
        hit->t += t0;
        if (!indexMatched(*hit)) return hit;
        t0 = hit->t;
    }
    return std::nullopt;
}

}  // namespace tetglow
