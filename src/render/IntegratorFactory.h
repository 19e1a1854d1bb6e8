// The integrator a scene description names, made for a scene: here, above every kind of integrator.
#pragma once
#include <memory>

#include "integrators/Integrator.h"
#include "render/IntegratorFactory.h"

namespace tetglow {

std::unique_ptr<Integrator> makeIntegrator(const Scene& scene, const IntegratorDesc& desc);

}  // namespace tetglow
