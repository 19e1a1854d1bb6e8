// Volumetric photon mapping (Jensen and Christensen 1998), progressive (Knaus and Zwicker 2011).
// Each pass traces a fresh photon set (PhotonTracer) and takes one eye sample per pixel; the
// image is the mean of the passes while the radii shrink, so the error keeps falling with time.
//
// Eye rays follow specular chains (both branches of their first dielectric events, weighted by
// the Fresnel reflectance: eyePath) and never scatter in a medium. A light seen at the end of a
// specular chain (through glass), or a glowing medium seen along one, is estimated, in every
// pixel that can see a specular surface, by more rays spread over the pixel that follow the
// chain only (src/photon/SpecularChains.cpp): a small light there covers a sliver of a pixel,
// one sample in hundreds. Along each stretch of a volume (through its regions, up to where it
// leaves or meets a dielectric interface) the integrator adds, against the exact transmittance
// of the tet walk:
//   - emission, integrated in closed form;
//   - single scattering by next-event estimation, at a distance drawn by transmittance or, in a
//     spot light's cone, equiangularly towards the light (directAlong);
//   - multiple scattering (and light that reached the medium through glass) from the volume
//     photons, by the parity baseline's ray march with a k-NN lookup per step (`knn-march`, optionally
//     dividing by the part of the ball inside the medium) or by the beam radiance estimate
//     (`beam`: every photon ball the ray crosses, integrated exactly along the ray, no step).
// Photons are kept per medium (region), pooled over regions of one same medium that meet
// without an interface (PhotonDomains). Each domain that scatters gets, from a pilot before the
// render, the estimate whose predicted error at the render's pass count is lower: its photons,
// or the eye path walking it as volpath does (PhotonChoice). A photon is only ever found from the domain that
// scattered it, and a kernel's volume is its volume inside that domain (its boundary and the
// other media's and dielectric interfaces stop it). A diffuse surface gets direct light by next-event estimation and
// caustics from the surface photons with a cone filter; with final gathering (final_gather), the
// first diffuse surface of an eye path takes only the caustic photons (from a light by specular
// events alone) and gathers the rest by one more bounce, whose next diffuse surface takes all
// its photons (Jensen's final gather: the kernel's blur stays off what the eye sees directly).
//
// Which media the eye path walks (choose): where a kernel cannot resolve the light, the eye path
// walks a photon domain as volpath does, lit by next-event estimation, and a pass keeps no photons
// there. A pilot before the render measures, for each domain that scatters, the photon estimate's
// variance and its kernel's bias and the walk's variance, and gives the domain the estimate whose
// predicted error at the render's pass count is lower (PhotonChoice.h). Decided without it:
//   - a domain that does not scatter keeps photons;
//   - an optically dense domain (kDenseMeanFreePath) is walked;
//   - in a scene with a dielectric every other domain keeps photons (unmeasurable(): behind
//     glass the walk finds the light by chance only, a tail no pilot sees);
//   - a domain that fewer than kMinPilotProbes pilot pixels see keeps photons.
// An eye ray whose stretch meets a walked domain walks the whole stretch. Where every domain is
// walked and nothing is a dielectric, passes trace no photons (tracesPhotons).
#pragma once
#include <memory>
#include <vector>

#include "integrators/Integrator.h"
#include "integrators/VolPathIntegrator.h"
#include "photon/ClippedBall.h"
#include "photon/ColumnProfile.h"
#include "photon/PhotonChoice.h"
#include "photon/PhotonDiscs.h"
#include "photon/PhotonDomains.h"
#include "photon/PhotonMap.h"
#include "photon/PhotonTracer.h"

namespace tetglow {

struct PhotonStats {
    double tracingSeconds = 0;                                  // photon tracing and map building, all passes
    double pilotSeconds = 0;                                    // the pilot that chose each domain's estimate
    uint64_t paths = 0, volumePhotons = 0, surfacePhotons = 0;  // all passes
    size_t bytes = 0;                                           // the largest pass's maps
    EnergyBalance energy;                                       // all passes
};

// The estimate a photon domain got, and why.
struct DomainChoice {
    std::vector<int> media;  // the domain's scene media
    bool walked = false;     // the eye path walks it; else its photons are read
    // Chosen from the pilot's measurement (else: it does not scatter, or the scene has a
    // dielectric, where the walk finds caustic light by chance only and the pilot cannot see
    // that; then it is walked only if optically dense).
    bool measured = false;
    int probes = 0;                     // pilot eye paths that met it
    EstimateErrors errors;              // per pass, relative to the whole image
    uint64_t passes = 0;                // the render's: the count the prediction is for
    double photonMse = 0, walkMse = 0;  // predicted at `passes`
    uint64_t walksPayFrom = 0;          // the crossover (0: not within kMaxPredictedPasses)
};

class PhotonIntegrator : public Integrator {
public:
    // The pilot: this many probe pixels (a regular subset of the image), two independent passes
    // of photons (each read at two radii) and of eye paths.
    static constexpr int kPilotProbes = 4096;
    static constexpr uint64_t kMaxPredictedPasses = 1 << 16;
    // Fewer probes than this met a domain: too few to judge, and it keeps its photons (a 6 x 6
    // image's pilot walked a thin medium, whose 16 passes then read 4.5% off volpath's mean of
    // the 36 pixels, against 2% with photons).
    static constexpr int kMinPilotProbes = 100;

