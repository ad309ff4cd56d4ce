#pragma once
// All-or-nothing output. A transaction collects files in memory and replaces
// the target folder as a whole: the files are written to a staging folder
// beside the target, then the old folder (if any) is renamed aside, the new
// one renamed in, and the old one removed. Until the new folder is in place,
// any failure restores the old folder, removes the staging folder (and any
// parent folders the transaction created), and throws; the target then holds
// exactly what it held before. Files of an earlier run that this run does not
// write do not survive: the folder is the output of one run. A target that is
// a symbolic link (or a chain of them) stays one: the folder it names is
// replaced, as the runtime's outputs do with a link to a file.
#include <filesystem>
#include <map>
#include <string>

namespace sg {

class OutputTransaction {
 public:
  explicit OutputTransaction(std::filesystem::path target_dir) : target_(std::move(target_dir)) {}
  // `relative_name` may contain subdirectories ("v5/n24.json"), never ".." or a root.
  void add(const std::string& relative_name, std::string bytes);
  std::size_t size() const { return files_.size(); }
  // Throws sg::Error (naming the path and the reason) on any failure.
  void commit();

  // The steps of commit(), and a way for tests to make one of them fail as if
  // the file system had refused it (WriteFile fails after the first file).
  enum class Step { None, CreateStaging, WriteFile, MoveOldAside, MoveNewIn, RemoveOld };
  void inject_failure(Step step) { fault_ = step; }

 private:
  std::filesystem::path target_;
  std::map<std::string, std::string> files_;
  Step fault_ = Step::None;
};

// Whether `out_dir` can receive an output folder, checked before a long run
// rather than found at its end: it exists and is a directory, or the nearest
// folder above it that exists is, and that one can be written to. Throws
// sg::Error naming the path and the reason.
void check_output_parent(const std::filesystem::path& out_dir);

// One file, all or nothing: written beside `path` under a temporary name and
// renamed over it. Throws sg::Error on failure, leaving neither the temporary
// file nor any parent folder it created.
void write_file_atomically(const std::filesystem::path& path, const std::string& bytes);

}  // namespace sg
