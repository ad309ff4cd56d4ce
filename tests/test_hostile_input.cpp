// Hostile input through the command line (issue 12): every class of input that
// used to crash stencilgen, run away with time or memory, or report a library's
// internal text gets one line "stencilgen: error: ..." that names the file,
// field or value and the limit, exit code 1, and no output left behind.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli.hpp"
#include "common/scheme_registry.hpp"

namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}
void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
ordered_json read_json(const fs::path& p) { return ordered_json::parse(read_text(p)); }
void write_json(const fs::path& p, const ordered_json& j) { write_text(p, j.dump(1)); }

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// A refusal: exit code 1 (not an abort or a signal, not a timeout), exactly one
// line on stdout and stderr together, "stencilgen: error: ..." with every piece
// of `expected` in it, and no new entry in `dir` (no output, staging folder or
// parent folder). `args` run for at most 20 seconds.
void expect_refusal(const fs::path& dir, const std::string& args, const std::vector<std::string>& expected) {
  const auto before = entries(dir);
  const CliResult r = run_stencilgen_within(20, args);
  INFO("stencilgen " << args.substr(0, 300) << "\n" << r.output.substr(0, 2000));
  CHECK(r.status == 1);
  CHECK(r.output.rfind("stencilgen: error: ", 0) == 0);
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
  for (const std::string& piece : expected) CHECK(r.output.find(piece) != std::string::npos);
  CHECK(entries(dir) == before);
}

// Tables to tamper with: fourpoint n = 3, nonpoly valence 5 n = 2, loop valence 5 n = 2.
fs::path curve_table() { return generated_table("fourpoint", "--n 3", "sgc").parent_path() / "n3.json"; }
fs::path quad_table() { return generated_table("nonpoly", "--valence 5 --n 2", "sgs").parent_path() / "v5" / "n2.json"; }
fs::path triangle_table() { return generated_table("loop", "--valence 5 --n 2", "sgt").parent_path() / "v5" / "n2.json"; }

ordered_json fourpoint_scheme() {
  return ordered_json::parse(read_text(sg::default_schemes_dir() / "fourpoint.json"));
}

}  // namespace

TEST_CASE("verify accepts a valid quad table (it used to read freed memory) and names the file and field of every fault",
          "[hostile]") {
  const CliResult ok = run_stencilgen("verify " + quad_table().string());
  INFO(ok.output);
  CHECK(ok.status == 0);
  CHECK(ok.output.find(": OK") != std::string::npos);

  const fs::path dir = scratch_dir("hostile-tables");
  auto tampered = [&](const fs::path& from, const std::string& name, auto change) {
    ordered_json j = read_json(from);
    change(j);
    const fs::path p = dir / name;
    write_json(p, j);
    return p.string();
  };
  const std::string no_arity = tampered(curve_table(), "no-arity.json", [](ordered_json& j) { j.erase("arity"); });
  expect_refusal(dir, "verify " + no_arity, {no_arity + ": missing required field 'arity'"});
  const std::string bad_value = tampered(curve_table(), "bad-value.json", [](ordered_json& j) {
    j["functions"][0]["values"]["1/3"] = "x/y";
  });
  expect_refusal(dir, "verify " + bad_value, {bad_value + ": functions[0].values[\"1/3\"]: 'x/y' is not an exact rational"});
  const std::string bad_support = tampered(curve_table(), "bad-support.json", [](ordered_json& j) {
    j["functions"][0]["support"][1] = "1/0";
  });
  expect_refusal(dir, "verify " + bad_support, {bad_support + ": functions[0].support[1]: ", "zero denominator"});
  const std::string float_parameter = tampered(curve_table(), "float-parameter.json", [](ordered_json& j) {
    j["parameters"]["w"] = 0.0625;
  });
  expect_refusal(dir, "verify " + float_parameter, {float_parameter + ": parameters.w: expected a string, got 0.0625"});
  const std::string far_key = tampered(curve_table(), "far-key.json", [](ordered_json& j) {
    j["functions"][0]["values"]["99999999999999999999999"] = "1";
  });
  expect_refusal(dir, "verify " + far_key,
                 {far_key + ": functions[0].values[\"99999999999999999999999\"]: ", "outside every support"});
  const std::string no_parameters = tampered(quad_table(), "no-parameters.json", [](ordered_json& j) { j.erase("parameters"); });
  expect_refusal(dir, "verify " + no_parameters, {no_parameters + ": missing required field 'parameters'"});
  const std::string number_denominator = tampered(quad_table(), "number-denominator.json", [](ordered_json& j) {
    j["nodes"][1]["denominator"] = 5;
  });
  expect_refusal(dir, "verify " + number_denominator, {number_denominator + ": nodes[1].denominator: expected a string"});
  const std::string text_valence = tampered(triangle_table(), "text-valence.json", [](ordered_json& j) { j["valence"] = "5"; });
  expect_refusal(dir, "verify " + text_valence, {text_valence + ": valence: expected an integer, got \"5\""});
  const std::string path_scheme = tampered(curve_table(), "path-scheme.json", [](ordered_json& j) {
    j["scheme"] = "../schemes/fourpoint";
  });
  expect_refusal(dir, "verify " + path_scheme, {path_scheme + ": scheme: '../schemes/fourpoint' is not a scheme name"});
  const std::string unknown = tampered(curve_table(), "unknown-format.json", [](ordered_json& j) { j["format"] = "csv"; });
  expect_refusal(dir, "verify " + unknown, {unknown + ": format: unknown table format 'csv'"});
  write_text(dir / "array.json", "[1, 2]");
  expect_refusal(dir, "verify " + (dir / "array.json").string(), {"array.json: expected an object, got [1,2]"});
  fs::remove_all(dir);
}

