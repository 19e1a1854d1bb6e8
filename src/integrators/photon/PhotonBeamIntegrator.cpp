#include "integrators/photon/PhotonBeamIntegrator.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>

#include <tbb/parallel_for.h>

#include "integrators/DirectLighting.h"
#include "integrators/PathStep.h"
#include "integrators/photon/PhotonIntegrator.h"
#include "media/PhotonWalk.h"
#include "media/Roulette.h"
#include "media/SpectralPath.h"
#include "render/Material.h"
#include "tet/SurfaceBVH.h"

namespace tetglow {

namespace {

constexpr uint64_t kBeamStream = uint64_t(1) << 60;
constexpr uint64_t kBlock = 1024;

struct BeamQuery {
    RTCIntersectContext base;
    std::vector<uint32_t>* found;
};

void collect(const RTCFilterFunctionNArguments* args) {
    auto* q = reinterpret_cast<BeamQuery*>(args->context);
    q->found->push_back(RTCHitN_primID(args->hit, args->N, 0));
    args->valid[0] = 0;
}

}  // namespace

PhotonBeamIntegrator::PhotonBeamIntegrator(const Scene& scene, const IntegratorDesc& desc)
    : scene_(scene), desc_(desc), cameraMedium_(scene.mediumAt(scene.camera().position())), source_(scene) {}

PhotonBeamIntegrator::~PhotonBeamIntegrator() {
    if (bvh_) rtcReleaseScene(bvh_);
}

void PhotonBeamIntegrator::tracePath(uint64_t index, uint64_t pass, std::vector<Beam>& beams) const {
    Rng rng(desc_.seed, index, kBeamStream + pass);
    PhotonSource::Emission e = source_.sample(scene_, rng);
    const RGB flux = e.flux / double(desc_.photons);
    SpectralPath path = SpectralPath::pick(rng.uniform());
    Ray ray = e.ray;
    VolumeState state = e.medium;
    bool direct = !e.fromMedium;
    int depth = 0;
    double entry = 0;  // where the current ray entered the medium it is in
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        std::optional<Intersection> hit;
        WalkExit exit;
        if (state.inside()) {
            const RegionMedia& medium = *scene_.volumes()[state.volume].media;
            const int volume = state.volume;
            bool open = false;  // a beam begun at the current flight's start
            double openFrom = 0;
            double from = entry;  // the first flight starts where the ray entered
            const WalkResult walk = photonWalk(
                medium, ray, state.start, e.flux, path, rng, desc_.maxDepth - depth,
                [&](const Ray& r) {
                    static const bool all = getenv("BEAMDIRECT");
                    if (!direct || all) {
                        beams.push_back({r.at(from), r.d, INFINITY, path.beta * flux, path.r, path.hero, volume});
                        open = true;
                    }
                    openFrom = from;
                    from = 0;
                    hit = scene_.intersect(r, state);
                    return hit ? hit->t : INFINITY;
                },
                [&](const PhotonEvent& event) {
                    if (open) beams.back().length = glm::length(event.position - beams.back().o);
                    open = false;
                    direct = false;
                });
            depth += walk.events;
            if (open) beams.back().length = (walk.exit.left ? walk.exit.t : (hit ? hit->t : 0)) - openFrom;
            if (walk.absorbed) return;
            ray = walk.ray;
            exit = walk.exit;
        } else {
            hit = scene_.intersect(ray);
        }
        double moved = 0;
        const StretchEnd end = endStretch(scene_, hit, exit, ray, state, &moved);
        entry = end == StretchEnd::Crossed && moved == 0 ? hit->t : 0;
        if (end == StretchEnd::Crossed) continue;
        if (end != StretchEnd::Surface) return;
        const MaterialDesc& material = scene_.material(*hit);
        if (++depth >= desc_.maxDepth) return;
        const double u0 = rng.uniform(), u1 = rng.uniform();
        const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1}, TransportMode::Importance);
        path.beta *= bs.weight;
        direct = false;
        leaveSurface(scene_, *hit, bs.direction, ray, state);
        const double keep = photonSurvival(path.weight(), rng);
        if (keep == 0) return;
        path.beta /= keep;
    }
}

