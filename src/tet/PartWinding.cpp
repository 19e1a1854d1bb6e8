#include "tet/PartWinding.h"

#include <cmath>

namespace tetglow {

PartWinding::PartWinding(const TriangleMesh& soup, const std::vector<char>& closed) {
    closedPart_.positions = openPart_.positions = soup.positions;
    for (uint32_t t = 0; t < soup.triangles.size(); ++t)
        (closed[t] ? closedPart_ : openPart_).triangles.push_back(soup.triangles[t]);
    closed_ = std::make_unique<WindingNumber>(closedPart_);
    open_ = std::make_unique<WindingNumber>(openPart_);
}

long PartWinding::closedWinding(const glm::dvec3& p) const {
    // Whole off the surface: the tree's value rounds to it where its error is well below 1/2;
    // else the side of the half-way value between the two nearest wholes, certified.
    const double w = closed_->approximate(p);
    if (std::abs(w - std::round(w)) < 0.25) return std::lround(w);
    const double level = std::floor(w) + 0.5;
    return std::lround(level + (closed_->above(p, level) ? 0.5 : -0.5));
}

double PartWinding::approximate(const glm::dvec3& p) const {
    const long c = closedWinding(p);
    return c != 0 ? double(c) : open_->approximate(p);
}

double PartWinding::classify(const glm::dvec3& p) const {
    const long c = closedWinding(p);
    return c != 0 ? double(c) : open_->classify(p);
}

}  // namespace tetglow
