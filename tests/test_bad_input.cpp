// Every bad input gets a clear error, a nonzero exit code, and leaves no file.
#include <catch2/catch.hpp>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.hpp"
#include "common/scheme_registry.hpp"

namespace fs = std::filesystem;

namespace {
fs::path write_scheme(const fs::path& dir, const std::string& name, const std::string& body) {
  const fs::path p = dir / (name + ".json");
  std::ofstream(p) << body;
  return p;
}
std::string uniform(const std::string& first, const std::string& coeffs, int arity = 2) {
  return R"({"format": "stencilgen-scheme", "version": 1, "name": "bad", "type": "curve-uniform", "arity": )" +
         std::to_string(arity) + R"(, "mask": {"first": )" + first + R"(, "coefficients": [)" + coeffs + "]}}";
}
// Runs a generation that must fail, with `expected` in its message and nothing under `out`.
void expect_failure(const std::string& args, const std::string& expected, const fs::path& out) {
  const CliResult r = run_stencilgen(args + " --out " + out.string());
  INFO(args << "\n" << r.output);
  CHECK(r.status != 0);
  CHECK(r.output.find(expected) != std::string::npos);
  CHECK(r.output.find("error") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // No staging directory left beside it either.
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    CHECK(e.path().filename().string().find("staging") == std::string::npos);
}
}  // namespace

TEST_CASE("malformed scheme files are rejected with the file and field named") {
  const fs::path dir = scratch_dir("malformed");
  const fs::path out = dir / "out";
  expect_failure("--scheme " + write_scheme(dir, "json", "{ not json").string() + " --n 3", "not valid JSON", out);
  expect_failure("--scheme loop --valence 3 --n 2 --binary-layout stored", "--binary-layout applies to quad schemes", out);
  expect_failure("--scheme fourpoint --n 2 --binary-layout stored", "--binary-layout applies to quad schemes", out);
  expect_failure("--scheme " + write_scheme(dir, "float", uniform("-1", "0.5, 1, 0.5")).string() + " --n 3",
                 "mask.coefficients[0]", out);
  expect_failure("--scheme " + write_scheme(dir, "nofirst", R"({"format": "stencilgen-scheme", "version": 1, "name": "x", "type": "curve-uniform", "arity": 2, "mask": {"coefficients": ["1"]}})").string() + " --n 3",
                 "missing required field 'first'", out);
  expect_failure("--scheme " + write_scheme(dir, "arity", uniform("-1", "\"1/2\", \"1\", \"1/2\"", 4)).string() + " --n 3",
                 "arity: 4 is outside the range 2..3", out);
  expect_failure("--scheme " + write_scheme(dir, "type", R"({"format": "stencilgen-scheme", "version": 1, "name": "x", "type": "surface"})").string() + " --n 3",
                 "unknown type 'surface'", out);
  expect_failure("--scheme " + write_scheme(dir, "expr", uniform("-1", "\"1/2 + q\", \"1\", \"1/2\"")).string() + " --n 3",
                 "unknown name 'q'", out);
  // A misspelt optional field would give another scheme without a word: refused, named.
  std::string quad;
  {
    std::ifstream in(sg::default_schemes_dir() / "nonpoly.json");
    quad.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = quad.find("\"polygon_rules\"");
  REQUIRE(at != std::string::npos);
  quad.replace(at, 15, "\"polygon_rule\"");
  expect_failure("--scheme " + write_scheme(dir, "typo", quad).string() + " --n 2 --valence 3",
                 "polygon_rule: is not a field of a quad scheme", out);
  // A parameter named like something the formulas already mean (the valence v, the function cos2pi).
  expect_failure("--scheme " + write_scheme(dir, "cos", R"({"format": "stencilgen-scheme", "version": 1, "name": "x", "type": "curve-uniform", "arity": 2, "parameters": {"cos2pi": "1"}, "mask": {"first": -1, "coefficients": ["1/2", "1", "1/2"]}})").string() + " --n 2",
                 "'cos2pi' is a name of the formulas", out);
  fs::remove_all(dir);
}

TEST_CASE("masks without a unique solution are refused with the reason") {
  const fs::path dir = scratch_dir("singular");
  const fs::path out = dir / "out";
  // Sub-masks 1/2 + 1/2 and 1: partition of unity is impossible.
  expect_failure("--scheme " + write_scheme(dir, "nopou", uniform("-1", "\"1/2\", \"1\", \"1/2\", \"1/2\"")).string() + " --n 2",
                 "no solution", out);
  // phi = box on [0, 3] / 3 (mask 1 + z^3): at n = 5 the residue cycle {1/5, 2/5, 4/5, 3/5}
  // leaves a free solution space, reported with its dimension.
  expect_failure("--scheme " + write_scheme(dir, "free", uniform("-1", "\"1\", \"0\", \"0\", \"1\"")).string() + " --n 5",
                 "solution space of dimension", out);
  // The box mask 1 + z: phi is discontinuous, the grid values cannot sum to 1.
  expect_failure("--scheme " + write_scheme(dir, "box", uniform("0", "\"1\", \"1\"")).string() + " --n 3",
                 "no solution", out);
  fs::remove_all(dir);
}

TEST_CASE("unknown schemes, bad rates and bad parameters are refused") {
  const fs::path dir = scratch_dir("args");
  const fs::path out = dir / "out";
  expect_failure("--scheme no-such-scheme --n 3", "unknown scheme 'no-such-scheme'", out);
  expect_failure("--scheme ./missing.json --n 3", "no such scheme file", out);
  expect_failure("--scheme fourpoint --n 0", "less than 1", out);
  expect_failure("--scheme fourpoint --n=-2", "not a positive integer", out);
  expect_failure("--scheme fourpoint --n 3 --param q=1/2", "has no parameter 'q'", out);
  expect_failure("--scheme fourpoint --n 3 --param w=1/0", "division by zero", out);
  // A parameter given twice is a mistake, not "the last one wins".
  expect_failure("--scheme fourpoint --n 3 --param w=1/32 --param w=1/16", "parameter 'w' is overridden twice", out);
  // An empty value names no file: refused, not taken as "none" or as ".".
  for (const std::string& args : {std::string("--scheme fourpoint --n 3 --out ''"), "--scheme '' --n 3 --out " + out.string(),
                                 std::string("plot --scheme fourpoint --n 3 --out ''")}) {
    const CliResult r = run_stencilgen(args);
    INFO(args << "\n" << r.output);
    CHECK(r.status == 1);
    CHECK_THAT(r.output, Catch::Contains(": an empty value"));
  }
  // Options that would change nothing for the scheme's kind are refused, not ignored.
  expect_failure("--scheme fourpoint --n 3 --binary-precision single", "--binary-precision applies to surface schemes", out);
  expect_failure("--scheme loop --n 2 --route eigen", "--route applies to curve schemes", out);
  // An output folder that cannot be made is refused before the work, not after it.
  std::ofstream(dir / "a-file") << "x";
  for (const fs::path& bad : {dir / "a-file", dir / "a-file" / "sub"}) {
    const CliResult r = run_stencilgen("--scheme fourpoint --n 1-3 --out " + bad.string());
    INFO(r.output);
    CHECK(r.status == 1);
    CHECK(r.output.find("cannot create output folder " + bad.string() + ": " + (dir / "a-file").string() + " is not a directory") !=
          std::string::npos);
    CHECK(r.output.find("solved") == std::string::npos);
  }
  const CliResult analyze = run_stencilgen("analyze --scheme fourpoint");
  CHECK(analyze.status == 1);
  CHECK(analyze.output.find("analyze: 'fourpoint' is a curve scheme (type curve-uniform); analyze studies") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the schemes directory: names agree with files, list and lookups agree, a missing directory is an error") {
  const fs::path dir = scratch_dir("registry");
  const fs::path schemes = dir / "schemes", out = dir / "out";
  fs::create_directories(schemes);
  fs::copy_file(sg::default_schemes_dir() / "fourpoint.json", schemes / "fourpoint.json");
  // A copy saved under another name but still named "fourpoint" inside would write fourpoint's tables.
  fs::copy_file(sg::default_schemes_dir() / "fourpoint.json", schemes / "mine.json");
  std::ofstream(schemes / "broken.json") << "{";
  const std::string env = "STENCILGEN_SCHEMES_DIR=" + schemes.string() + " ";
  CliResult r = run_command(env + stencilgen_exe(), "--scheme mine --n 2 --out " + out.string());
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find("mine.json: name: 'fourpoint' differs from the file's name 'mine'") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  // By path the file's name does not matter: the tables are named by the field.
  r = run_stencilgen("--scheme " + (schemes / "mine.json").string() + " --n 2 -q --out " + out.string());
  CHECK(r.status == 0);
  CHECK(fs::exists(out / "fourpoint"));
  fs::remove_all(out);
  // The listing and the "available" list of an unknown name agree: only loadable schemes, the others with the reason.
  r = run_command(env + stencilgen_exe(), "list");
  CHECK(r.status == 0);
  CHECK(r.output.find("  fourpoint (curve)") != std::string::npos);
  CHECK(r.output.find("  mine (curve)") == std::string::npos);
  CHECK(r.output.find("mine.json: ") != std::string::npos);
  CHECK(r.output.find("broken.json: ") != std::string::npos);
  r = run_command(env + stencilgen_exe(), "--scheme nope --n 2 --out " + out.string());
  CHECK(r.status == 1);
  CHECK(r.output.find("available: fourpoint\n") != std::string::npos);
  // A directory that is not there is an error, for list and for a lookup.
  const std::string gone = "STENCILGEN_SCHEMES_DIR=" + (dir / "gone").string() + " ";
  r = run_command(gone + stencilgen_exe(), "list");
  CHECK(r.status == 1);
  CHECK(r.output.find("schemes directory " + (dir / "gone").string() + ": No such file or directory") != std::string::npos);
  r = run_command(gone + stencilgen_exe(), "--scheme fourpoint --n 2 --out " + out.string());
  CHECK(r.status == 1);
  CHECK(r.output.find("No such file or directory") != std::string::npos);
  // Something that is not a regular file is named as such, not as missing.
  r = run_stencilgen("--scheme /dev/null --n 2 --out " + out.string());
  CHECK(r.status == 1);
  CHECK(r.output.find("/dev/null: not a regular file") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("surface runs report the patch subdivision and every tenth of the boundary sectors as they go") {
  const fs::path dir = scratch_dir("progress");
  for (const char* scheme : {"catmull-clark", "loop"}) {
    const CliResult r = run_stencilgen(std::string("--scheme ") + scheme + " --valence 5 --n 1 --out " + (dir / "out").string());
    INFO(r.output);
    REQUIRE(r.status == 0);
    std::size_t lines = 0, at = 0;
    while ((at = r.output.find("cone sectors: ", at)) != std::string::npos) ++lines, ++at;
    CHECK(lines >= 5);
    CHECK(lines <= 10);
    CHECK(r.output.find(" solved\n") != std::string::npos);
    if (std::string(scheme) == "catmull-clark")
      CHECK(r.output.find("catmull-clark: valence 5 patch subdivision and tangent plane solved (1/1)") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("a control character in a quoted value is shown escaped, not ending the message") {
  const fs::path dir = scratch_dir("control-chars");
  std::string body = uniform("-1", R"("1/2", "1", "1/2")");
  body.replace(body.find("\"bad\""), 5, std::string("\"ab\\u0000cd\\u001b[31m\""));
  const fs::path file = write_scheme(dir, "nul", body);
  const CliResult r = run_stencilgen("--scheme " + file.string() + " --n 2 --out " + (dir / "out").string());
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find("'ab\\x00cd\\x1b[31m' is not a scheme name") != std::string::npos);
  CHECK(r.output.find('\0') == std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("a scheme not shown to converge gets a warning even with -q and shipped ones do not") {
  const fs::path dir = scratch_dir("divergent");
  // The four-point scheme with w = 1: its difference scheme is not contractive.
  const fs::path divergent = write_scheme(dir, "wide", uniform("-3", R"("-1", "0", "3/2", "1", "3/2", "0", "-1")"));
  CliResult r = run_stencilgen("-q --scheme " + divergent.string() + " --n 2 --out " + (dir / "out").string());
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK(r.output.find("warning: scheme 'bad' is not shown to converge") != std::string::npos);
  for (const char* shipped : {"fourpoint", "dd6", "bspline3", "chaikin", "ternary-dd4"}) {
    r = run_stencilgen(std::string("-q --scheme ") + shipped + " --n 2 --out " + (dir / "out").string());
    INFO(shipped << ": " << r.output);
    CHECK(r.status == 0);
    CHECK(r.output.find("warning") == std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("a successful run writes JSON and binary tables for every rate, and verify accepts them") {
  const fs::path dir = scratch_dir("ok");
  const CliResult r = run_stencilgen("--scheme fourpoint --n 2-4 --out " + (dir / "t").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  for (int n = 2; n <= 4; ++n) {
    CHECK(fs::exists(dir / "t" / "fourpoint" / ("n" + std::to_string(n) + ".json")));
    CHECK(fs::exists(dir / "t" / "fourpoint" / ("n" + std::to_string(n) + ".sgc")));
  }
  CHECK_FALSE(fs::exists(dir / "t" / "fourpoint" / "n1.json"));
  const CliResult v = run_stencilgen("verify " + (dir / "t" / "fourpoint" / "n3.json").string());
  INFO(v.output);
  CHECK(v.status == 0);
  CHECK(v.output.find("OK") != std::string::npos);
  // The binary table beside it is named as such, not as broken JSON.
  const CliResult binary = run_stencilgen("verify " + (dir / "t" / "fourpoint" / "n3.sgc").string());
  CHECK(binary.status != 0);
  CHECK(binary.output.find("a binary file; verify checks exact JSON tables") != std::string::npos);

  // A tampered table fails verification with a nonzero exit code.
  const fs::path table = dir / "t" / "fourpoint" / "n3.json";
  std::string text;
  {
    std::ifstream in(table);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto at = text.find("\"4240/5589\"");
  REQUIRE(at != std::string::npos);
  text.replace(at, 11, "\"4241/5589\"");
  std::ofstream(table) << text;
  const CliResult bad = run_stencilgen("verify " + table.string());
  CHECK(bad.status != 0);
  CHECK(bad.output.find("FAIL") != std::string::npos);

  const CliResult plot = run_stencilgen("plot --scheme fourpoint --n 21 --out " + (dir / "p.svg").string());
  CHECK(plot.status == 0);
  CHECK(fs::file_size(dir / "p.svg") > 1000);
  const CliResult upper = run_stencilgen("plot --scheme fourpoint --n 21 --out " + (dir / "P.SVG").string());
  CHECK(upper.status == 0);  // the extension in either case
  CHECK(fs::exists(dir / "P.SVG"));
  // A link is written through (it used to be replaced by a plain file).
  fs::create_symlink("P.SVG", dir / "link.svg");
  fs::remove(dir / "P.SVG");
  CHECK(run_stencilgen("plot --scheme fourpoint --n 5 --out " + (dir / "link.svg").string()).status == 0);
  CHECK(fs::is_symlink(dir / "link.svg"));
  CHECK(fs::file_size(dir / "P.SVG") > 500);
  // A scheme file is never an output: plot writes .svg only (it used to
  // replace its own scheme with SVG), and a generation refuses a scheme file
  // inside the folder OUT/<scheme> it replaces (it used to delete it).
  const fs::path scheme = dir / "od" / "fourpoint" / "fourpoint.json";
  fs::create_directories(scheme.parent_path());
  fs::copy_file(sg::default_schemes_dir() / "fourpoint.json", scheme);
  const std::uintmax_t bytes = fs::file_size(scheme);
  const CliResult onto = run_stencilgen("plot --scheme " + scheme.string() + " --n 5 --out " + scheme.string());
  CHECK(onto.status == 1);
  CHECK_THAT(onto.output, Catch::Contains("plot --out must end in .svg"));
  const CliResult inside = run_stencilgen("--scheme " + scheme.string() + " --n 2 --out " + (dir / "od").string() + " -q");
  INFO(inside.output);
  CHECK(inside.status == 1);
  CHECK_THAT(inside.output, Catch::Contains("is inside") && Catch::Contains("which the run replaces whole"));
  CHECK(fs::file_size(scheme) == bytes);
  fs::remove_all(dir);
}