void PhotonBeamIntegrator::beginPass(uint64_t pass, const std::atomic<bool>*) {
    radius_ = desc_.radius * PhotonIntegrator::radiusScale(pass, PhotonIntegrator::balancedAlpha(1), 1);
    const uint64_t blocks = (desc_.photons + kBlock - 1) / kBlock;
    std::vector<std::vector<Beam>> parts(blocks);
    tbb::parallel_for(uint64_t(0), blocks, [&](uint64_t b) {
        for (uint64_t i = b * kBlock; i < std::min(desc_.photons, (b + 1) * kBlock); ++i) tracePath(i, pass, parts[b]);
    });
    beams_.clear();
    for (auto& part : parts)
        for (const Beam& beam : part)
            if (beam.length > 0 && std::isfinite(beam.length)) beams_.push_back(beam);
    if (bvh_) rtcReleaseScene(bvh_);
    bvh_ = nullptr;
    if (getenv("BEAMDBG")) fprintf(stderr, "pass %lu beams %zu r %g\n", (unsigned long)pass, beams_.size(), radius_);
    if (beams_.empty()) return;
    RTCDevice device = embreeDevice();
    bvh_ = rtcNewScene(device);
    rtcSetSceneFlags(bvh_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                          4 * sizeof(float), 2 * beams_.size()));
    auto* index = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), beams_.size()));
    const float r = float(radius_ * 1.001);
    for (size_t i = 0; i < beams_.size(); ++i) {
        const glm::dvec3 a = beams_[i].o, b = beams_[i].o + beams_[i].d * beams_[i].length;
        float* p = v + 8 * i;
        p[0] = float(a.x), p[1] = float(a.y), p[2] = float(a.z), p[3] = r;
        p[4] = float(b.x), p[5] = float(b.y), p[6] = float(b.z), p[7] = r;
        index[i] = unsigned(2 * i);
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(bvh_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(bvh_);
}

RGB PhotonBeamIntegrator::beamsAlong(const Ray& ray, double tStart, double tEnd, const RegionOptics& optics) const {
    static const bool off = getenv("BEAMOFF");
    if (off || !bvh_ || !(tEnd > 0)) return RGB(0);
    thread_local std::vector<uint32_t> found;
    found.clear();
    BeamQuery q{{}, &found};
    rtcInitIntersectContext(&q.base);
    q.base.filter = collect;
    RTCRayHit rh{};
    rh.ray.org_x = float(ray.o.x), rh.ray.org_y = float(ray.o.y), rh.ray.org_z = float(ray.o.z);
    rh.ray.dir_x = float(ray.d.x), rh.ray.dir_y = float(ray.d.y), rh.ray.dir_z = float(ray.d.z);
    rh.ray.tnear = 0;
    rh.ray.tfar = std::isfinite(tEnd) ? float(tEnd + radius_) : INFINITY;
    rh.ray.mask = UINT32_MAX;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    static const bool brute = getenv("BEAMBRUTE");
    if (brute)
        for (uint32_t i = 0; i < beams_.size(); ++i) found.push_back(i);
    else
        rtcIntersect1(bvh_, &q.base, &rh);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    RGB sum(0);
    for (uint32_t i : found) {
        const Beam& b = beams_[i];
        const glm::dvec3 w0 = ray.o - b.o;
        const double c = glm::dot(ray.d, b.d), dd = glm::dot(ray.d, w0), e = glm::dot(b.d, w0);
        const double sin2 = 1 - c * c;
        if (!(sin2 > 1e-8)) continue;
        const double t = (c * e - dd) / sin2, s = (e - c * dd) / sin2;
        if (t < tStart || t > tEnd || s < 0 || s > b.length) continue;
        const glm::dvec3 gap = w0 + t * ray.d - s * b.d;
        if (glm::dot(gap, gap) >= radius_ * radius_) continue;
        // The beam's flux at s, as its path's spectral MIS carries it past s.
        const RGB tr = exp(-optics.sigmaT * s);
        const RGB ratio = tr / tr[b.hero];
        const RGB flux = b.betaFlux * ratio / average(b.ratios * ratio);
        const double f = optics.phase.eval(-c);
        sum += flux * exp(-optics.sigmaT * (t - tStart)) * (f / (2 * radius_ * std::sqrt(sin2)));
    }
    return sum * optics.params.sigmaS;
}

RGB PhotonBeamIntegrator::singleAlong(const Ray& ray, const VolumeState& state, double tMax, const RegionOptics& optics,
                                      Rng& rng) const {
    static const bool all = getenv("BEAMDIRECT");
    if (all || scene_.sealed(state.volume)) return RGB(0);
    // Where a free flight of its own interacts on the stretch, lit by next-event estimation.
    const RegionMedia& medium = *scene_.volumes()[state.volume].media;
    SpectralPath path = SpectralPath::pick(rng.uniform());
    const FreeFlight f = medium.sampleFlight(ray, state.start, tMax, path.hero, rng.uniform(), path.r);
    if (!f.scattered) return RGB(0);
    path.interact(f.transmittance, optics.sigmaT * f.density);
    const VolumeState here{state.volume, f.located ? WalkStart::inside(f.tet) : WalkStart::inRegion(f.tet)};
    return path.weight() * f.density * optics.params.sigmaS *
           sampleDirect(scene_, ray.at(f.t), rng, false, phaseScattering(optics.phase, ray.d),
                        shadowRays(scene_, here, rng));
}

RGB PhotonBeamIntegrator::radiance(const Ray& cameraRay, Rng& rng) const {
    RGB L(0), beta(1);
    Ray ray = cameraRay;
    VolumeState state = cameraMedium_;
    int depth = 0;
    bool specular = true;
    double entry = 0;
    double lastPdf = 0;
    glm::dvec3 lastPoint = ray.o;
    for (int crossings = 0; crossings < kMaxCrossings; ++crossings) {
        auto hit = scene_.intersect(ray, state);
        FreeFlight flight;
        if (state.inside()) {
            const RegionMedia& medium = *scene_.volumes()[state.volume].media;
            const double tMax = hit ? hit->t : INFINITY;
            flight = medium.sampleFlight(ray, state.start, tMax, 0, 1.0);
            const double tEnd = flight.exit.left ? flight.exit.t : tMax;
            const RegionOptics& optics = medium.region(0);
            L += beta * (singleAlong(ray, state, tMax, optics, rng) + beamsAlong(ray, entry, tEnd, optics));
            beta *= flight.transmittance;
        }
        double moved = 0;
        const StretchEnd end = endStretch(scene_, hit, flight.exit, ray, state, &moved);
        entry = end == StretchEnd::Crossed && moved == 0 ? hit->t : 0;
        if (end == StretchEnd::Crossed) continue;
        if (end == StretchEnd::Escaped) {
            if (const Light* env = scene_.environment()) {
                const double w =
                    specular ? 1 : powerHeuristic(lastPdf, lightPdf(scene_, *env, lastPoint, ray.d, ray.o + ray.d, 0));
                L += beta * env->emitted(ray.d, 0) * w;
            }
            break;
        }
        if (end == StretchEnd::Emitter) {
            const Light& light = *scene_.lights()[hit->index];
            const double w =
                specular ? 1
                         : powerHeuristic(lastPdf, lightPdf(scene_, light, lastPoint, ray.d, hit->p, hit->triangle));
            L += beta * light.emitted(ray.d, hit->triangle) * w;
            break;
        }
        const MaterialDesc& material = scene_.material(*hit);
        if (++depth >= desc_.maxDepth) break;
        if (!isSpecular(material)) {
            const VolumeState here = scene_.afterHit(*hit, ray.d, state);
            L += beta * sampleDirect(
                            scene_, hit->p, rng, true,
                            [&](const glm::dvec3& wi) {
                                return Scattering{evaluateMaterial(material, ray.d, hit->n, wi),
                                                  materialPdf(material, ray.d, hit->n, wi)};
                            },
                            shadowRays(scene_, here, rng));
        }
        const double u0 = rng.uniform(), u1 = rng.uniform();
        const BsdfSample bs = sampleMaterial(material, ray.d, hit->n, {u0, u1});
        beta *= bs.weight;
        specular = bs.specular;
        lastPdf = bs.pdf;
        lastPoint = hit->p;
        leaveSurface(scene_, *hit, bs.direction, ray, state);
        if (isBlack(beta)) break;
        const double keep = eyePathSurvival(beta, depth, rng);
        if (keep == 0) break;
        beta /= keep;
    }
    return L;
}

}  // namespace tetglow