    PhotonIntegrator(const Scene& scene, const IntegratorDesc& desc);
    ~PhotonIntegrator() override;
    // The first pass runs the pilot (choose) if it has not run yet.
    void beginPass(uint64_t pass, const std::atomic<bool>* cancel = nullptr) override;
    // Measures, for every domain that scatters, both estimates on the pilot and sets `walked`
    // (src/photon/PhotonPilot.cpp); stops early, choosing nothing, once *cancel is set (a live render's
    // change: the pilot of a large photon count takes as long as several passes).
    void choose(const std::atomic<bool>* cancel = nullptr);
    RGB radiance(const Ray& ray, Rng& rng) const override;
    std::vector<std::string> warnings() const override;
    IntegratorStats stats() const override;  // the photons traced
    const PhotonStats& photonStats() const { return stats_; }
    // Whether passes trace photons. They do not when the eye path walks every medium (the rule
    // at the top of this file) and no surface or medium boundary is a dielectric: the only
    // photons left would be the diffuse surfaces', whose light paths with next-event estimation
    // carry without the kernel's bias and, measured, with less error at equal time. Each eye path
    // is then volpath's.
    bool tracesPhotons() const { return tracing_; }
    const std::vector<DomainChoice>& choices() const { return choices_; }

    // Radius factor of pass `pass` (from 0) for a kernel of dimension `dim`: the radius^dim
    // shrinks by (i + alpha) / (i + 1) from pass i to i + 1.
    static double radiusScale(uint64_t pass, double alpha, int dim);
    // The alpha of a kernel of dimension `dim` when the scene sets none: with it the variance
    // of the mean of N passes falls as N^-alpha and the kernel's squared bias (radius^4) as
    // N^(4 (alpha - 1) / dim), the same rate for 4 / (dim + 4) (Kaplanyan and Dachsbacher
    // 2013): 2/3 for discs, 4/7 for balls. A larger alpha leaves bias to dominate the error.
    static double balancedAlpha(int dim) { return 4.0 / (dim + 4); }

private:
    struct MediumPhotons {
        std::unique_ptr<PhotonMap> map;      // null when the pass stored none
        std::unique_ptr<PhotonDiscs> beams;  // beam estimate only
        // Beam estimate: 1 / the volume of each photon's ball, only the part inside the medium
        // with boundary correction, so that the kernel integrates to 1 over the medium.
        std::vector<float> invBallVolume;
        double largestRadius = 0;  // of this pass's photons: how far past a stretch balls reach
        float maxRadius = 0;
        bool walked = false;  // no photons: the eye path walks it as volpath does (see choose)
    };

    // The pilot's estimates at its probe pixels (src/photon/PhotonPilot.cpp); false where *cancel was set.
    struct PilotSamples;
    bool samplePilot(const std::vector<int>& measured, PilotSamples& pilot, const std::atomic<bool>* cancel);
    // Each measured domain's errors from the pilot, its predictions and its choice.
    void judge(const PilotSamples& pilot, const std::vector<int>& measured);
    // Which media a pass stores photons in, and whether it traces any, from the domains' choices.
    void storeUnwalked();
    // Traces the photons of pass `pass` (from `seed`) and builds their maps, the volume kernels at
    // `radiusFactor` times the radius of pass `radiusPass`.
    void loadPhotons(uint64_t seed, uint64_t pass, uint64_t radiusPass, double radiusFactor,
                     std::optional<std::chrono::steady_clock::time_point> deadline, const std::atomic<bool>* cancel);
    // Which light an eye path gathers. Light from a light or the environment at the end of a
    // specular chain (seen through glass), and light a medium emits along such a chain, is its own
    // term, `ChainLight`: from a small light or a small glowing medium it is rare and bright, as
    // it covers a sliver of the pixels that see it through the glass.
    enum class EyeLight { All, AllButChains, ChainLight };
    // One eye path. The domain `walkedToo` is walked as well (-1: none); `met`, if given, gets a 1
    // for each domain a stretch of the path reads photons from. ChainLight ends the path at its
    // first non-specular event and where it meets a walked domain.
    RGB eyePath(const Ray& ray, Rng& rng, int walkedToo, char* met, EyeLight light = EyeLight::All) const;
    // An eye path from where `b` stands. At its first kSplitDielectricEvents dielectric events
    // it follows both the reflected and the refracted branch, each weighted by its Fresnel
    // probability; later ones choose one by that probability.
    static constexpr int kSplitDielectricEvents = 2;
    struct EyeBranch {
        Ray ray;
        VolumeState state;
        RGB beta{1};
        int depth = 0;
        // After the final-gather bounce: emitters it reaches were counted by next-event estimation
        // or as caustics, and its next diffuse surface ends the path.
        bool gathering = false;
        int splits = kSplitDielectricEvents;
        EyeLight light = EyeLight::All;
    };
    RGB eyePath(EyeBranch b, Rng& rng, int walkedToo, char* met) const;
    // Pixels whose footprint (its corners and centre) meets a specular surface first split the
    // chain light: kChainSplits rays of their own, spread over the pixel, estimate it
    // (src/photon/SpecularChains.cpp). Any fixed choice of pixels keeps the image's expectation.
    static constexpr int kChainSplits = 5, kChainLatticeGenerator = 3;  // a Fibonacci lattice (5, 3)
    // chainPixels_ for the scene's camera, when it changed since the last call.
    void markChainPixels();
    // The pixel (row-major) that cameraRay passes through, when it splits the chain light; else -1.
    int chainPixel(const Ray& cameraRay) const;
    // The chain light of that pixel, from kChainSplits rays spread over it.
    RGB splitChainLight(int pixel, Rng& rng) const;
    // A chain light ray's stretch through volume v: its transmittance and, with `emission`, the
    // light media emit along it. Nothing on it scatters towards the eye in this term, so it needs
    // no column profile, and a region of constant density is crossed by one exit query.
    struct ChainStretch {
        RGB transmittance{1}, emitted{0};
        WalkExit exit;
    };
    ChainStretch chainStretch(int v, const Ray& ray, WalkStart start, double tMax, bool emission) const;
    // The light a medium emits along a piece of `column` (density integrated) whose start lies
    // at optical depth depthIn, in closed form.
    static RGB emittedOver(const Medium& medium, const RGB& depthIn, double column);

