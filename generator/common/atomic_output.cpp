#include "common/atomic_output.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "base/error.hpp"

namespace sg {
namespace fs = std::filesystem;

namespace {

// `path` without a trailing separator ("out/" -> "out"), so that it has a file name.
fs::path normalised(const fs::path& path) {
  fs::path p = path.lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p;
}

// What `path` names once a chain of symbolic links is followed (`path` itself
// when it is no link): the output replaces that and the links stay, as the
// runtime's output_file does (the layers share no code). Throws sg::Error for
// a loop of links or one that cannot be read.
fs::path followed_links(const fs::path& path) {
  fs::path target = normalised(path);
  std::error_code ec;
  for (int links = 0; fs::is_symlink(fs::symlink_status(target, ec)); ++links) {
    const fs::path to = fs::read_symlink(target, ec);
    if (links == 40 || ec) throw Error("cannot write " + path.string() + ": a loop of symbolic links or an unreadable one");
    target = normalised(to.is_absolute() ? to : target.parent_path() / to);
  }
  return target;
}

// A sibling of `path` that only this process uses: ".NAME.ROLE-PID".
fs::path sibling(const fs::path& parent, const fs::path& path, const std::string& role) {
  return parent / ("." + path.filename().string() + "." + role + "-" + std::to_string(::getpid()));
}

// Creates `dir` and its missing parents; returns the topmost folder it created
// (empty if none), which the caller removes again if it fails later.
fs::path create_folders(const fs::path& dir) {
  fs::path created;
  for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    if (fs::exists(p, ec) || ec) break;
    created = p;
    if (!p.has_parent_path() || p.parent_path() == p) break;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    // libstdc++ may report a refused folder with an error code of 0 ("Success").
    const std::string why = ec && ec.value() != 0 ? ec.message() : "not created (is its parent a folder you may write to?)";
    std::error_code ignored;
    if (!created.empty()) fs::remove_all(created, ignored);
    throw Error("cannot create output folder " + dir.string() + ": " + why);
  }
  return created;
}

void write_bytes(const fs::path& file, const std::string& bytes, const fs::path& named) {
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw Error("cannot write " + named.string());
}

std::error_code injected() { return std::make_error_code(std::errc::io_error); }

// What an earlier run for `target` left when it was killed (an interrupt
// cannot run the Undo): its staging folder or file is removed; its previous
// contents moved aside are moved back if the target is missing (the run died
// between the two renames), else removed. Only runs whose process is gone
// (kill(pid, 0) fails with ESRCH) are touched.
void sweep_interrupted(const fs::path& parent, const fs::path& target) {
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) return;
  std::string name(1, '.');  // ".NAME." (appended: GCC 12 warns falsely on "." + string)
  name += target.filename().string();
  name += '.';
  std::vector<std::pair<fs::path, bool>> left;  // (path, is the moved-aside previous contents)
  for (const fs::directory_entry& entry : fs::directory_iterator(parent, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.compare(0, name.size(), name) != 0) continue;
    const std::string rest = file.substr(name.size());
    const bool old = rest.compare(0, 4, "old-") == 0;
    if (!old && rest.compare(0, 8, "staging-") != 0) continue;
    const std::string digits = rest.substr(old ? 4 : 8);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    if (pid == ::getpid() || !(::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH)) continue;
    left.emplace_back(entry.path(), old);
  }
  for (const auto& [path, old] : left) {
    if (old && !fs::exists(target, ec)) fs::rename(path, target, ec);
    else fs::remove_all(path, ec);
  }
}

}  // namespace

void OutputTransaction::add(const std::string& relative_name, std::string bytes) {
  const fs::path name(relative_name);
  bool plain = !relative_name.empty() && !name.has_root_path();
  for (const auto& part : name) plain = plain && part != ".." && part != "." && !part.empty();
  if (!plain) throw Error("internal: output file name '" + relative_name + "' is not a plain relative path");
  files_[relative_name] = std::move(bytes);
}

// Until dismissed, undoes a failed commit whatever the failure (an sg::Error,
// bad_alloc, ...): moves the previous target back if it was moved aside, and
// removes the staging folder and the parent folders the commit created.
class Undo {
 public:
  Undo(fs::path staging, fs::path created) : staging_(std::move(staging)), created_(std::move(created)) {}
  ~Undo() {
    if (dismissed_) return;
    std::error_code ignore;
    if (!aside_.empty() && !fs::exists(target_, ignore)) fs::rename(aside_, target_, ignore);
    fs::remove_all(staging_, ignore);
    if (!created_.empty()) fs::remove_all(created_, ignore);
  }
  Undo(const Undo&) = delete;
  Undo& operator=(const Undo&) = delete;
  void moved_aside(fs::path target, fs::path aside) { target_ = std::move(target), aside_ = std::move(aside); }
  void dismiss() { dismissed_ = true; }

