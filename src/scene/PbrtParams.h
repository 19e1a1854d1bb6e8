// The parameter lists of pbrt-v3 directives ("rgb Kd" [0.5 0.5 0.5] ...) and pbrt-v3's typed
// lookups: a parameter is found by its name and its type's storage class ("point" and "point3"
// are one class; "rgb", "color", "xyz", "blackbody" and "spectrum" another), the last of two
// with the same name winning. A parameter that no lookup asked for is reported as unused.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/PbrtTokenizer.h"

namespace tetglow {

enum class PbrtParamClass { Integer, Float, Bool, Point2, Vector2, Point3, Vector3, Normal, String, Texture, Spectrum };

struct PbrtParam {
    std::string type, name;  // as written: "color", "Kd"
    PbrtParamClass cls = PbrtParamClass::Float;
    std::vector<double> numbers;
    std::vector<std::string> strings;  // string, texture, bool, and spectrum file names
    PbrtLocation where;
    bool used = false;
    std::string declaration() const { return "\"" + type + " " + name + "\""; }
};

class PbrtParams {
public:
    PbrtParams() = default;
    // Reads "type name" value pairs up to the next token that is not a quoted string.
    // `directive` names the owner in messages: Shape "trianglemesh".
    PbrtParams(PbrtTokenizer& tokens, std::string directive);

    const std::string& directive() const { return directive_; }
    // The parameter, marked used; null when absent.
    PbrtParam* find(const std::string& name, PbrtParamClass cls);

    // One value, or `fallback` when absent; the wrong number of values is an error.
    double getFloat(const std::string& name, double fallback);
    int getInt(const std::string& name, int fallback);
    bool getBool(const std::string& name, bool fallback);
    std::string getString(const std::string& name, const std::string& fallback);
    glm::dvec3 getPoint(const std::string& name, const glm::dvec3& fallback);
    // "rgb" / "color" only: xyz, blackbody and sampled spectra are errors.
    glm::dvec3 getSpectrum(const std::string& name, const glm::dvec3& fallback);
    // All values (empty when absent): numbers grouped in threes for points and normals.
    std::vector<double> getFloats(const std::string& name);
    std::vector<int> getInts(const std::string& name);
    std::vector<glm::dvec3> getTriples(const std::string& name, PbrtParamClass cls);

    // "<file>:<line>: <directive>: parameter "<type> <name>": <message>"
    [[noreturn]] void fail(const PbrtParam& p, const std::string& message) const;
    // One warning line for each parameter nothing asked for (pbrt-v3 ignores those too).
    void reportUnused(std::vector<std::string>& warnings) const;

private:
    // find(), and an error unless it holds `count` values (strings or numbers, as its type takes).
    PbrtParam* findOne(const std::string& name, PbrtParamClass cls, size_t count);

    std::string directive_;
    std::vector<PbrtParam> params_;
};

}  // namespace tetglow
