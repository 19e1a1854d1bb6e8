#include "scene/PbrtTokenizer.h"

#include <utility>

#include "base/Error.h"
#include "base/InputFile.h"

namespace tetglow {
namespace {

constexpr size_t kMaxIncludeDepth = 64;  // deeper is a file that includes itself

bool isSpace(char c) { return c == ' ' || c == '\n' || c == '\t' || c == '\r'; }

// pbrt-v3's escapes in quoted strings.
char unescape(char c, const PbrtLocation& at) {
    switch (c) {
        case 'b': return '\b';
        case 'f': return '\f';
        case 'n': return '\n';
        case 'r': return '\r';
        case 't': return '\t';
        case '\\':
        case '\'':
        case '"': return c;
    }
    pbrtError(at, std::string("unknown escape \\") + c + " in a string");
}

}  // namespace

void pbrtError(const PbrtLocation& at, const std::string& message) { throw InputError(at.str() + ": " + message); }

void pbrtWarn(std::vector<std::string>& warnings, const PbrtLocation& at, const std::string& message,
              const char* kind) {
    addWarning(warnings, at.str() + ": " + kind + ": " + message);
}

PbrtTokenizer::PbrtTokenizer(const std::string& path) {
    files_.push_back({path, readInputFile(path, kMaxSceneFileBytes, "a pbrt file")});
}

void PbrtTokenizer::include(const std::string& path, const PbrtLocation& from) {
    if (files_.size() >= kMaxIncludeDepth)
        pbrtError(from, "Include nested more than 64 deep (does a file include itself?)");
    try {
        files_.push_back({path, readInputFile(path, kMaxSceneFileBytes, "a pbrt file")});
    } catch (const InputError& e) {
        pbrtError(from, std::string("Include: ") + e.what());
    }
}

void PbrtTokenizer::unget(PbrtToken token) { pending_ = std::move(token); }

std::optional<PbrtToken> PbrtTokenizer::next() {
    if (pending_) return std::exchange(pending_, std::nullopt);
    while (!files_.empty()) {
        if (auto token = scan(files_.back())) return token;
        if (files_.size() == 1) return std::nullopt;
        files_.pop_back();
    }
    return std::nullopt;
}

std::optional<PbrtToken> PbrtTokenizer::scan(Source& s) {
    const std::string& t = s.text;
    while (s.pos < t.size()) {
        const char c = t[s.pos];
        if (isSpace(c)) {
            s.line += c == '\n';
            ++s.pos;
            continue;
        }
        if (c == '#') {
            while (s.pos < t.size() && t[s.pos] != '\n' && t[s.pos] != '\r') ++s.pos;
            continue;
        }
        const PbrtLocation at{s.file, s.line};  // where the token starts: copies the path, so once per token
        if (c == '[' || c == ']') {
            ++s.pos;
            return PbrtToken{c == '[' ? PbrtToken::Kind::Open : PbrtToken::Kind::Close, std::string(1, c), at};
        } else if (c == '"') {
            std::string text;
            for (++s.pos;; ++s.pos) {
                if (s.pos >= t.size() || t[s.pos] == '\n') pbrtError(at, "unterminated string");
                if (t[s.pos] == '"') break;
                if (t[s.pos] == '\\') {
                    if (++s.pos >= t.size()) pbrtError(at, "unterminated string");
                    text += unescape(t[s.pos], at);
                } else {
                    text += t[s.pos];
                }
            }
            ++s.pos;
            return PbrtToken{PbrtToken::Kind::String, std::move(text), at};
        } else {
            const size_t start = s.pos;
            while (s.pos < t.size() && !isSpace(t[s.pos]) && t[s.pos] != '"' && t[s.pos] != '[' && t[s.pos] != ']')
                ++s.pos;
            return PbrtToken{PbrtToken::Kind::Word, t.substr(start, s.pos - start), at};
        }
    }
    return std::nullopt;
}

}  // namespace tetglow
