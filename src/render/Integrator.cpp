#include "render/Integrator.h"

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
            break;
    }
    throw InputError("the photon integrator is not available in this build yet (issue 4); use volpath or single");
}

}  // namespace tetglow
