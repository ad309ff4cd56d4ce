// All-or-nothing output (issue 12): an output folder is replaced as a whole or
// not at all, whichever step fails, and nothing is left beside it.
#include <catch2/catch.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <map>

#include "base/error.hpp"
#include "cli.hpp"
#include "common/atomic_output.hpp"

namespace fs = std::filesystem;
using Step = sg::OutputTransaction::Step;

namespace {

// Every file below `dir` with its contents, keyed by relative path.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      std::ifstream in(e.path(), std::ios::binary);
      files[fs::relative(e.path(), dir).string()] = std::string(std::istreambuf_iterator<char>(in), {});
    }
  return files;
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The previous run's output: two files, one of which the new run does not write.
void write_previous(const fs::path& target) {
  fs::create_directories(target / "v5");
  std::ofstream(target / "v5" / "n1.json") << "old n1";
  std::ofstream(target / "old-only.json") << "old only";
}

sg::OutputTransaction new_run(const fs::path& target) {
  sg::OutputTransaction tx(target);
  tx.add("v5/n1.json", "new n1");
  tx.add("v5/n2.json", "new n2");
  tx.add("table.sgs", "new binary");
  return tx;
}

const std::map<std::string, std::string> kNew = {
    {"v5/n1.json", "new n1"}, {"v5/n2.json", "new n2"}, {"table.sgs", "new binary"}};
const std::map<std::string, std::string> kPrevious = {{"v5/n1.json", "old n1"}, {"old-only.json", "old only"}};

}  // namespace

TEST_CASE("an output folder is written whole, and replaces a previous one whole", "[output]") {
  const fs::path dir = scratch_dir("output-ok");
  new_run(dir / "fresh").commit();
  CHECK(snapshot(dir / "fresh") == kNew);
  write_previous(dir / "again");
  new_run(dir / "again/").commit();  // a trailing separator names the same folder
  CHECK(snapshot(dir / "again") == kNew);  // old-only.json does not survive
  CHECK(names_in(dir) == std::vector<std::string>{"again", "fresh"});  // no staging or old folder beside them
  fs::remove_all(dir);
}

TEST_CASE("an output folder that is a symbolic link is replaced through it: the link stays", "[output]") {
  const fs::path dir = scratch_dir("output-link");
  write_previous(dir / "real" / "tables");
  fs::create_symlink("real/tables", dir / "out");  // relative, as `ln -s` makes them
  fs::create_symlink("out", dir / "out2");         // and a chain of two
  new_run(dir / "out2").commit();
  CHECK(fs::is_symlink(dir / "out"));
  CHECK(fs::is_symlink(dir / "out2"));
  CHECK(snapshot(dir / "real" / "tables") == kNew);  // old-only.json does not survive there either
  CHECK(names_in(dir) == std::vector<std::string>{"out", "out2", "real"});
  CHECK(names_in(dir / "real") == std::vector<std::string>{"tables"});  // no staging or old folder beside it
  // A link to a folder that does not exist yet: the folder is made where the link points.
  fs::create_symlink("real/later", dir / "dangling");
  new_run(dir / "dangling").commit();
  CHECK(fs::is_symlink(dir / "dangling"));
  CHECK(snapshot(dir / "real" / "later") == kNew);
  // A loop of links is refused, and nothing is written.
  fs::create_symlink("loop-b", dir / "loop-a");
  fs::create_symlink("loop-a", dir / "loop-b");
  CHECK_THROWS_WITH(new_run(dir / "loop-a").commit(), Catch::Contains("loop of symbolic links"));
  CHECK(names_in(dir) == std::vector<std::string>{"dangling", "loop-a", "loop-b", "out", "out2", "real"});
  fs::remove_all(dir);
}

TEST_CASE("a failure at any step before the new folder is in place leaves the previous folder exactly as it was",
          "[output]") {
  const fs::path dir = scratch_dir("output-fail");
  for (Step step : {Step::CreateStaging, Step::WriteFile, Step::MoveOldAside, Step::MoveNewIn}) {
    INFO("failing step " << static_cast<int>(step));
    const fs::path target = dir / "out";
    write_previous(target);
    sg::OutputTransaction tx = new_run(target);
    tx.inject_failure(step);
    CHECK_THROWS_AS(tx.commit(), sg::Error);
    CHECK(snapshot(target) == kPrevious);
    CHECK(names_in(dir) == std::vector<std::string>{"out"});
    fs::remove_all(target);

    // Without a previous folder: nothing at all, not even the parent folders the commit created.
    sg::OutputTransaction first = new_run(dir / "new" / "parents" / "out");
    first.inject_failure(step);
    if (step != Step::MoveOldAside) CHECK_THROWS_AS(first.commit(), sg::Error);
    else first.commit();  // nothing to move aside: this step does not happen
    CHECK(names_in(dir) == (step == Step::MoveOldAside ? std::vector<std::string>{"new"} : std::vector<std::string>{}));
    fs::remove_all(dir / "new");
  }
  fs::remove_all(dir);
}

