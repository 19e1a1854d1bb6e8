#include "tet/SurfaceBVH.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace tetglow {

RTCDevice embreeDevice() {
    // One device for the process: Embree's thread pool and allocator are process-wide anyway.
    static RTCDevice device = [] {
        RTCDevice d = rtcNewDevice(nullptr);
        if (!d) throw std::runtime_error("cannot create an Embree device");
        return d;
    }();
    return device;
}

unsigned attachTriangles(RTCScene scene, const std::vector<glm::dvec3>& positions,
                         const std::vector<std::array<uint32_t, 3>>& triangles) {
    RTCGeometry geom = rtcNewGeometry(embreeDevice(), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), positions.size()));
    for (size_t i = 0; i < positions.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + k] = float(positions[i][k]);
    auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(uint32_t), triangles.size()));
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) idx[3 * t + k] = triangles[t][k];
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    return id;
}

SurfaceBVH::SurfaceBVH(const std::vector<glm::dvec3>& positions,
                       const std::vector<std::array<uint32_t, 3>>& triangles) {
    RTCDevice device = embreeDevice();
    scene_ = rtcNewScene(device);
    // Robust mode: watertight triangle tests, so rays through edges are not lost between faces.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    attachTriangles(scene_, positions, triangles);
    normals_.resize(triangles.size());
    corners_.resize(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        const glm::dvec3 a = positions[triangles[t][0]];
        normals_[t] = glm::cross(positions[triangles[t][1]] - a, positions[triangles[t][2]] - a);
        corners_[t] = a;
    }
    rtcCommitScene(scene_);

    // Each edge moved out by the margin: scaled about the incentre by (r + margin) / r. Embree's
    // rays start at the bounds (see candidates()), so its float error is about 1e-7 of the
    // bounds' extent; the margin is 1e-5 of it.
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    margin_ = 1e-5 * (glm::length(hi - lo) + glm::length(glm::max(glm::abs(lo), glm::abs(hi))));
    std::vector<glm::dvec3> grown;
    std::vector<std::array<uint32_t, 3>> separate;
    for (const auto& tri : triangles) {
        const glm::dvec3 a = positions[tri[0]], b = positions[tri[1]], c = positions[tri[2]];
        const double la = glm::distance(b, c), lb = glm::distance(c, a), lc = glm::distance(a, b),
                     perimeter = la + lb + lc;
        const glm::dvec3 incentre = (la * a + lb * b + lc * c) / perimeter;
        const double inradius = glm::length(glm::cross(b - a, c - a)) / perimeter;
        const double scale = (inradius + margin_) / inradius;
        const uint32_t first = uint32_t(grown.size());
        for (const glm::dvec3& p : {a, b, c}) grown.push_back(incentre + (p - incentre) * scale);
        separate.push_back({first, first + 1, first + 2});
    }
    for (const auto& p : grown) grownBounds_.extend(p);
    grown_ = rtcNewScene(device);
    // Not robust mode: the margin, not watertight tests, keeps a crossing at an edge from being
    // lost, and Embree's fast tests are about 10% quicker (bench_tet's BM_FirstEntry).
    rtcSetSceneFlags(grown_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    attachTriangles(grown_, grown, separate);
    rtcCommitScene(grown_);
}

SurfaceBVH::~SurfaceBVH() {
    rtcReleaseScene(scene_);
    rtcReleaseScene(grown_);
}

namespace {
thread_local uint64_t tQueries = 0;
}  // namespace

uint64_t surfaceQueries() { return tQueries; }

double SurfaceBVH::refine(const Ray& ray, uint32_t triangle, float t) const {
    // Embree's float t is off by ~1e-7 / sin(angle) at grazing angles; the plane equation in
    // double is not.
    const double nd = glm::dot(normals_[triangle], ray.d);
    return nd != 0 ? glm::dot(normals_[triangle], corners_[triangle] - ray.o) / nd : double(t);
}

namespace {

// The filter sees every candidate hit; these contexts decide which ones count.
struct QueryContext {
    RTCIntersectContext base;
    const SurfaceBVH* bvh;
    Ray ray;
    double shift;  // Embree's ray starts at ray.at(shift)
    double tnear;
    Facing facing;
    int* count = nullptr;  // when set: count and reject every hit
    // When set: pass every hit to visit, and reject it unless visit's answer shortens Embree's ray.
    void* visit = nullptr;
    double (*call)(void*, const SurfaceHit&) = nullptr;
    double margin = 0;      // how far past visit's answer Embree's ray ends
    float tfar = INFINITY;  // Embree's ray ends here
};

void filter(const RTCFilterFunctionNArguments* args) {
    auto* ctx = reinterpret_cast<QueryContext*>(args->context);
    if (ctx->count) {
        ++*ctx->count;
        args->valid[0] = 0;
        return;
    }
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, 0);
    // Embree's window is widened for float rounding; the exact window applies to the refined t.
    const double t = ctx->bvh->refine(ctx->ray, prim, float(ctx->shift + RTCRayN_tfar(args->ray, args->N, 0)));
    const bool entering = glm::dot(ctx->ray.d, ctx->bvh->normal(prim)) < 0;
    if (ctx->visit) {
        if (t >= ctx->tnear) {
            const double until = ctx->call(ctx->visit, {t, prim, entering});
            const double reach = until + ctx->margin + (until - ctx->tnear) / 8 - ctx->shift;
            // Only a hit Embree accepts keeps the tfar its filter sets (then it searches no further).
            if (const float end = std::nextafter(float(reach), INFINITY); end < ctx->tfar) {
                ctx->tfar = end;
                RTCRayN_tfar(args->ray, args->N, 0) = end;
                return;
            }
        }
        args->valid[0] = 0;
        return;
    }
    if (t < ctx->tnear || (ctx->facing == Facing::Entering && !entering)) args->valid[0] = 0;
}

RTCRayHit makeRay(const Ray& ray, double tnear, double tfar, double shift = 0) {
    RTCRayHit rh{};
    const glm::dvec3 o = ray.at(shift);
    tnear -= shift;
    tfar -= shift;
    rh.ray.org_x = float(o.x);
    rh.ray.org_y = float(o.y);
    rh.ray.org_z = float(o.z);
    rh.ray.dir_x = float(ray.d.x);
    rh.ray.dir_y = float(ray.d.y);
    rh.ray.dir_z = float(ray.d.z);
    // Rounded down by a margin above Embree's float error, so no hit at tnear is lost.
    rh.ray.tnear = float(std::max(tnear * (1 - 1e-6) - 1e-12, 0.0));
    rh.ray.tfar = std::isfinite(tfar) && tfar < 3e38 ? float(tfar) : INFINITY;
    rh.ray.mask = UINT32_MAX;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace

std::optional<SurfaceHit> SurfaceBVH::intersect(const Ray& ray, double tnear, double tfar, Facing facing) const {
    QueryContext ctx{{}, this, ray, 0, tnear, facing};
    rtcInitIntersectContext(&ctx.base);
    ctx.base.filter = filter;
    RTCRayHit rh = makeRay(ray, tnear, tfar);
    ++tQueries;
    rtcIntersect1(scene_, &ctx.base, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const uint32_t prim = rh.hit.primID;
    return SurfaceHit{std::max(tnear, refine(ray, prim, rh.ray.tfar)), prim, glm::dot(ray.d, normals_[prim]) < 0};
}

std::vector<SurfaceHit> SurfaceBVH::allHits(const Ray& ray, double tnear) const {
    std::vector<SurfaceHit> hits;
    auto collect = [&](const SurfaceHit& hit) {
        hits.push_back(hit);
        return INFINITY;
    };
    QueryContext ctx{{}, this, ray, 0, tnear, Facing::Any};
    ctx.visit = &collect;
    ctx.call = &callVisit<decltype(collect)>;
    rtcInitIntersectContext(&ctx.base);
    ctx.base.filter = filter;
    RTCRayHit rh = makeRay(ray, tnear, INFINITY);
    ++tQueries;
    rtcIntersect1(scene_, &ctx.base, &rh);
    std::sort(hits.begin(), hits.end(), [](const SurfaceHit& a, const SurfaceHit& b) { return a.t < b.t; });
    return hits;
}

int SurfaceBVH::crossings(const Ray& ray) const {
    int count = 0;
    QueryContext ctx{{}, this, ray, 0, 0, Facing::Any, &count};
    rtcInitIntersectContext(&ctx.base);
    ctx.base.filter = filter;
    RTCRayHit rh = makeRay(ray, 0, INFINITY);
    ++tQueries;
    rtcIntersect1(scene_, &ctx.base, &rh);
    return count;
}

std::vector<SurfaceHit> SurfaceBVH::candidates(const Ray& ray, double tnear, double tfar) const {
    std::vector<SurfaceHit> hits;
    visitCandidates(ray, tnear, tfar, [&](const SurfaceHit& hit) {
        hits.push_back(hit);
        return INFINITY;
    });
    return hits;
}

void SurfaceBVH::visitCandidates(const Ray& ray, double tnear, double tfar, void* visit, CandidateVisit call) const {
    // Embree's ray starts where the ray enters the bounds, a margin early, and ends a margin
    // late: its float rounding is then relative to the mesh, however far away the ray's own
    // origin is, and no crossing within [tnear, tfar] is cut off.
    const double margin = margin_ / glm::length(ray.d);
    double t0 = tnear, t1 = tfar + margin;
    if (!clip(grownBounds_, ray, t0, t1)) return;
    const double shift = t0 - margin;
    QueryContext ctx{{}, this, ray, shift, tnear, Facing::Any};
    ctx.visit = visit;
    ctx.call = call;
    ctx.margin = margin;
    rtcInitIntersectContext(&ctx.base);
    ctx.base.filter = filter;
    RTCRayHit rh = makeRay(ray, shift, t1 + margin, shift);
    ctx.tfar = rh.ray.tfar;
    ++tQueries;
    rtcIntersect1(grown_, &ctx.base, &rh);
}

}  // namespace tetglow
