// Typed reads from a parsed JSON document. Every value carries its file and JSON pointer, so each
// error is one line naming both and what was expected:
//   scene.json: /media/0/g: expected a number in (-1, 1), got 1
#pragma once
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace tetglow {

inline constexpr size_t kMaxJsonDepth = 64;  // arrays and objects inside each other; a scene needs 4

// Parses JSON text. A syntax error, a number too large for a double, a duplicate key or nesting
// deeper than kMaxJsonDepth throws InputError naming `file`, the line and column (where known)
// and the JSON pointer being read.
nlohmann::json parseJson(const std::string& text, const std::string& file);

// The numbers a field allows; the default allows every finite number.
struct Range {
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    bool loOpen = false, hiOpen = false;

    bool contains(double x) const;
    // "finite non-negative number", "number in (-1, 1)"; plural: "... numbers".
    std::string describe(bool plural = false) const;
};
inline constexpr Range kNonNegative{.lo = 0}, kPositive{.lo = 0, .loOpen = true};
// Every coordinate and vector component in a scene: well inside what Embree accepts in a ray
// (its floats stop at 1.8e19), and any product of two is still finite.
inline constexpr double kMaxCoordinate = 1e12;
inline constexpr Range kCoordinate{.lo = -kMaxCoordinate, .hi = kMaxCoordinate};
// Colours (radiance, intensity, coefficients) end in the image's 32-bit floats.
inline constexpr Range kColour{.lo = 0, .hi = std::numeric_limits<float>::max()};

class JsonObject;

// A value in the document, or an absent optional key: false in a condition, and "missing" in
// the error of any typed read.
class JsonValue {
public:
    JsonValue(const nlohmann::json* json, nlohmann::json::json_pointer pointer, std::string file);

    explicit operator bool() const { return json_ != nullptr; }
    std::string path() const { return pointer_.to_string(); }
    std::string where() const;  // "scene.json: /camera/fov"

    // "<where>: <message>"
    [[noreturn]] void error(const std::string& message) const;
    // "<where>: expected <expected>, got <value>", or "<where>: missing; expected <expected>" (and
    // the key of the object that may be it misspelt).
    [[noreturn]] void fail(const std::string& expected) const;

    double number(const Range& range = {}) const;
    int64_t integer(int64_t lo, int64_t hi = std::numeric_limits<int64_t>::max()) const;
    bool boolean() const;
    std::string string() const;  // non-empty
    std::vector<double> numbers(size_t count, const Range& range = {}) const;
    glm::dvec3 vec3(const Range& range = kCoordinate) const;
    glm::dvec3 vec3OrScalar(const Range& range = kCoordinate) const;  // one number x stands for (x, x, x)
    std::vector<JsonValue> array() const;

    // The value for the string this value names, e.g. choice<LightType>({{"point", LightType::Point}, ...}),
    // or from a table of such pairs.
    template <class T, class Options = std::initializer_list<std::pair<std::string_view, T>>>
    T choice(const Options& options) const;

    // Reads this object with `read(JsonObject&)`, then rejects every key `read` did not ask for,
    // so that a typo is an error and not a silently ignored setting.
    template <class F>
    auto readObject(F&& read) const;

private:
    friend class JsonObject;
    size_t choiceIndex(const std::vector<std::string_view>& names) const;
    JsonValue child(const nlohmann::json* json, const nlohmann::json::json_pointer& pointer) const;

    const nlohmann::json* json_;
    nlohmann::json::json_pointer pointer_;
    std::string file_;
    std::string misspelling_;  // an absent key's: the key of its object nearest its name, if near
};

// A JSON object that remembers which keys were asked for.
class JsonObject {
public:
    explicit JsonObject(const JsonValue& value);  // fails unless the value is an object

    JsonValue operator[](const std::string& key);  // absent keys give a false JsonValue
    const JsonValue& self() const { return value_; }
    // Throws for the first key that was never asked for, listing the ones that were (and the
    // nearest of them).
    void rejectUnknownKeys() const;

private:
    JsonValue value_;
    std::vector<std::string> asked_;
};

template <class T, class Options>
T JsonValue::choice(const Options& options) const {
    std::vector<std::string_view> names;
    for (const auto& option : options) names.push_back(option.first);
    return std::begin(options)[choiceIndex(names)].second;
}

template <class F>
auto JsonValue::readObject(F&& read) const {
    JsonObject object(*this);
    auto result = read(object);
    object.rejectUnknownKeys();
    return result;
}

}  // namespace tetglow