TEST_CASE("library exceptions on scheme files become messages that name the file and the field", "[hostile]") {
  const fs::path dir = scratch_dir("hostile-schemes");
  const std::string out = " --n 3 --out " + (dir / "out").string();
  auto scheme_with = [&](const std::string& name, auto change) {
    ordered_json j = fourpoint_scheme();
    change(j);
    const fs::path p = dir / (name + ".json");
    write_json(p, j);
    return p.string();
  };
  std::string text = fourpoint_scheme().dump();
  text.replace(text.find("\"first\":-3"), 10, "\"first\":1e999");
  write_text(dir / "overflow.json", text);
  expect_refusal(dir, "--scheme " + (dir / "overflow.json").string() + out,
                 {"overflow.json: not valid JSON: number overflow parsing '1e999'"});
  expect_refusal(dir, "--scheme " + scheme_with("description", [](ordered_json& j) { j["description"] = 5; }) + out,
                 {"description.json: description: expected a string, got 5"});
  expect_refusal(dir, "--scheme " + scheme_with("long-name", [](ordered_json& j) { j["name"] = std::string(300, 'x'); }) + out,
                 {"long-name.json: name: 'xxxx", "is not a scheme name", "at most 64 characters"});
  expect_refusal(dir, "--scheme " + scheme_with("slash-name", [](ordered_json& j) { j["name"] = "a/b"; }) + out,
                 {"slash-name.json: name: 'a/b' is not a scheme name"});
  expect_refusal(dir, "--scheme " + scheme_with("huge-first", [](ordered_json& j) { j["mask"]["first"] = 18446744073709551615ull; }) + out,
                 {"huge-first.json: mask.first: 18446744073709551615 is outside the range -64..64"});
  // 2^32 + 2 used to become arity 2 by a cast to int.
  expect_refusal(dir, "--scheme " + scheme_with("wide-arity", [](ordered_json& j) { j["arity"] = 4294967298L; }) + out,
                 {"wide-arity.json: arity: 4294967298 is outside the range 2..3"});
  expect_refusal(dir, "--scheme " + scheme_with("long-mask", [](ordered_json& j) {
                   j["mask"]["coefficients"] = std::vector<std::string>(65, "1/65");
                 }) + out,
                 {"long-mask.json: mask.coefficients: 65 coefficients; the limit is 64"});
  expect_refusal(dir, "--scheme " + scheme_with("bad-parameter", [](ordered_json& j) { j["parameters"]["w x"] = "1"; }) + out,
                 {"bad-parameter.json: parameters[\"w x\"]: 'w x' is not a parameter name"});
  // The message names the path, shortened (its start: 40 characters are always shown, however deep the temp dir).
  const std::string too_long = (dir / std::string(5000, 'a')).string() + ".json";
  expect_refusal(dir, "--scheme " + too_long + out, {too_long.substr(0, 40), "File name too long"});
  expect_refusal(dir, "--scheme 'bad name!'" + out, {"'bad name!' is neither a scheme name", "nor a path"});
  ordered_json quad = ordered_json::parse(read_text(sg::default_schemes_dir() / "nonpoly.json"));
  quad["regular_curve"] = "../schemes/nonpoly-curve";
  write_json(dir / "quad.json", quad);
  expect_refusal(dir, "--scheme " + (dir / "quad.json").string() + " --valence 5" + out,
                 {"quad.json: regular_curve: '../schemes/nonpoly-curve' is not the name of a curve scheme"});
  fs::remove_all(dir);
}

