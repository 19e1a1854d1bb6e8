#include "scene/PbrtParams.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "tet/TriangleMesh.h"  // shorten

namespace tetglow {
namespace {

using Class = PbrtParamClass;

// pbrt-v3's type names (parser.cpp lookupType).
Class classOf(const std::string& type, const PbrtLocation& at, const std::string& directive) {
    static const std::pair<const char*, Class> kTypes[] = {
        {"integer", Class::Integer},    {"float", Class::Float},      {"bool", Class::Bool},
        {"point2", Class::Point2},      {"vector2", Class::Vector2},  {"point3", Class::Point3},
        {"point", Class::Point3},       {"vector3", Class::Vector3},  {"vector", Class::Vector3},
        {"normal", Class::Normal},      {"string", Class::String},    {"texture", Class::Texture},
        {"rgb", Class::Spectrum},       {"color", Class::Spectrum},   {"xyz", Class::Spectrum},
        {"blackbody", Class::Spectrum}, {"spectrum", Class::Spectrum}};
    for (const auto& [name, cls] : kTypes)
        if (type == name) return cls;
    pbrtError(at, directive + ": unknown parameter type \"" + type + "\"");
}

bool takesStrings(Class c) { return c == Class::Bool || c == Class::String || c == Class::Texture; }

// How many numbers make one value of the type.
size_t groupSize(const PbrtParam& p) {
    switch (p.cls) {
        case Class::Point2:
        case Class::Vector2: return 2;
        case Class::Point3:
        case Class::Vector3:
        case Class::Normal: return 3;
        case Class::Spectrum: return p.type == "rgb" || p.type == "color" || p.type == "xyz" ? 3 : 2;
        default: return 1;
    }
}

void addValue(PbrtParam& p, const PbrtToken& t, const PbrtParams& owner) {
    if (t.kind == PbrtToken::Kind::String) {
        p.strings.push_back(t.text);
        return;
    }
    if (t.kind != PbrtToken::Kind::Word) owner.fail(p, "unexpected '" + t.text + "' among the values");
    char* end = nullptr;
    const double x = std::strtod(t.text.c_str(), &end);
    // pbrt-v3 stores its numbers as floats: a larger double is not a number it can read.
    if (t.text.empty() || *end != '\0' || !(std::abs(x) <= std::numeric_limits<float>::max()))
        owner.fail(p, "expected a finite number of float range (|x| <= 3.40282e38), got '" + shorten(t.text) + "'");
    p.numbers.push_back(x);
}

// The checks pbrt-v3 makes when it stores a parameter, as errors.
void check(const PbrtParam& p, const PbrtParams& owner) {
    if (p.numbers.empty() && p.strings.empty()) owner.fail(p, "no values");
    if (!p.numbers.empty() && !p.strings.empty()) owner.fail(p, "mixes strings and numbers");
    const bool strings = !p.strings.empty();
    if (takesStrings(p.cls) && !strings) owner.fail(p, "expected quoted strings");
    if (!takesStrings(p.cls) && strings && p.type != "spectrum") owner.fail(p, "expected numbers, not strings");
    if (p.numbers.size() % groupSize(p) != 0)
        owner.fail(p, "expected a multiple of " + std::to_string(groupSize(p)) + " numbers, got " +
                          std::to_string(p.numbers.size()));
    if (p.cls == Class::Integer)
        for (double x : p.numbers)
            if (x != std::floor(x) || std::abs(x) > 2147483647) owner.fail(p, "expected integers");
    if (p.cls == Class::Bool)
        for (const auto& s : p.strings)
            if (s != "true" && s != "false") owner.fail(p, "expected \"true\" or \"false\", got \"" + s + "\"");
}

}  // namespace

PbrtParams::PbrtParams(PbrtTokenizer& tokens, std::string directive) : directive_(std::move(directive)) {
    while (auto decl = tokens.next()) {
        if (decl->kind != PbrtToken::Kind::String) {
            tokens.unget(std::move(*decl));
            break;
        }
        PbrtParam p;
        p.where = decl->where;
        const size_t typeEnd = decl->text.find_first_of(" \t");
        const size_t nameStart = decl->text.find_first_not_of(" \t", typeEnd);
        if (typeEnd == std::string::npos || nameStart == std::string::npos)
            pbrtError(p.where, directive_ + ": \"" + decl->text + "\" is not a parameter declaration (\"type name\")");
        p.type = decl->text.substr(0, typeEnd);
        p.name = decl->text.substr(nameStart, decl->text.find_first_of(" \t", nameStart) - nameStart);
        p.cls = classOf(p.type, p.where, directive_);
        auto value = tokens.next();
        if (!value) fail(p, "the file ends before its value");
        if (value->kind == PbrtToken::Kind::Open) {
            for (value = tokens.next(); value && value->kind != PbrtToken::Kind::Close; value = tokens.next())
                addValue(p, *value, *this);
            if (!value) fail(p, "the file ends before ']'");
        } else {
            addValue(p, *value, *this);
        }
        check(p, *this);
        params_.push_back(std::move(p));
    }
}

PbrtParam* PbrtParams::find(const std::string& name, PbrtParamClass cls) {
    for (auto it = params_.rbegin(); it != params_.rend(); ++it)
        if (it->name == name && it->cls == cls) {
            it->used = true;
            return &*it;
        }
    return nullptr;
}

PbrtParam* PbrtParams::findOne(const std::string& name, PbrtParamClass cls, size_t count) {
    PbrtParam* p = find(name, cls);
    const size_t size = p && takesStrings(cls) ? p->strings.size() : p ? p->numbers.size() : 0;
    if (p && size != count) {
        const std::string noun = takesStrings(cls) ? "string" : "number";
        fail(*p, "expected " + std::to_string(count) + " " + noun + (count > 1 ? "s" : "") + ", got " +
                     std::to_string(size));
    }
    return p;
}

double PbrtParams::getFloat(const std::string& name, double fallback) {
    const PbrtParam* p = findOne(name, Class::Float, 1);
    return p ? p->numbers[0] : fallback;
}

int PbrtParams::getInt(const std::string& name, int fallback) {
    const PbrtParam* p = findOne(name, Class::Integer, 1);
    return p ? int(p->numbers[0]) : fallback;
}

bool PbrtParams::getBool(const std::string& name, bool fallback) {
    const PbrtParam* p = findOne(name, Class::Bool, 1);
    return p ? p->strings[0] == "true" : fallback;
}

std::string PbrtParams::getString(const std::string& name, const std::string& fallback) {
    const PbrtParam* p = findOne(name, Class::String, 1);
    return p ? p->strings[0] : fallback;
}

glm::dvec3 PbrtParams::getPoint(const std::string& name, const glm::dvec3& fallback) {
    const PbrtParam* p = findOne(name, Class::Point3, 3);
    return p ? glm::dvec3(p->numbers[0], p->numbers[1], p->numbers[2]) : fallback;
}

glm::dvec3 PbrtParams::getSpectrum(const std::string& name, const glm::dvec3& fallback) {
    const PbrtParam* p = find(name, Class::Spectrum);
    if (!p) return fallback;
    if (p->type != "rgb" && p->type != "color")
        fail(*p, "only RGB colours (\"rgb\" or \"color\") are supported, not \"" + p->type + "\"");
    return findOne(name, Class::Spectrum, 3) ? glm::dvec3(p->numbers[0], p->numbers[1], p->numbers[2]) : fallback;
}

std::vector<double> PbrtParams::getFloats(const std::string& name) {
    const PbrtParam* p = find(name, Class::Float);
    return p ? p->numbers : std::vector<double>{};
}

std::vector<int> PbrtParams::getInts(const std::string& name) {
    const PbrtParam* p = find(name, Class::Integer);
    return p ? std::vector<int>(p->numbers.begin(), p->numbers.end()) : std::vector<int>{};
}

std::vector<glm::dvec3> PbrtParams::getTriples(const std::string& name, PbrtParamClass cls) {
    std::vector<glm::dvec3> triples;
    if (const PbrtParam* p = find(name, cls))
        for (size_t i = 0; i + 2 < p->numbers.size(); i += 3)
            triples.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
    return triples;
}

void PbrtParams::fail(const PbrtParam& p, const std::string& message) const {
    pbrtError(p.where, directive_ + ": parameter " + p.declaration() + ": " + message);
}

void PbrtParams::reportUnused(std::vector<std::string>& warnings) const {
    for (const PbrtParam& p : params_)
        if (!p.used)
            pbrtWarn(warnings, p.where,
                     directive_ + ": parameter " + p.declaration() + " is not used (pbrt-v3 ignores it too)");
}

}  // namespace tetglow
