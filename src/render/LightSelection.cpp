#include "render/LightSelection.h"

namespace tetglow {

namespace {

double totalImportance(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p) {
    double total = 0;
    for (const auto& light : lights) total += light->importance(p);
    return total;
}

}  // namespace

LightChoice chooseLight(const std::vector<std::unique_ptr<Light>>& lights, const glm::dvec3& p, double u) {
    const double total = totalImportance(lights, p);
    if (!(total > 0)) return {};
    // The first light whose running sum passes u * total; the last one with weight if rounding
    // leaves u * total beyond the sum.
    const double target = u * total;
    double sum = 0;
    LightChoice choice;
    for (const auto& light : lights) {
        const double w = light->importance(p);
        if (w <= 0) continue;
        choice = {light.get(), w / total};
        if ((sum += w) > target) break;
    }
    return choice;
}

double choicePmf(const std::vector<std::unique_ptr<Light>>& lights, const Light& light, const glm::dvec3& p) {
    const double total = totalImportance(lights, p);
    return total > 0 ? light.importance(p) / total : 0;
}

}  // namespace tetglow
