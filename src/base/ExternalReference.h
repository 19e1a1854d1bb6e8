// Files a model names besides itself (a glTF's buffers, a pbrt file's Include and plymesh): they
// must lie in the model's folder, or one below it, once ".." and links are resolved. A model from
// elsewhere could otherwise make a command read any file the user may read (/proc/self/environ,
// a key) and copy its bytes into an output. Trusted input may name any file when the environment
// sets TETGLOW_ALLOW_OUTSIDE_REFS=1 (docs/USAGE.md, "Hostile input").
#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace tetglow {

// A URI's RFC 3986 percent-decoding, as glTF writes references ("my%20scene.bin"); nullopt where
// a '%' is not followed by two hex digits.
std::optional<std::string> percentDecoded(const std::string& uri);

// Whether $TETGLOW_ALLOW_OUTSIDE_REFS is "1".
bool outsideReferencesAllowed();

// The file `reference` names (absolute, or relative to `folder`; "" stands for the working
// folder). InputError, one line for the caller to prefix with the model's name, when it lies
// outside `folder` and outsideReferencesAllowed() is false: "'<reference>' lies outside the
// model's folder: refusing to read it (TETGLOW_ALLOW_OUTSIDE_REFS=1 allows it)" (the model's
// name before it says which folder, and keeps the line short enough to print whole).
std::filesystem::path resolveReference(const std::filesystem::path& folder, const std::string& reference);
// The same check for a reference resolved elsewhere (a pbrt Include, relative to the including
// file): `path`, what `reference` leads to, must lie in `folder`.
void checkReference(const std::filesystem::path& path, const std::string& reference,
                    const std::filesystem::path& folder);

}  // namespace tetglow
