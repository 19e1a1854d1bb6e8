// pbrt-v3 scene text as tokens, each with the file and line it came from. Include switches to
// another file until its end, as pbrt-v3's parser does.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace tetglow {

struct PbrtLocation {
    std::string file;
    int line = 0;
    std::string str() const { return file + ":" + std::to_string(line); }
};

// Throws InputError "<file>:<line>: <message>".
[[noreturn]] void pbrtError(const PbrtLocation& at, const std::string& message);
// Adds "file:line: kind: message" to the warnings the caller prints.
void pbrtWarn(std::vector<std::string>& warnings, const PbrtLocation& at, const std::string& message,
              const char* kind = "warning");

struct PbrtToken {
    enum class Kind { Word, String, Open, Close };  // a directive or number; "..."; [; ]
    Kind kind = Kind::Word;
    std::string text;  // a string's contents without the quotes, escapes decoded
    PbrtLocation where;
};

class PbrtTokenizer {
public:
    explicit PbrtTokenizer(const std::string& path);
    // The next token of the innermost file, going back to the including file at its end;
    // nothing at the end of the first file. Comments are skipped.
    std::optional<PbrtToken> next();
    void unget(PbrtToken token);
    // Reads `path` next, up to its end.
    void include(const std::string& path, const PbrtLocation& from);

private:
    struct Source {
        std::string file, text;
        size_t pos = 0;
        int line = 1;
    };
    std::optional<PbrtToken> scan(Source& s);

    std::vector<Source> files_;
    std::optional<PbrtToken> pending_;
};

}  // namespace tetglow
