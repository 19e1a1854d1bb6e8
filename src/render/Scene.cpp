#include "render/Scene.h"

#include <chrono>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "scene/DensityField.h"
#include "tet/MeshValidation.h"
#include "tet/RegionComplex.h"
#include "tet/SurfaceBVH.h"

namespace tetglow {

namespace {

std::vector<glm::dvec3> unitNormals(const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::vector<glm::dvec3> normals;
    normals.reserve(triangles.size());
    for (const auto& t : triangles)
        normals.push_back(glm::normalize(glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]])));
    return normals;
}

// The description's coefficients and density on the medium's tets.
void setCoefficients(Medium& medium, const MediumDesc& desc) {
    MediumParams params{desc.sigmaA, desc.sigmaS, desc.g, desc.emission};
    std::vector<double> density;
    if (desc.density.isConstant()) {
        // A constant density only scales the coefficients.
        params.sigmaA *= desc.density.offset, params.sigmaS *= desc.density.offset, params.emission *= desc.density.offset;
    } else {
        density = evaluateDensity(desc.density, medium.mesh().vertices);
    }
    medium.setParams(params, std::move(density));
}

SceneMedium buildMedium(const MediumDesc& desc) {
    SceneMedium m;
    m.name = desc.name;
    m.boundary = desc.boundaryMaterial;
    try {
        TetMesh mesh = tetrahedralize(desc.boundary, desc.tetOptions, &m.stats);
        m.steinerPoints = mesh.vertices.size() - mesh.surfaceVertexCount;
        m.medium = std::make_unique<Medium>(MediumParams{}, std::move(mesh));
        setCoefficients(*m.medium, desc);
    } catch (const InputError& e) {
        throw InputError(desc.name + ": " + e.what());
    }
    return m;
}

// Media must lie apart. Crossing media are an error in any case (naming both and a triangle
// pair); nested or touching ones would be regions of one tet mesh, which the integrators do not
// render yet, so they are refused rather than rendered wrong.
void checkMediaApart(const std::vector<MediumDesc>& media) {
    if (media.size() < 2) return;
    std::vector<TriangleMesh> surfaces;
    std::vector<std::string> names;
    for (const auto& m : media) {
        surfaces.push_back(m.boundary);
        names.push_back(m.name);
        try {
            validateAndRepair(surfaces.back());
        } catch (const InputError& e) {
            throw InputError(m.name + ": " + e.what());
        }
    }
    const RegionComplex regions = buildRegionComplex(surfaces, names);
    for (size_t i = 0; i < media.size(); ++i)
        if (const int32_t p = regions.parent[i]; p >= 0)
            throw InputError(names[i] + " lies inside " + names[p] + ": nested media are not rendered yet");
    for (size_t s = 0; s < regions.sides.size(); ++s)
        if (const int32_t front = regions.sides[s][1]; front >= 0)
            throw InputError(names[regions.sides[s][0]] + " and " + names[front] +
                             " share triangles: touching media are not rendered yet");
}

double sceneScale(const SceneDesc& desc) {
    double scale = glm::length(desc.camera.position);
    auto extend = [&](const TriangleMesh& mesh) {
        for (const auto& p : mesh.positions) scale = std::max(scale, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    };
    for (const auto& s : desc.surfaces) extend(s.mesh);
    for (const auto& m : desc.media) extend(m.boundary);
    return std::max(scale, 1.0);
}

}  // namespace

Scene::Scene(const SceneDesc& desc) : desc_(desc), camera_(desc.camera) {
    // 64 float ulps at the scene's largest coordinate: beyond Embree's rounding of hit points.
    epsilon_ = 64 * 0x1.0p-23 * sceneScale(desc);
    const auto start = std::chrono::steady_clock::now();
    checkMediaApart(desc.media);
    for (const auto& m : desc.media) media_.push_back(buildMedium(m));
    tetSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Bounds3 geometry;
    for (const auto& surface : desc.surfaces) geometry.extend(bounds(surface.mesh));
    for (const auto& m : media_) geometry.extend(m.medium->volume().bounds());
    if (geometry.empty()) geometry.extend(desc.camera.position);  // nothing but lights
    // Constant environments add up: they become one light with the summed radiance, in the
    // place of the first, so that rays escaping and light samples see the same sky.
    LightDesc sky;
    sky.type = LightType::Environment;
    for (const auto& l : desc.lights)
        if (l.type == LightType::Environment) sky.radiance += l.radiance;
    for (const auto& l : desc.lights) {
        if (l.type != LightType::Environment) lights_.push_back(makeLight(l, geometry));
        else if (!environment_) lights_.push_back(makeLight(sky, geometry)), environment_ = lights_.back().get();
    }

    scene_ = rtcNewScene(embreeDevice());
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    auto add = [&](HitKind kind, uint32_t index, const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles) {
        const unsigned id = attachTriangles(scene_, positions, triangles);
        if (geometries_.size() <= id) geometries_.resize(id + 1), normals_.resize(id + 1);
        geometries_[id] = {kind, index};
        normals_[id] = unitNormals(positions, triangles);
    };
    for (uint32_t i = 0; i < desc.surfaces.size(); ++i) {
        TriangleMesh mesh = desc.surfaces[i].mesh;
        for (auto& p : mesh.positions) p = {roundToFloat(p.x), roundToFloat(p.y), roundToFloat(p.z)};
        add(HitKind::Surface, i, mesh.positions, mesh.triangles);
    }
    // The boundary exactly as the tets have it: surface triangle ids are Embree primitive ids.
    for (uint32_t i = 0; i < media_.size(); ++i) add(HitKind::MediumBoundary, i, media_[i].medium->mesh().vertices, media_[i].medium->mesh().surface);
    for (uint32_t i = 0; i < lights_.size(); ++i)
        if (const TriangleMesh* shape = lights_[i]->shape()) add(HitKind::Light, i, shape->positions, shape->triangles);
    rtcCommitScene(scene_);
}