TEST_CASE("deep nesting and repeated keys are refused while parsing, naming the limit or the key", "[hostile]") {
  const fs::path dir = scratch_dir("hostile-nesting");
  const std::string out = " --n 3 --out " + (dir / "out").string();
  // 60,000 parentheses used to overflow the stack: the length limit refuses them first.
  expect_refusal(dir, "--scheme fourpoint --param 'w=" + std::string(60000, '(') + "1" + std::string(60000, ')') + "'" + out,
                 {"parameter override w: ", "120001 characters long; the limit is 4096"});
  expect_refusal(dir, "--scheme fourpoint --param 'w=" + std::string(100, '(') + "1" + std::string(100, ')') + "'" + out,
                 {"nested more than 64 levels deep"});
  expect_refusal(dir, "--scheme fourpoint --param 'w=" + std::string(3000, '-') + "1'" + out, {"nested more than 64 levels deep"});
  // Inside a scheme file, the error names the field.
  ordered_json scheme = fourpoint_scheme();
  scheme["mask"]["coefficients"][0] = std::string(100, '(') + "w" + std::string(100, ')');
  write_json(dir / "formula.json", scheme);
  expect_refusal(dir, "--scheme " + (dir / "formula.json").string() + out,
                 {"formula.json: mask.coefficients[0]: ", "nested more than 64 levels deep"});
  // A field given twice in a scheme file, and in a table given to verify.
  std::string twice = fourpoint_scheme().dump();
  twice.insert(twice.size() - 1, ", \"mask\": {}");
  write_text(dir / "twice.json", twice);
  expect_refusal(dir, "--scheme " + (dir / "twice.json").string() + out, {"twice.json: mask: the key appears twice"});
  twice = read_text(curve_table());
  twice.insert(twice.rfind('}'), ", \"arity\": 2");
  write_text(dir / "twice-table.json", twice);
  expect_refusal(dir, "verify " + (dir / "twice-table.json").string(), {"twice-table.json: arity: the key appears twice"});
  // A deeply nested array in a scheme file, and in a table given to verify.
  std::string text = fourpoint_scheme().dump();
  text.insert(text.size() - 1, ", \"extra\": " + std::string(100000, '[') + std::string(100000, ']'));
  write_text(dir / "deep.json", text);
  expect_refusal(dir, "--scheme " + (dir / "deep.json").string() + out,
                 {"deep.json: arrays and objects nested deeper than 32 levels"});
  text = read_text(curve_table());
  text.insert(text.rfind('}'), ", \"extra\": " + std::string(100000, '[') + std::string(100000, ']'));
  write_text(dir / "deep-table.json", text);
  expect_refusal(dir, "verify " + (dir / "deep-table.json").string(),
                 {"deep-table.json: arrays and objects nested deeper than 32 levels"});
  fs::remove_all(dir);
}

