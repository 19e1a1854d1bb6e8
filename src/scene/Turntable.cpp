#include "scene/Turntable.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

namespace tetglow {

CameraDesc cameraAtFrame(const SceneDesc& scene, int frame) {
    const TurntableDesc& t = scene.turntable;
    CameraDesc c = scene.camera;
    if (frame == 0) return c;  // exactly the camera as given, not a rotation by 0 rounded
    const double angle = glm::radians(t.degrees * frame / t.frames);
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1), angle, glm::normalize(t.axis)));
    c.position = t.center + turn * (c.position - t.center);
    c.lookAt = t.center + turn * (c.lookAt - t.center);
    c.up = turn * c.up;
    return c;
}

}  // namespace tetglow
