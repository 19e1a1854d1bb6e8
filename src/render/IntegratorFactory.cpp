#include "render/IntegratorFactory.h"

#include <algorithm>

#include "integrators/MarchStep.h"
#include "integrators/SingleScatterIntegrator.h"
#include "integrators/VolPathIntegrator.h"
#include "photon/PhotonIntegrator.h"

namespace tetglow {

std::unique_ptr<Integrator> makeIntegrator(const Scene& scene, const IntegratorDesc& desc) {
    if (desc.type == IntegratorType::Single ||
        (desc.type == IntegratorType::Photon && desc.estimate == PhotonEstimate::KnnMarch)) {
        double diagonal = 0;
        for (const auto& m : scene.volumes()) diagonal = std::max(diagonal, m.volume->traversal().bounds().diagonal());
        // Rays start anywhere in the scene: the coordinates resolve what the scene's ray offset does.
        checkMarchStep("step (/integrator/step or --step)", desc.stepSize, diagonal, scene.rayEpsilon());
    }
    switch (desc.type) {
        case IntegratorType::VolPath: return std::make_unique<VolPathIntegrator>(scene, desc.maxDepth);
        case IntegratorType::Single: return std::make_unique<SingleScatterIntegrator>(scene, desc);
        case IntegratorType::Photon: return std::make_unique<PhotonIntegrator>(scene, desc);
    }
    return nullptr;
}

}  // namespace tetglow
