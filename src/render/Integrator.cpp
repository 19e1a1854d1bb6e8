#include "render/Integrator.h"

#include "render/PhotonIntegrator.h"
#include "render/SingleScatterIntegrator.h"
#include "render/VolPathIntegrator.h"

namespace tetglow {

std::unique_ptr<Integrator> makeIntegrator(const Scene& scene, const IntegratorDesc& desc) {
    switch (desc.type) {
        case IntegratorType::VolPath:
            return std::make_unique<VolPathIntegrator>(scene, desc.maxDepth);
        case IntegratorType::Single:
            return std::make_unique<SingleScatterIntegrator>(scene, desc);
        case IntegratorType::Photon:
            return std::make_unique<PhotonIntegrator>(scene, desc);
    }
    return nullptr;
}

}  // namespace tetglow