TEST_CASE("small inputs that ask for unbounded work are refused before the work, naming the limit", "[hostile]") {
  const fs::path dir = scratch_dir("hostile-work");
  const std::string out = " --out " + (dir / "out").string();
  // A 500-byte curve table at n = 3,000,000 used to run for minutes and gigabytes.
  ordered_json table = read_json(curve_table());
  table["n"] = 3000000;
  for (auto& f : table["functions"]) f["values"] = ordered_json::object();
  write_json(dir / "big-n.json", table);
  expect_refusal(dir, "verify " + (dir / "big-n.json").string(), {"big-n.json: n: 3000000 is outside the range 1..4096"});
  ordered_json quad = read_json(quad_table());
  quad["n"] = 100000;
  write_json(dir / "big-quad.json", quad);
  expect_refusal(dir, "verify " + (dir / "big-quad.json").string(), {"big-quad.json: n: 100000 is outside the range 1..128"});
  quad = read_json(quad_table());
  quad["valence"] = 1000;
  write_json(dir / "valence-quad.json", quad);
  expect_refusal(dir, "verify " + (dir / "valence-quad.json").string(),
                 {"valence-quad.json: valence: 1000 is outside the range 3..64"});
  // Nested powers used to run forever.
  expect_refusal(dir, "--scheme fourpoint --n 3 --param 'w=((2^4096)^4096)^4096'" + out,
                 {"the power would have about 16785408 bits", "the limit is 65536"});
  expect_refusal(dir, "--scheme fourpoint --n 3 --param 'w=2^4097'" + out, {"above the limit 4096"});
  // Every valence is checked before the first is analysed (3-1000 used to analyse 62 valences first).
  expect_refusal(dir, "analyze --scheme nonpoly --valence 3-1000", {"--valence '3-1000': 1000 is above 64, the largest valence"});
  ordered_json narrow = ordered_json::parse(read_text(sg::default_schemes_dir() / "catmull-clark.json"));
  narrow["valences"]["max"] = 10;
  write_json(dir / "narrow.json", narrow);
  fs::copy_file(sg::default_schemes_dir() / narrow["regular_curve"].get<std::string>().append(".json"),
                dir / narrow["regular_curve"].get<std::string>().append(".json"));
  expect_refusal(dir, "analyze --scheme " + (dir / "narrow.json").string() + " --valence 3-12",
                 {"narrow.json: valence 11 is outside the range 3..10 the scheme covers"});
  expect_refusal(dir, "--scheme " + (dir / "narrow.json").string() + " --valence 9-12 --n 2" + out,
                 {"narrow.json: valence 11 is outside the range 3..10"});
  expect_refusal(dir, "--scheme nonpoly --valence 5 --n 129" + out, {"129 is above 128, the largest rate for surface schemes"});
  expect_refusal(dir, "--scheme loop --valence 5 --n 120-130" + out, {"130 is above 128, the largest rate for surface schemes"});
  expect_refusal(dir, "plot --scheme fourpoint --n 5000 --out " + (dir / "p.svg").string(), {"5000 is outside 1..4096"});
  expect_refusal(dir, "analyze --scheme nonpoly --valence 5 --samples 1000", {"--samples", "see --help"});
  // File sizes: a scheme file is read only up to its limit.
  write_text(dir / "padded.json", fourpoint_scheme().dump() + std::string(2 << 20, ' '));
  expect_refusal(dir, "--scheme " + (dir / "padded.json").string() + " --n 3" + out,
                 {"padded.json: larger than 1048576 bytes, the limit for scheme files"});
  fs::remove_all(dir);
}

TEST_CASE("integers in rate and valence specs are read without overflow", "[hostile]") {
  const fs::path dir = scratch_dir("hostile-integers");
  const std::string out = " --out " + (dir / "out").string();
  expect_refusal(dir, "--scheme fourpoint --n 1-9999999999999" + out,
                 {"--n '1-9999999999999': 9999999999999 is above 4096, the largest rate for curve schemes"});
  expect_refusal(dir, "--scheme fourpoint --n 99999999999999999999999999" + out, {"is above 4096"});
  expect_refusal(dir, "--scheme fourpoint --n 3-99999999999999999999,2" + out, {"99999999999999999999 is above 4096"});
  expect_refusal(dir, "--scheme nonpoly --n 2 --valence 3-99999999999999999999" + out, {"is above 64, the largest valence"});
  expect_refusal(dir, "--scheme fourpoint --n 5-" + out, {"'' is not a positive integer"});
  fs::remove_all(dir);
}

TEST_CASE("every failure is one line and exit code 1: command-line errors and an impossible allocation", "[hostile]") {
  const fs::path dir = scratch_dir("hostile-boundary");
  expect_refusal(dir, "--scheme fourpoint --n 3 --bogus", {"--bogus", "(see --help)"});
  expect_refusal(dir, "--scheme fourpoint --n 3", {"generation needs --scheme, --n and --out"});
  const CliResult help = run_stencilgen("--help");
  CHECK(help.status == 0);
  CHECK(help.output.find("stencilgen") != std::string::npos);
#if !defined(__SANITIZE_ADDRESS__)  // ASan reserves more address space than any such limit
  // 150 MB of address space: GMP's allocations fail inside the solver (GMP used
  // to abort the process; now they throw std::bad_alloc like any other).
  const CliResult oom = run_command("ulimit -v 150000; " + stencilgen_exe(),
                                    "-q --scheme nonpoly --valence 8 --n 128,128 --out " + (dir / "out").string());
  INFO(oom.output);
  CHECK(oom.status == 1);
  CHECK(oom.output == "stencilgen: error: out of memory\n");
  CHECK(entries(dir).empty());
#endif
  fs::remove_all(dir);
}