    // Light emitted towards ray.o along the stretch `column` of volume v, in closed form.
    RGB emittedAlong(int v, const ColumnProfile& column) const;
    // Light scattered towards ray.o along it: single scattering and the photons.
    RGB scatteredAlong(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const;
    RGB marchKnn(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const;
    RGB beamEstimate(int v, const Ray& ray, const ColumnProfile& column) const;
    // Single scattering at a distance drawn along the stretch, read off its column profile: by one
    // channel's transmittance (one-sample spectral MIS) or, where the stretch passes through the
    // cone a small light lights, equiangularly towards that light (one-sample MIS of the two,
    // half the samples each): a narrow spot light's beam is a sliver of a long stretch.
    RGB directAlong(int v, const Ray& ray, const ColumnProfile& column, Rng& rng) const;
    // The photons of `map` around p, nearest first: those within the fixed radius times `scale`,
    // or the k nearest within maxRadius. Returns the gather radius: the fixed one, or `scale`
    // times the k-th distance (maxRadius when fewer than k are within reach).
    double gather(const PhotonMap& map, const glm::dvec3& p, double scale, float maxRadius,
                  std::vector<Neighbour>& near) const;
    // sigma_s times in-scattered radiance from the volume photons at p in tet `tet` of volume v, seen along d.
    RGB knnEstimate(int v, uint32_t tet, const glm::dvec3& p, const glm::dvec3& d) const;
    int domainOf(int v, uint32_t tet) const;  // the photon domain whose region holds the tet
    // Surface photons of `map` around the hit, cone-filtered, reflected towards -d.
    RGB caustics(const PhotonMap* map, const Intersection& hit, const glm::dvec3& d,
                 const MaterialDesc& material) const;

    const Scene& scene_;
    IntegratorDesc desc_;
    VolumeState cameraMedium_;
    PhotonSource source_;
    PhotonDomains domains_;
    VolPathIntegrator volpath_;                                  // the eye path's walk through the domains it walks
    std::vector<std::unique_ptr<SurfaceBVH>> regionBoundaries_;  // per photon domain: its boundary's triangles
    std::vector<ClippedBall> balls_;                             // per photon domain, over its boundary
    std::vector<MediumPhotons> media_;                           // per photon domain
    std::vector<char> storedMedia_;       // per scene medium, whether a pass stores its photons (PhotonTracingOptions)
    std::unique_ptr<PhotonMap> surface_;  // every surface photon not straight from its light
    std::unique_ptr<PhotonMap> caustic_;  // those from a light by specular events only (final gathering)
    float surfaceMaxRadius_ = 0;
    bool chosen_ = false;                                            // the pilot has run
    bool tracing_ = true;                                            // see tracesPhotons()
    bool walksAny_ = false;                                          // the eye path walks some domain
    double volumeScale_ = 1, surfaceScale_ = 1;                      // this pass's radius factors
    std::optional<std::chrono::steady_clock::time_point> deadline_;  // of the time limit, if any
    PhotonStats stats_;
    std::vector<LightFocus> foci_;         // of the scene's point and spot lights
    std::vector<DomainChoice> choices_;    // per photon domain
    std::vector<char> chainPixels_;        // per pixel of the camera, row-major: it splits the chain light
    std::vector<glm::dvec3> chainCamera_;  // the camera chainPixels_ was marked for: position, corner rays
};

}  // namespace tetglow
