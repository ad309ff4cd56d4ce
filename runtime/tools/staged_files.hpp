#pragma once
// Outputs of a run that writes several files (an animation's frames), all or
// nothing: each is written first to a staging name beside its target, and
// only when every one is written are they moved into place. A failure before
// that removes the staged files; a failure while moving puts back what the
// targets held before. Files that existed are never lost to a failed run.
#include <string>
#include <utility>
#include <vector>

namespace stencil_tools {

class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();  // removes what was staged and not committed

  // The name to write `target`'s content to now: beside it, same extension
  // (writers choose the format by it). A symbolic link is followed (the link
  // stays; what it names is replaced); throws if `target` is a directory or
  // another file that is not regular (stencil_runtime::output_file).
  std::string stage(const std::string& target);
  // Moves every staged file onto its target; throws, having restored the
  // targets' earlier content, if one cannot be moved.
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // (staging name, target)
  bool committed_ = false;
};

}  // namespace stencil_tools
