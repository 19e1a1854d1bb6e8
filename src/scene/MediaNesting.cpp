#include "scene/MediaNesting.h"

#include <algorithm>
#include <set>

#include "tet/VolumeBoundary.h"

namespace tetglow {

MediaNesting nestMedia(const std::vector<MediumDesc>& media) {
    std::vector<TriangleMesh> surfaces;
    std::vector<std::string> names;
    for (const MediumDesc& m : media) {
        surfaces.push_back(m.boundary);
        names.push_back(m.name);
    }
    const bool strict =
        std::any_of(media.begin(), media.end(), [](const MediumDesc& m) { return m.tetOptions.strict; });
    const VolumeBoundary boundary = validatedBoundary(std::move(surfaces), names, strict);
    std::set<std::pair<int32_t, int32_t>> touching;
    for (const auto& [behind, front] : boundary.sides)
        if (behind >= 0 && front >= 0) touching.insert(std::minmax(behind, front));
    return {boundary.parent, {touching.begin(), touching.end()}};
}

}  // namespace tetglow
