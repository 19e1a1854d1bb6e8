#include "scene/LightSelection.h"

namespace tetglow {

namespace {

double weight(const Light& light, const glm::dvec3& p, bool mis) {
    return mis && light.isEnvironment() ? 0 : light.importance(p);
}

double totalWeight(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p, bool mis) {
    double total = 0;
    for (const auto& light : lights) total += weight(*light, p, mis);
    return total;
}

}  // namespace

LightChoice chooseLight(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p, bool mis, double u) {
    // Each light's importance once: it is the costly part (a solid angle per area light).
    thread_local std::vector<double> weights;
    weights.clear();
    double total = 0;
    for (const auto& light : lights) total += weights.emplace_back(weight(*light, p, mis));
    if (!(total > 0)) return {};
    // The first light whose running sum passes u * total; the last one with weight if rounding
    // leaves u * total beyond the sum.
    const double target = u * total;
    double sum = 0;
    LightChoice choice;
    for (size_t i = 0; i < lights.size(); ++i) {
        const double w = weights[i];
        if (w <= 0) continue;
        choice = {lights[i].get(), w / total};
        if ((sum += w) > target) break;
    }
    return choice;
}

double choicePmf(const std::vector<std::unique_ptr<Light>>& lights, const Light& light, const glm::dvec3& p, bool mis) {
    const double total = totalWeight(lights, p, mis);
    return total > 0 ? weight(light, p, mis) / total : 0;
}

}  // namespace tetglow
