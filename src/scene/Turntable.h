// The camera of one frame of a scene's turntable (SceneDesc::turntable).
#pragma once
#include "scene/SceneDescription.h"

namespace tetglow {

// The scene's camera turned for frame `frame` in 0 .. frames - 1 (frame 0 is the camera as given).
CameraDesc cameraAtFrame(const SceneDesc& scene, int frame);

}  // namespace tetglow
