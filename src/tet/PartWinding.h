// The field the repair labels tets by. A closed part (a patch every edge of which joins two of
// its triangles) says for itself where it is inside: its winding number is whole off its
// surface, and the closed parts' sum C decides wherever it is not 0 (C >= 1 inside, C <= -1 a
// cavity). Elsewhere the open parts' generalized winding number decides, above 1/2 inside
// (Jacobson et al. 2013). So an open part cannot take a closed part's inside away (letters on
// a ground quad, where the quad's winding number is -1/2 above it) or fill a cavity whose own
// closed shell, wound inward, bounds it inside a solid with holes.
#pragma once
#include <memory>
#include <vector>

#include "tet/WindingNumber.h"

namespace tetglow {

class PartWinding {
public:
    // `closed[t]`: triangle t belongs to a closed part.
    PartWinding(const TriangleMesh& soup, const std::vector<char>& closed);

    // C where it is not 0 (then whole, and no tet is uncertain), else the open parts' winding
    // number (the tree's approximation).
    double approximate(const glm::dvec3& p) const;
    // The same, with the open parts' winding number on its exact side of 1/2 where it is near
    // (WindingNumber::classify).
    double classify(const glm::dvec3& p) const;
    // The closed parts' winding number C at a point off their surface, exactly.
    long closedWinding(const glm::dvec3& p) const;
    // The open parts' winding number (the tree's approximation).
    double openWinding(const glm::dvec3& p) const { return open_->approximate(p); }

private:
    TriangleMesh closedPart_, openPart_;
    std::unique_ptr<WindingNumber> closed_, open_;
};

}  // namespace tetglow
