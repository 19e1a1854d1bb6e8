// Scenes compared field by field, exactly: what the renderer sees must not change by a bit.
#pragma once
#include <string>

#include "scene/SceneDescription.h"

namespace tetglow::test {

void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, const std::string& what);
void expectSameMaterial(const MaterialDesc& a, const MaterialDesc& b, const std::string& what);
// Every field of the two scenes (but their paths and inputs) is equal.
void expectSameScene(const SceneDesc& a, const SceneDesc& b);

}  // namespace tetglow::test
