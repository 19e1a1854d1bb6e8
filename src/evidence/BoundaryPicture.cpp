#include "evidence/BoundaryPicture.h"

#include <cmath>

#include <tbb/parallel_for.h>

#include "integrators/MarchStep.h"

namespace tetglow {

BoundaryPicture renderBoundaryPicture(const Camera& camera, const std::vector<const TetTraversal*>& media, double step,
                                      int parityRays) {
    struct Counts {
        size_t samples = 0, disagreements = 0, pixels = 0;
    };
    std::vector<Bounds3> boxes;
    Bounds3 all;
    for (const TetTraversal* v : media) {
        boxes.push_back(v->bounds());
        all.extend(boxes.back());
    }
    // Lengths shade by 1 - exp(-length / scale): a chord of a tenth of the scene's diagonal is clearly lit.
    const double scale = 0.1 * all.diagonal();
    checkMarchStep("the scene's step (/integrator/step)", step, all.diagonal(), resolutionOf(all, camera.position()));
    BoundaryPicture picture;
    picture.image = Image(camera.width(), camera.height());
    std::vector<Counts> rows(camera.height());
    tbb::parallel_for(0, camera.height(), [&](int y) {
        Counts& c = rows[y];
        for (int x = 0; x < camera.width(); ++x) {
            const Ray ray = camera.generateRay(x + 0.5, y + 0.5);
            double inside = 0, boxOnly = 0;
            size_t disagreements = 0;
            for (size_t m = 0; m < media.size(); ++m) {
                double t0 = 0, t1 = INFINITY;
                if (!clip(boxes[m], ray, t0, t1)) continue;
                int64_t tet = -1;
                for (double t = t0 + 0.5 * step; t < t1; t += step) {
                    const glm::dvec3 p = ray.at(t);
                    tet = media[m]->locate(p, tet);
                    const bool byTets = tet >= 0, byParity = insideByParity(media[m]->bvh(), p, parityRays);
                    ++c.samples;
                    if (byTets != byParity)
                        ++disagreements;
                    else
                        (byTets ? inside : boxOnly) += step;
                }
            }
            c.disagreements += disagreements;
            c.pixels += disagreements > 0;
            picture.image.at(x, y) =
                disagreements ? glm::vec3(1, 0, 1)
                              : glm::vec3(0.3 * (1 - std::exp(-boxOnly / scale)), 1 - std::exp(-inside / scale), 0);
        }
    });
    for (const Counts& c : rows) {
        picture.samples += c.samples;
        picture.disagreements += c.disagreements;
        picture.pixelsWithDisagreement += c.pixels;
    }
    return picture;
}

}  // namespace tetglow