 private:
  fs::path staging_, created_, target_, aside_;
  bool dismissed_ = false;
};

void OutputTransaction::commit() {
  const fs::path target = followed_links(target_);  // a link to a folder stays; the folder is replaced
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (fs::exists(target, ec) && !fs::is_directory(target, ec))
    throw Error("output path " + target.string() + " exists and is not a folder");
  const fs::path staging = sibling(parent, target, "staging"), aside = sibling(parent, target, "old");
  Undo undo(staging, create_folders(parent));
  sweep_interrupted(parent, target);
  fs::remove_all(staging, ec);  // left by an earlier process with this pid
  fs::remove_all(aside, ec);
  ec = fault_ == Step::CreateStaging ? injected() : std::error_code();
  if (!ec) fs::create_directory(staging, ec);
  if (ec) throw Error("cannot create staging folder " + staging.string() + ": " + ec.message());
  std::size_t written = 0;
  for (const auto& [name, bytes] : files_) {
    const fs::path file = staging / name;
    fs::create_directories(file.parent_path(), ec);
    if (ec) throw Error("cannot create " + file.parent_path().string() + ": " + ec.message());
    if (fault_ == Step::WriteFile && written == 1)
      throw Error("cannot write " + (target / name).string() + ": " + injected().message());
    write_bytes(file, bytes, target / name);
    ++written;
  }
  const bool replacing = fs::exists(target, ec);
  if (replacing) {
    ec = fault_ == Step::MoveOldAside ? injected() : std::error_code();
    if (!ec) fs::rename(target, aside, ec);
    if (ec) throw Error("cannot move the previous " + target.string() + " aside to " + aside.string() + ": " + ec.message());
    undo.moved_aside(target, aside);
  }
  ec = fault_ == Step::MoveNewIn ? injected() : std::error_code();
  if (!ec) fs::rename(staging, target, ec);  // the commit point
  if (ec) {
    std::string why = "cannot move " + staging.string() + " to " + target.string() + ": " + ec.message();
    if (replacing) {
      std::error_code back;
      fs::rename(aside, target, back);
      if (back) why += "; the previous contents could not be moved back either and are in " + aside.string();
    }
    throw Error(why);  // (Undo tries the move back once more if it failed here)
  }
  undo.dismiss();
  if (replacing) {
    ec = fault_ == Step::RemoveOld ? injected() : std::error_code();
    if (!ec) fs::remove_all(aside, ec);
    if (ec)
      throw Error("the new output in " + target.string() + " is complete, but the previous contents, moved to " +
                  aside.string() + ", could not be removed: " + ec.message());
  }
}

void write_file_atomically(const fs::path& path, const std::string& bytes) {
  // A device or FIFO would be deleted by the rename: refused.
  const fs::path target = followed_links(path);
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(target, ec);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw Error("cannot write " + path.string() + ": not a regular file (a directory, device, FIFO or socket)");
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const fs::path temporary = sibling(parent, target, "staging");
  Undo undo(temporary, create_folders(parent));
  sweep_interrupted(parent, target);
  write_bytes(temporary, bytes, target);
  fs::rename(temporary, target, ec);
  if (ec) throw Error("cannot write " + target.string() + ": " + ec.message());
  undo.dismiss();
}

void check_output_parent(const fs::path& out_dir) {
  if (out_dir.empty()) throw Error("--out is empty: it names the folder that receives the tables");
  std::error_code ec;
  fs::path at = out_dir;
  // The nearest existing folder at or above out_dir: what the run creates its folders in.
  while (!fs::exists(fs::symlink_status(at, ec))) {
    if (!at.has_relative_path() || at.parent_path() == at) break;
    at = at.has_parent_path() ? at.parent_path() : fs::path(".");
  }
  if (!fs::exists(at, ec)) throw Error("cannot create output folder " + out_dir.string() + ": no folder above it exists");
  if (!fs::is_directory(at, ec))
    throw Error("cannot create output folder " + out_dir.string() + ": " + at.string() + " is not a directory");
  if (::access(at.c_str(), W_OK | X_OK) != 0)
    throw Error("cannot create output folder " + out_dir.string() + ": " + at.string() + ": " + std::strerror(errno));
}

}  // namespace sg
