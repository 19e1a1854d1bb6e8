// Scene files the tests read back as JSON.
#pragma once
#include <fstream>
#include <string>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace tetglow::test {

inline nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

inline glm::dvec3 vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

}  // namespace tetglow::test
