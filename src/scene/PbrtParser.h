// pbrt-v3 scene files -> SceneDesc: the subset that media-in-mesh scenes use, with pbrt-v3's
// semantics (docs/FORMAT.md, "pbrt-v3 scenes"). Anything else is an InputError naming the
// directive, the file and the line.
#pragma once
#include <string>
#include <vector>

#include "scene/SceneDescription.h"

namespace tetglow {

// Warnings (unused parameters, features tetglow renders differently) are appended to
// `warnings`, one line each naming file and line; with no vector they go to stderr.
SceneDesc loadPbrtScene(const std::string& path, std::vector<std::string>* warnings = nullptr);

// True when the first token of `text`, after comments, is a pbrt-v3 directive.
bool looksLikePbrt(const std::string& text);

}  // namespace tetglow