Scene::~Scene() { rtcReleaseScene(scene_); }

void Scene::retuneMedia(const std::vector<MediumDesc>& media) {
    if (media.size() != media_.size()) throw std::invalid_argument("Scene::retuneMedia: a different number of media");
    for (size_t i = 0; i < media.size(); ++i) {
        const MediumDesc& old = desc_.media[i];
        const MediumDesc& m = media[i];
        if (m.boundary.positions != old.boundary.positions || m.boundary.triangles != old.boundary.triangles ||
            m.tetOptions.radiusEdgeRatio != old.tetOptions.radiusEdgeRatio || m.tetOptions.maxVolume != old.tetOptions.maxVolume)
            throw std::invalid_argument("Scene::retuneMedia: medium " + m.name + " has other tets");
        setCoefficients(*media_[i].medium, m);
        desc_.media[i] = m;
    }
}

void Scene::setCamera(const CameraDesc& camera) {
    desc_.camera = camera;
    camera_ = Camera(camera);
}

std::optional<Intersection> Scene::intersect(const Ray& ray, double tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = float(ray.o.x), rh.ray.org_y = float(ray.o.y), rh.ray.org_z = float(ray.o.z);
    rh.ray.dir_x = float(ray.d.x), rh.ray.dir_y = float(ray.d.y), rh.ray.dir_z = float(ray.d.z);
    rh.ray.tnear = float(epsilon_);
    rh.ray.tfar = tMax < 1e30 ? float(tMax) : INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    Intersection hit;
    hit.t = rh.ray.tfar;
    hit.p = ray.at(hit.t);
    hit.triangle = rh.hit.primID;
    hit.kind = geometries_[rh.hit.geomID].kind;
    hit.index = geometries_[rh.hit.geomID].index;
    hit.n = normals_[rh.hit.geomID][rh.hit.primID];
    return hit;
}

const MaterialDesc& Scene::material(const Intersection& hit) const {
    static const MaterialDesc black{MaterialType::Diffuse, RGB(0)};
    switch (hit.kind) {
        case HitKind::Surface: return desc_.surfaces[hit.index].material;
        case HitKind::MediumBoundary: return media_[hit.index].boundary;
        case HitKind::Light: return black;
    }
    return black;
}

MediumState Scene::afterHit(const Intersection& hit, const glm::dvec3& d, const MediumState& before) const {
    if (hit.kind == HitKind::MediumBoundary) {
        if (glm::dot(d, hit.n) < 0) return {int(hit.index), WalkStart::surface(hit.triangle)};
        return {};
    }
    if (!before.inside()) return before;
    // A surface inside a medium: the path goes on in the same medium, from the tet at the hit.
    const int64_t tet = media_[before.medium].medium->volume().locate(hit.p);
    return tet >= 0 ? MediumState{before.medium, WalkStart::inside(uint32_t(tet))} : MediumState{};
}

bool Scene::crossInterface(const Intersection& hit, Ray& ray, MediumState& state) const {
    if (!indexMatched(hit)) return false;
    state = afterHit(hit, ray.d, state);
    ray.o = hit.p;
    return true;
}

RGB Scene::emitted(const Ray& ray, const Intersection* hit) const {
    if (!hit) return environment_ ? environment_->emitted(ray.d, 0) : RGB(0);
    return hit->kind == HitKind::Light ? lights_[hit->index]->emitted(ray.d, hit->triangle) : RGB(0);
}

MediumState Scene::mediumAt(const glm::dvec3& p) const {
    for (size_t m = 0; m < media_.size(); ++m)
        if (const int64_t tet = media_[m].medium->volume().locate(p); tet >= 0) return {int(m), WalkStart::inside(uint32_t(tet))};
    return {};
}

RGB Scene::transmittance(Ray ray, double tMax, MediumState state) const {
    RGB tr(1);
    for (int crossings = 0; crossings < 256; ++crossings) {
        const auto hit = intersect(ray, tMax);
        // An opaque or specular surface blocks the ray whatever lies before it: no walk needed.
        if (hit && !indexMatched(*hit)) return RGB(0);
        if (state.inside()) tr *= media_[state.medium].medium->transmittance(ray, state.start, hit ? hit->t : tMax);
        if (!hit) return tr;
        state = afterHit(*hit, ray.d, state);
        ray.o = hit->p;
        tMax -= hit->t;
    }
    return RGB(0);
}

std::optional<Intersection> Scene::intersectOpaque(const Ray& ray, double tMax) const {
    double t0 = 0;
    for (int crossings = 0; crossings < 256; ++crossings) {
        auto hit = intersect(Ray{ray.at(t0), ray.d}, tMax - t0);
        if (!hit) return std::nullopt;
        hit->t += t0;
        if (!indexMatched(*hit)) return hit;
        t0 = hit->t;
    }
    return std::nullopt;
}

}  // namespace tetglow
