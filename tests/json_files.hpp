#pragma once
// A JSON file read and written whole, keys in file order: for tests that
// change one field of a generated table and hand it back to a tool.
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

inline nlohmann::ordered_json read_json_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::ordered_json::parse(in);
}

inline void write_json_file(const std::filesystem::path& p, const nlohmann::ordered_json& j) { std::ofstream(p) << j.dump(); }
