#pragma once
// All-or-nothing output: files are collected in memory, written to a staging
// directory beside the target, and moved into place only when every write has
// succeeded. On failure the staging directory is removed and the target is
// untouched.
#include <filesystem>
#include <map>
#include <string>

namespace sg {

class OutputTransaction {
 public:
  explicit OutputTransaction(std::filesystem::path target_dir) : target_(std::move(target_dir)) {}
  // `relative_name` may contain subdirectories ("v5/n24.json").
  void add(const std::string& relative_name, std::string bytes) { files_[relative_name] = std::move(bytes); }
  std::size_t size() const { return files_.size(); }
  // Throws sg::Error (naming the path) on any failure, leaving nothing behind.
  void commit();

 private:
  std::filesystem::path target_;
  std::map<std::string, std::string> files_;
};

}  // namespace sg