TEST_CASE("a file system that refuses a file part way through the writes leaves the previous folder intact", "[output]") {
  const fs::path dir = scratch_dir("output-real-failure");
  const fs::path target = dir / "out";
  write_previous(target);
  sg::OutputTransaction tx(target);
  tx.add("a.json", "written first");
  tx.add("b" + std::string(300, 'x') + ".json", "a name longer than any file system takes");
  CHECK_THROWS_WITH(tx.commit(), Catch::Contains("cannot write"));
  CHECK(snapshot(target) == kPrevious);
  CHECK(names_in(dir) == std::vector<std::string>{"out"});
  fs::remove_all(dir);
}

TEST_CASE("when only the removal of the previous folder fails, the new folder is complete and the message says so",
          "[output]") {
  const fs::path dir = scratch_dir("output-remove-old");
  const fs::path target = dir / "out";
  write_previous(target);
  sg::OutputTransaction tx = new_run(target);
  tx.inject_failure(Step::RemoveOld);
  CHECK_THROWS_WITH(tx.commit(), Catch::Contains("is complete") && Catch::Contains("could not be removed"));
  CHECK(snapshot(target) == kNew);
  fs::remove_all(dir);
}

TEST_CASE("a single file is written atomically, or not at all", "[output]") {
  const fs::path dir = scratch_dir("output-file");
  sg::write_file_atomically(dir / "plot.svg", "first");
  sg::write_file_atomically(dir / "plot.svg", "second");
  CHECK(snapshot(dir) == std::map<std::string, std::string>{{"plot.svg", "second"}});
  fs::create_directories(dir / "folder" / "inside");
  CHECK_THROWS_AS(sg::write_file_atomically(dir / "folder", "over a folder"), sg::Error);
  CHECK(fs::is_directory(dir / "folder" / "inside"));
  CHECK(names_in(dir) == std::vector<std::string>{"folder", "plot.svg"});
  fs::remove_all(dir);
}

TEST_CASE("stencilgen replaces OUT/<scheme> as a whole: tables of an earlier run do not mix with the new ones",
          "[output]") {
  const fs::path dir = scratch_dir("output-cli");
  REQUIRE(run_stencilgen("-q --scheme fourpoint --n 4-5 --out " + dir.string()).status == 0);
  REQUIRE(fs::exists(dir / "fourpoint" / "n5.json"));
  const CliResult r = run_stencilgen("-q --scheme fourpoint --n 2-3 --out " + dir.string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(names_in(dir / "fourpoint") == std::vector<std::string>{"n2.json", "n2.sgc", "n3.json", "n3.sgc"});
  CHECK(names_in(dir) == std::vector<std::string>{"fourpoint"});
  fs::remove_all(dir);
}

TEST_CASE("what a killed run left beside its output is cleared by the next run, and its previous output put back",
          "[output]") {
  // A process that has exited: its pid names no live process (until reused).
  const pid_t child = fork();
  if (child == 0) _exit(0);
  int status = 0;
  waitpid(child, &status, 0);
  const std::string dead = std::to_string(child);
  const fs::path dir = scratch_dir("output-interrupted");
  // Killed while writing: a staging folder; the output itself untouched.
  write_previous(dir / "a");
  fs::create_directories(dir / (".a.staging-" + dead) / "v5");
  std::ofstream(dir / (".a.staging-" + dead) / "v5" / "n1.json") << "half";
  // Killed between its two renames: the previous output aside, no output.
  write_previous(dir / (".b.old-" + dead));
  // Another live process's staging folder (ours, by pid): not touched by a sweep of another target.
  fs::create_directories(dir / (".c.staging-" + std::to_string(getpid())));
  // A file written atomically, killed before its rename.
  std::ofstream(dir / (".d.txt.staging-" + dead)) << "half";

  new_run(dir / "a").commit();
  CHECK(snapshot(dir / "a") == kNew);
  sg::OutputTransaction b(dir / "b");  // a run that fails: the previous output is back where it was
  b.add("x.json", "new");
  b.inject_failure(Step::MoveNewIn);
  CHECK_THROWS(b.commit());
  CHECK(snapshot(dir / "b") == kPrevious);
  sg::write_file_atomically(dir / "d.txt", "whole");
  CHECK(names_in(dir) == std::vector<std::string>{".c.staging-" + std::to_string(getpid()), "a", "b", "d.txt"});
  fs::remove_all(dir);
}
