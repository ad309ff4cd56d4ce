// The runtime and its tools against hostile input (issue: robustness): every
// table reader checks every count, index, rate and key before use; meshes,
// parameters and options outside their limits get one clear line and exit
// code 1, and nothing is written. One regression test per class found.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_runtime/binary_format.hpp"
#include "mesh/file_output.hpp"
#include "tables/triangle_tables.hpp"

using namespace stencil_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

std::string nonpoly_dir() { return generated_table("nonpoly", "--valence 3-8 --n 24", "sgs").parent_path().string(); }

void expect_error(const CliResult& r, const std::string& text) {
  INFO(r.output);
  CHECK(r.status == 1);
  CHECK(r.output.find(text) != std::string::npos);
  CHECK(r.output.find("terminate") == std::string::npos);
  // One line: the error boundary prints nothing else.
  CHECK(std::count(r.output.begin(), r.output.end(), '\n') <= 1);
}

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Appends the FNV-1a checksum the binary formats end with.
std::string with_checksum(std::string bytes) {
  const std::uint64_t h = format::fnv1a64(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  for (int k = 0; k < 8; ++k) bytes.push_back(static_cast<char>((h >> (8 * k)) & 0xff));
  return bytes;
}

template <class T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

}  // namespace

TEST_CASE("binary tables with zero rates, or rates, valences and indices out of range, are refused", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-binary");
  // A complete, checksummed .sgs with no rates: refused at load, not at use.
  std::string sgs(format::kSurfaceMagic, 8);
  put<std::uint32_t>(sgs, format::kSurfaceVersion);
  put<std::uint32_t>(sgs, 8);
  put<std::uint8_t>(sgs, 0);  // stored stencils
  put<std::uint64_t>(sgs, 0x1234);
  put<std::uint32_t>(sgs, 4);
  sgs += "test";
  for (double w : {0.25, 0.375, 0.0625}) put(sgs, w);
  put<std::uint32_t>(sgs, 1);  // one vertex rule, valence 4
  put<std::uint32_t>(sgs, 4);
  for (double w : {0.5625, 0.09375, 0.015625}) put(sgs, w);
  put<std::uint8_t>(sgs, 0);   // no polygon rules
  put<std::int32_t>(sgs, -2);  // the cubic B-spline's mask, non-negative, no polynomial pieces
  put<std::uint32_t>(sgs, 5);
  for (double a : {0.125, 0.5, 0.75, 0.5, 0.125}) put(sgs, a);
  put<std::uint8_t>(sgs, 3);
  put<std::uint32_t>(sgs, 0);
  put<std::uint32_t>(sgs, 0);  // no rates
  put<std::uint32_t>(sgs, 0);  // no valences
  put<std::uint32_t>(sgs, 0);  // no boundary sectors
  write_file(dir / "zero.sgs", with_checksum(sgs));
  CHECK_THROWS_WITH(Tables::load((dir / "zero.sgs").string()), Catch::Contains("zero.sgs: holds no rates"));
  const CliResult r = run_stenciltess("--tables " + (dir / "zero.sgs").string() + " --mesh " + (kMeshes / "cube.obj").string() +
                                      " --rate 4 --out " + (dir / "out.ply").string());
  expect_error(r, "holds no rates");
  CHECK_FALSE(fs::exists(dir / "out.ply"));
  fs::remove_all(dir);
}

namespace {

// A checksum-less .sgs of the given layout up to its valence count: the cubic
// B-spline's rules and mask, the rates, and no regular values or derivatives.
std::string sgs_prefix(format::SurfaceLayout layout, const std::vector<std::uint32_t>& rates) {
  std::string sgs(format::kSurfaceMagic, 8);
  put<std::uint32_t>(sgs, format::kSurfaceVersion);
  put<std::uint32_t>(sgs, 8);
  put<std::uint8_t>(sgs, static_cast<std::uint8_t>(layout));
  put<std::uint64_t>(sgs, 0x1234);
  put<std::uint32_t>(sgs, 4);
  sgs += "test";
  for (double w : {0.25, 0.375, 0.0625}) put(sgs, w);
  put<std::uint32_t>(sgs, 1);
  put<std::uint32_t>(sgs, 4);
  for (double w : {0.5625, 0.09375, 0.015625}) put(sgs, w);
  put<std::uint8_t>(sgs, 0);
  put<std::int32_t>(sgs, -2);
  put<std::uint32_t>(sgs, 5);
  for (double a : {0.125, 0.5, 0.75, 0.5, 0.125}) put(sgs, a);
  put<std::uint8_t>(sgs, 3);
  put<std::uint32_t>(sgs, 0);
  put<std::uint32_t>(sgs, static_cast<std::uint32_t>(rates.size()));
  for (std::uint32_t n : rates) put<std::uint32_t>(sgs, n);
  for (int block = 0; block < 2; ++block)  // no regular values, no derivatives
    for (std::size_t k = 0; k < rates.size(); ++k) {
      put<std::int32_t>(sgs, 0);
      put<std::uint32_t>(sgs, 0);
    }
  return sgs;
}

// One valence of `points` points: identity reflection, a limit stencil, then
// A0 and the three regular children with every row dense (all columns), no tangents.
void put_generated_valence(std::string& sgs, std::uint32_t valence, bool rows) {
  const std::uint32_t points = 2 * valence + 8;
  put<std::uint32_t>(sgs, valence);
  put<std::uint32_t>(sgs, points);
  for (std::uint32_t h = 0; h < points; ++h) put<std::uint32_t>(sgs, h);
  for (std::uint32_t h = 0; h < points; ++h) put<double>(sgs, h == 0 ? 1.0 : 0.0);
  if (!rows) return;
  put<std::uint8_t>(sgs, 1);
  for (std::uint32_t row = 0; row < points + 3 * 16; ++row) {
    put<std::uint32_t>(sgs, points);
    for (std::uint32_t c = 0; c < points; ++c) {
      put<std::uint32_t>(sgs, c);
      put<double>(sgs, 1.0 / points);
    }
  }
  put<std::uint8_t>(sgs, 0);
}

}  // namespace

TEST_CASE("a small .sgs of generated layout may not ask for an expansion beyond the stated limits", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-expansion");
  // One grid too large: valence 3 at rate 4096 would expand into (8193^2) * 14 long doubles.
  std::string one = sgs_prefix(format::SurfaceLayout::Generated, {4096});
  put<std::uint32_t>(one, 1);
  put_generated_valence(one, 3, false);
  write_file(dir / "bomb.sgs", with_checksum(one));
  CHECK_THROWS_WITH(Tables::load((dir / "bomb.sgs").string()),
                    Catch::Contains("bomb.sgs") && Catch::Contains("valence 3, rate 4096: too large to expand at load time") &&
                        Catch::Contains("--binary-layout stored"));
  // Every grid within its limit, but 200 rates together beyond the file's.
  std::vector<std::uint32_t> rates;
  for (std::uint32_t n = 1; n <= 200; ++n) rates.push_back(n);
  std::string many = sgs_prefix(format::SurfaceLayout::Generated, rates);
  put<std::uint32_t>(many, 1);
  put_generated_valence(many, 3, false);
  write_file(dir / "many.sgs", with_checksum(many));
  CHECK_THROWS_WITH(Tables::load((dir / "many.sgs").string()), Catch::Contains("too large to expand at load time"));
  // Few entries, but dense rows at valence 64: the multiply-adds exceed their limit.
  rates.resize(40);
  std::string dense = sgs_prefix(format::SurfaceLayout::Generated, rates);
  put<std::uint32_t>(dense, 1);
  put_generated_valence(dense, 64, true);
  put<std::uint32_t>(dense, 0);  // no boundary sectors
  write_file(dir / "dense.sgs", with_checksum(dense));
  CHECK_THROWS_WITH(Tables::load((dir / "dense.sgs").string()),
                    Catch::Contains("valence 64: too much work to expand at load time"));
  // A boundary sector (expanded on first use) is refused at load when one rate's grid would exceed the limit.
  std::string sector = sgs_prefix(format::SurfaceLayout::Generated, {4096});
  put<std::uint32_t>(sector, 0);  // no valences
  put<std::uint32_t>(sector, 1);
  put<std::uint8_t>(sector, 0);
  for (std::uint32_t x : {3u, 1u, 15u}) put<std::uint32_t>(sector, x);  // 3 faces, face 1: 2*3 + 2 + 7 points
  write_file(dir / "sector.sgs", with_checksum(sector));
  CHECK_THROWS_WITH(Tables::load((dir / "sector.sgs").string()),
                    Catch::Contains("sector.sgs") && Catch::Contains("boundary vertex in 3 faces, face 1, rate 4096: too large to expand"));
  fs::remove_all(dir);
}

TEST_CASE("a generated limit stencil that does not sum to 1 is refused at load", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-sums");
  REQUIRE(run_stencilgen("--scheme nonpoly --valence 3 --n 1-2 -q --out " + dir.string()).status == 0);
  const fs::path file = dir / "nonpoly" / "nonpoly.sgs";
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // The limit stencil (the generated layout's only stored stencil) is the JSON's node (0, 0): find its bytes.
  const nlohmann::json table = nlohmann::json::parse(std::ifstream(dir / "nonpoly" / "v3" / "n1.json"));
  const auto& origin = table["nodes"][0];
  REQUIRE(origin["at"] == nlohmann::json::array({"0", "0"}));
  std::string limit;
  const double den = std::stod(origin["denominator"].get<std::string>());
  for (const auto& num : origin["numerators"]) put<double>(limit, std::stod(num.get<std::string>()) / den);
  const std::size_t at = bytes.find(limit);
  REQUIRE(at != std::string::npos);
  std::string broken = bytes.substr(0, bytes.size() - 8);
  double w = 0;
  std::memcpy(&w, broken.data() + at, 8);
  w += 0.25;
  std::memcpy(broken.data() + at, &w, 8);
  write_file(dir / "broken.sgs", with_checksum(broken));
  CHECK_THROWS_WITH(Tables::load((dir / "broken.sgs").string()), Catch::Contains("broken.sgs") && Catch::Contains("sums to"));
  REQUIRE_NOTHROW(Tables::load(file.string()));  // the untouched file loads
  fs::remove_all(dir);
}

TEST_CASE("exact JSON tables are read strictly: names, reflections, grid keys, repeated keys, nesting", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-json");
  REQUIRE(run_stencilgen("--scheme nonpoly --valence 3 --n 1-2 --out " + dir.string() + " -q").status == 0);
  const fs::path tables = dir / "nonpoly";
  fs::remove(tables / "nonpoly.sgs");
  REQUIRE(Tables::load(tables.string())->rates() == std::vector<int>{1, 2});
  auto edit = [&](const fs::path& file, const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(file));
    change(doc);
    std::ofstream(file) << doc.dump();
  };
  const fs::path table = tables / "v3" / "n2.json";
  const std::string original = [&] { std::ifstream in(table); return std::string(std::istreambuf_iterator<char>(in), {}); }();
  auto restore = [&] { write_file(table, original); };
  // An out-of-range reflection entry used to write past a stack buffer.
  edit(table, [](nlohmann::json& d) { d["reflection"][0] = 1000; });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n2.json: reflection[0]: index out of range"));
  restore();
  edit(table, [](nlohmann::json& d) { d["reflection"][0] = d["reflection"][1]; });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n2.json: reflection: differs from the other tables"));
  const fs::path first = tables / "v3" / "n1.json";
  const std::string first_text = [&] { std::ifstream in(first); return std::string(std::istreambuf_iterator<char>(in), {}); }();
  edit(first, [](nlohmann::json& d) { d["reflection"][0] = d["reflection"][1]; });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("the reflection is not a permutation"));
  write_file(first, first_text);
  restore();
  // A rate taken from a file name with atoi used to become a huge index.
  fs::copy_file(table, tables / "v3" / "n-1.json");
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n-1.json: not a table name of the form n<N>.json"));
  fs::remove(tables / "v3" / "n-1.json");
  // Grid keys "1/0" (division by zero) and "4e12" (a 256 TB vector).
  const fs::path regular = tables / "regular" / "n4.json";
  const std::string regular_text = [&] { std::ifstream in(regular); return std::string(std::istreambuf_iterator<char>(in), {}); }();
  for (const char* key : {"1/0", "4e12", "9/4", "1/3"}) {
    edit(regular, [&](nlohmann::json& d) { d["functions"][0]["values"][key] = "1/2"; });
    INFO(key);
    CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("values[\"" + std::string(key) + "\"]"));
    write_file(regular, regular_text);
  }
  // A missing field and a wrong kind are named.
  edit(table, [](nlohmann::json& d) { d.erase("nodes"); });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n2.json: nodes: missing"));
  restore();
  edit(table, [](nlohmann::json& d) { d["centres"][0]["denominator"] = 7; });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("centres[0].denominator: expected a string"));
  restore();
  edit(table, [](nlohmann::json& d) { d["centres"][0]["denominator"] = "0"; });
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("zero denominator"));
  restore();
  // A key given twice: the JSON library would keep one value without a word.
  {
    std::string twice = original;
    twice.insert(twice.rfind('}'), ", \"reflection\": []");
    write_file(table, twice);
    CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n2.json: reflection: the key appears twice"));
    nlohmann::json doc = nlohmann::json::parse(original);
    std::string inner = doc.dump();
    const std::size_t centres = inner.find("\"centres\":[{");
    REQUIRE(centres != std::string::npos);
    inner.insert(centres + 12, "\"denominator\":\"1\",");
    write_file(table, inner);
    CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("n2.json: centres[0].denominator: the key appears twice"));
    restore();
  }
  // Deep nesting is refused before it is built.
  write_file(table, std::string(100000, '[') + std::string(100000, ']'));
  CHECK_THROWS_WITH(Tables::load(tables.string()), Catch::Contains("nested deeper than"));
  restore();
  REQUIRE(Tables::load(tables.string())->rates() == std::vector<int>{1, 2});
  fs::remove_all(dir);
}

TEST_CASE("meshes outside the runtime's limits get a clear error naming the line or vertex", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-mesh");
  const std::string tables = nonpoly_dir();
  auto eval = [&](const std::string& mesh, const std::string& extra = "--face 0 --uv 1/2,1/2") {
    return run_stencileval("--tables " + tables + " --mesh " + mesh + " " + extra);
  };
  expect_error(eval("/dev/zero"), "/dev/zero: not a regular file");
  expect_error(eval(dir.string()), "not a regular file");
  write_file(dir / "huge.obj", "v 1.8e308 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  expect_error(eval((dir / "huge.obj").string()), "huge.obj:1: coordinate 1.8e308 is not a finite number");
  write_file(dir / "nan.obj", "v nan 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  expect_error(eval((dir / "nan.obj").string()), "nan.obj:1: coordinate nan");
  write_file(dir / "long.obj", "v 0 0 0\n# " + std::string(2 << 20, 'x') + "\n");
  expect_error(eval((dir / "long.obj").string()), "long.obj:2: line longer than");
  write_file(dir / "index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n");
  expect_error(eval((dir / "index.obj").string()), "index.obj:4: bad face index");
  // Texture and normal indices are not used, but a face vertex that is none of v, v/vt, v//vn, v/vt/vn is refused.
  for (const char* vertex : {"3/x", "3/1/2/4", "3/-"}) {
    write_file(dir / "slash.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 ") + vertex + "\n");
    expect_error(eval((dir / "slash.obj").string()), "slash.obj:4: bad face vertex");
  }
  // Valence 2 (a pillow of two quads) and valence 70 (a bipyramid's apex).
  write_file(dir / "pillow.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 4 3 2 1\n");
  expect_error(eval((dir / "pillow.obj").string()), "vertex 0 has valence 2; subdivision surfaces need every vertex in at least 3 faces");
  {
    std::ofstream out(dir / "spike.obj");
    const int k = 70;
    out << "v 0 0 1\nv 0 0 -1\n";
    for (int i = 0; i < k; ++i) out << "v " << std::cos(2 * M_PI * i / k) << " " << std::sin(2 * M_PI * i / k) << " 0\n";
    for (int i = 0; i < k; ++i) {
      const int a = 3 + i, b = 3 + (i + 1) % k;
      out << "f 1 " << a << " " << b << "\nf 2 " << b << " " << a << "\n";
    }
  }
  const std::string loop = generated_table("loop", "--valence 3-8 --n 24", "sgt").parent_path().string();
  expect_error(run_stencileval("--tables " + loop + " --mesh " + (dir / "spike.obj").string() + " --face 0 --uv 0,0"),
               "vertex 0 has valence 70; the runtime supports valences up to 64");
  // Numbering: the library counts from 0 and says so, and names the file.
  expect_error(eval((dir / "pillow.obj").string()), "numbered from 0");
  expect_error(eval((dir / "pillow.obj").string()), "pillow.obj: vertex 0 has valence 2");
  write_file(dir / "repeat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 3 3 4\n");
  expect_error(eval((dir / "repeat.obj").string()), "repeat.obj: face 0 uses vertex 2 twice");
  // Words after a vertex's numbers are refused by line; numbers (a weight, a colour) and comments are not.
  write_file(dir / "words.obj", "v 0 0 0\nv 1 0 0 oops\nv 0 1 0\nf 1 2 3\n");
  expect_error(eval((dir / "words.obj").string()), "words.obj:2: a vertex is three coordinates");
  // A UTF-8 byte-order mark is not part of the first line: the same surface as without it (it used to drop
  // the first vertex and shift every index by one).
  const std::string cube = read_text(fs::path(STENCIL_SOURCE_DIR) / "meshes" / "cube.obj");
  std::string coloured;  // each line with a colour after it, or a comment
  for (std::size_t at = 0, end; at < cube.size(); at = end + 1) {
    end = cube.find('\n', at);
    const std::string line = cube.substr(at, end - at);
    coloured += line + (line.rfind("v ", 0) == 0 ? " 0.5 0.25 1" : line.rfind("f ", 0) == 0 ? " # a face" : "") + "\n";
  }
  write_file(dir / "bom.obj", "\xEF\xBB\xBF" + cube);
  write_file(dir / "coloured.obj", coloured);
  // OBJ's line continuation: every face split over two lines (the second with
  // CRLF ends), and a comment ending in a backslash that must not swallow the
  // vertex after it; the same surface as the plain file.
  std::string continued;
  for (std::size_t at = 0, end; at < cube.size(); at = end + 1) {
    end = cube.find('\n', at);
    std::string line = cube.substr(at, end - at);
    if (at == cube.find("\nv ") + 1) continued += "# exported to C:\\models\\\n";  // just before the first vertex
    if (line.rfind("f ", 0) == 0) line.replace(line.find(' ', 2), 1, " \\\r\n   ");
    continued += line + "\n";
  }
  write_file(dir / "continued.obj", continued);
  const CliResult plain = eval((fs::path(STENCIL_SOURCE_DIR) / "meshes" / "cube.obj").string(), "--face 2 --uv 1/3,1/5");
  REQUIRE(plain.status == 0);
  for (const char* name : {"bom.obj", "coloured.obj", "continued.obj"}) {
    const CliResult r = eval((dir / name).string(), "--face 2 --uv 1/3,1/5");
    INFO(name << ": " << r.output);
    CHECK(r.status == 0);
    CHECK(r.output == plain.output);
  }
  // A continued line's error names its first line; a continuation at the end of the file ends the line.
  write_file(dir / "continued-bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 \\\n 3 4x\n");
  expect_error(eval((dir / "continued-bad.obj").string()), "continued-bad.obj:4: bad face index '4x'");
  write_file(dir / "continued-end.obj", cube.substr(0, cube.find_last_not_of('\n') + 1) + " \\");
  const CliResult at_end = eval((dir / "continued-end.obj").string(), "--face 2 --uv 1/3,1/5");
  INFO(at_end.output);
  CHECK(at_end.status == 0);
  CHECK(at_end.output == plain.output);
  fs::remove_all(dir);
}

TEST_CASE("tool options and parameters outside their limits are refused, not wrapped or clamped silently", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-options");
  const std::string tables = nonpoly_dir(), cube = (kMeshes / "cube.obj").string();
  auto eval = [&](const std::string& extra) { return run_stencileval("--tables " + tables + " --mesh " + cube + " " + extra); };
  auto tess = [&](const std::string& extra) {
    return run_stenciltess("--tables " + tables + " --mesh " + cube + " --out " + (dir / "t.ply").string() + " " + extra);
  };
  // A denominator whose lcm used to wrap, silently giving the point at (0, 1/2):
  // now the point at the parameter given, within a bound of the exact one.
  auto last_point = [](const CliResult& r) {
    const auto line = r.output.substr(r.output.rfind('\n', r.output.size() - 2) + 1);
    Point p{};
    std::istringstream(line) >> p[0] >> p[1] >> p[2];
    return p;
  };
  const CliResult wrapped = eval("--face 0 --uv 4611686018427387903/9223372036854775807,1/3");
  INFO(wrapped.output);
  REQUIRE(wrapped.status == 0);
  CHECK(wrapped.output.find("within") != std::string::npos);
  const Point half = last_point(eval("--face 0 --uv 1/2,1/3")), got = last_point(wrapped);
  CHECK(std::hypot(got[0] - half[0], got[1] - half[1], got[2] - half[2]) < 1e-12);
  expect_error(eval("--face 0 --uv 1/99999999999999999999,1/2"), "is not an exact rational");
  // A leading '+' is taken by decimals as by rationals (+1/2 was, +0.5 was refused).
  const CliResult plus = eval("--face 0 --uv +0.5,+0.25");
  INFO(plus.output);
  CHECK(plus.status == 0);
  CHECK(last_point(plus) == last_point(eval("--face 0 --uv 0.5,0.25")));
  expect_error(eval("--face 0 --uv +-0.5,0.25"), "is neither an exact rational");
  expect_error(eval("--face -1 --uv 1/2,1/2"), "--face '-1' is not a number");
  expect_error(eval("--face 0 --uv 1/2"), "--uv expects U,V");
  expect_error(eval("--face 0"), "give --face and --uv, or --batch");
  write_file(dir / "q.txt", "0 1/2 1/2\nx 1/2 1/2\n");
  expect_error(eval("--batch " + (dir / "q.txt").string()), "q.txt:2: face 'x' is not a number");
  write_file(dir / "q.txt", "0 1/2 1/2\n9 0 0\n");
  expect_error(eval("--batch " + (dir / "q.txt").string()), "q.txt:2: face 9 does not exist");
  expect_error(eval("--batch " + dir.string()), "not a regular file");
  // A huge argument is quoted by its start and length, not echoed whole.
  for (const std::string& uv : {std::string(100000, '(') + ",1/2", std::string(5000, '1') + "/3,1/2"}) {
    const CliResult r = eval("--face 0 --uv '" + uv + "'");
    INFO(r.output.substr(0, 400));
    CHECK(r.status == 1);
    CHECK(r.output.size() < 400);
    CHECK(r.output.find("characters)") != std::string::npos);
  }
  expect_error(tess("--rate 2147483647"), "--rate must be 1..4096");
  expect_error(tess("--rate 0"), "--rate must be 1..4096");
  expect_error(tess("--rate 4 --threads 2147483647"), "--threads must be 1..256");
  expect_error(tess("--tolerance 0"), "--tolerance must be a positive finite number");
  expect_error(tess("--camera 0,0,5,0,0,0 --pixels 0"), "--pixels must be a positive finite number");
  expect_error(tess("--camera 0,0,5,0,0 --pixels 4"), "--camera expects");
  expect_error(tess("--rate nope"), "--rate");
  expect_error(tess("--camera 1e308,0,6,0,0,0 --pixels 8"), "too large");
  expect_error(tess("--rate 4 --pixels 8"), "--pixels applies to --camera rates only");
  expect_error(tess("--rate 4 --fov 90"), "--fov applies to --camera rates only");
  CHECK_FALSE(fs::exists(dir / "t.ply"));
  // Tiny tolerances and pixel sizes ask for the largest rate, with a warning, instead of wrapping to rate 1.
  for (const std::string& mode : {std::string("--tolerance 1e-300"), std::string("--camera 0,0,5,0,0,0 --pixels 1e-300")}) {
    const CliResult r = tess(mode);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(r.output.find("were asked for on the prepared faces") != std::string::npos);
    CHECK(r.output.find("; the tables stop at 24") != std::string::npos);
    CHECK(r.output.find("rates 24..24") != std::string::npos);
  }
  // --tolerance takes polygon meshes, as --rate does.
  {
    std::ofstream prism(dir / "prism.obj");
    prism << "v 0 0 0\nv 1 0 0\nv 0.3 0.9 0\nv 0 0 1.2\nv 1 0 1.1\nv 0.4 1 1.3\n"
             "f 1 3 2\nf 4 5 6\nf 1 2 5 4\nf 2 3 6 5\nf 3 1 4 6\n";
  }
  const CliResult r = run_stenciltess("--tables " + tables + " --mesh " + (dir / "prism.obj").string() + " --tolerance 0.01 --out " +
                                      (dir / "p.ply").string());
  INFO(r.output);
  CHECK(r.status == 0);
  fs::remove_all(dir);
}

TEST_CASE("empty option values are refused, extensions are read in either case, a mesh too small for floats is refused",
          "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-names");
  const std::string tables = nonpoly_dir(), cube = (kMeshes / "cube.obj").string();
  write_file(dir / "q.xyz", "0.1 0.2 0.9\n3 -1 0.5\n");
  auto dist = [&](const std::string& points, const std::string& extra) {
    return run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + cube + " --points " + points + " " + extra);
  };
  // `--out ''` used to write the results to standard output, as if no --out were given.
  const CliResult empty = dist((dir / "q.xyz").string(), "--out ''");
  expect_error(empty, "--out: an empty value");
  expect_error(run_stenciltess("--tables " + tables + " --mesh '' --rate 2 --out " + (dir / "t.obj").string()), "--mesh: an empty value");
  expect_error(run_stencileval("--tables " + tables + " --mesh " + cube + " --face 0 --uv ''"), "--uv: an empty value");
  // A points file named .PLY is a PLY file (it used to be read as `x y z` lines and fail on its header).
  write_file(dir / "Q.PLY", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
                             "0.1 0.2 0.9\n3 -1 0.5\n");
  const CliResult xyz = dist((dir / "q.xyz").string(), ""), ply = dist((dir / "Q.PLY").string(), "");
  INFO(ply.output);
  CHECK(ply.status == 0);
  CHECK(xyz.status == 0);
  CHECK(ply.output.substr(0, ply.output.find("points")) == xyz.output.substr(0, xyz.output.find("points")));
  // A tessellation written as OUT.PLY is the binary PLY that out.ply would be.
  const CliResult upper = run_stenciltess("--tables " + tables + " --mesh " + cube + " --rate 2 --out " + (dir / "T.PLY").string());
  INFO(upper.output);
  REQUIRE(upper.status == 0);
  CHECK(read_text(dir / "T.PLY").rfind("ply\nformat binary_little_endian", 0) == 0);
  // A cube of 1e-40: its tessellation's floats are below the smallest normal
  // float and have lost their digits, so it is refused; one of 1e-30 is not.
  auto scaled_cube = [&](const std::string& scale) {
    const fs::path path = dir / ("cube" + scale + ".obj");
    std::ifstream in(cube);
    std::ofstream out(path);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("v ", 0) == 0) {
        std::istringstream v(line.substr(2));
        double x = 0, y = 0, z = 0;
        v >> x >> y >> z;
        out << "v " << x << scale << " " << y << scale << " " << z << scale << "\n";
      } else {
        out << line << "\n";
      }
    }
    return path.string();
  };
  for (const char* ext : {".obj", ".ply"}) {
    const fs::path out = dir / (std::string("tiny") + ext);
    const CliResult tiny = run_stenciltess("--tables " + tables + " --mesh " + scaled_cube("e-40") + " --rate 2 --out " + out.string());
    INFO(tiny.output);  // the progress line of the tessellation, then the error
    CHECK(tiny.status == 1);
    CHECK_THAT(tiny.output, Catch::Contains("coordinate of the tessellation is at most") && Catch::Contains("too small for its floats"));
    CHECK_FALSE(fs::exists(out));
    const CliResult small = run_stenciltess("--tables " + tables + " --mesh " + scaled_cube("e-30") + " --rate 2 --out " + out.string());
    INFO(small.output);
    CHECK(small.status == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("an output that is a symbolic link is written through it, and a FIFO or device is refused, not replaced",
          "[runtime][robustness]") {
  // Renaming the finished file onto the output's name used to replace a link
  // with a plain file, and to delete a FIFO or device (`--out /dev/null`).
  const fs::path dir = scratch_dir("robust-links");
  const std::string tables = nonpoly_dir(), cube = (kMeshes / "cube.obj").string();
  write_file(dir / "q.xyz", "0.1 0.2 0.9\n3 -1 0.5\n");
  auto dist = [&](const fs::path& out) {
    return run_command(STENCILDIST_EXE, "--tables " + tables + " --mesh " + cube + " --points " + (dir / "q.xyz").string() +
                                            " --out " + out.string());
  };
  fs::create_directories(dir / "real");
  write_file(dir / "real" / "r.txt", "earlier");
  fs::create_symlink("real/r.txt", dir / "link.txt");  // relative, as `ln -s` makes them
  fs::create_symlink("link.txt", dir / "link2.txt");   // and a chain of two
  for (const char* name : {"link.txt", "link2.txt"}) {
    write_file(dir / "real" / "r.txt", "earlier");
    const CliResult r = dist(dir / name);
    INFO(r.output);
    CHECK(r.status == 0);
    CHECK(fs::is_symlink(dir / name));
    const std::string results = read_text(dir / "real" / "r.txt");  // the results, a line per point
    CHECK(std::count(results.begin(), results.end(), '\n') == 2);
    CHECK(results.find("earlier") == std::string::npos);
  }
  CHECK(std::distance(fs::directory_iterator(dir / "real"), fs::directory_iterator{}) == 1);  // nothing staged left
  // A link that names no file yet: the file is made where it points.
  fs::create_symlink("real/new.txt", dir / "dangling.txt");
  CHECK(dist(dir / "dangling.txt").status == 0);
  CHECK(fs::is_regular_file(dir / "real" / "new.txt"));
  CHECK(fs::is_symlink(dir / "dangling.txt"));
  // A FIFO is refused before any work, and stays a FIFO (the tessellation's frames too).
  REQUIRE(::mkfifo((dir / "fifo.txt").c_str(), 0600) == 0);
  expect_error(dist(dir / "fifo.txt"), "is not a regular file (a device, FIFO or socket)");
  CHECK(fs::is_fifo(dir / "fifo.txt"));
  REQUIRE(::mkfifo((dir / "f1.obj").c_str(), 0600) == 0);
  write_file(dir / "frame0.obj", read_text(cube));
  write_file(dir / "frame1.obj", read_text(cube));
  const CliResult frames = run_stenciltess("--tables " + tables + " --mesh " + cube + " --rate 2 --frames '" +
                                           (dir / "frame*.obj").string() + "' --out '" + (dir / "f%d.obj").string() + "'");
  INFO(frames.output);
  CHECK(frames.status == 1);
  CHECK_THAT(frames.output, Catch::Contains("is not a regular file"));
  CHECK(fs::is_fifo(dir / "f1.obj"));
  CHECK_FALSE(fs::exists(dir / "f0.obj"));
  fs::remove_all(dir);
}

TEST_CASE("triangle tables' children and regular polynomial are checked at load", "[runtime][robustness][triangle]") {
  const fs::path dir = scratch_dir("robust-children");
  std::ifstream in(generated_table("loop", "--valence 3 --n 1", "sgt"), std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string body = file.substr(0, file.size() - 8);
  // Valence 3's children: 4 cells, the first the EV's own (valence 3, region 0, rotation 0).
  std::string pattern;
  for (std::uint32_t x : {4u, 3u, 0u, 0u}) put(pattern, x);
  const std::size_t at = body.find(pattern);
  REQUIRE(at != std::string::npos);
  auto refused = [&](std::size_t offset, std::uint32_t value, const std::string& message) {
    std::string bytes = body;
    std::memcpy(bytes.data() + offset, &value, sizeof value);
    write_file(dir / "bad.sgt", with_checksum(bytes));
    CHECK_THROWS_WITH(Tables::load((dir / "bad.sgt").string()), Catch::Contains(message));
  };
  refused(at, 5, "5 children (the scheme's step makes 4)");
  refused(at + 4, 7, "a child of valence 7");
  refused(at + 8, 2, "a child of a region the tables lack");
  refused(at + 12, 3, "child 0 has an invalid kind");
  refused(at + 20, 1, "child 0: invalid entry 0");                    // the first entry's row must be 0
  refused(at + 24, 100000, "child 0: invalid entry 0");               // a column beyond the layout
  refused(at + 16, 0x7fffffff, "child 0: truncated rows");
  // The sectors (version 7) end the file: boundary vertices in 1..6 faces (6:
  // the tables always hold the regular valence), 18 crease, 21 corner, 18
  // dart and 4 cone sectors, the first a crease vertex in one face. One byte less is truncated.
  std::string sectors_pattern;
  put(sectors_pattern, 61u);
  sectors_pattern.push_back('\0');
  for (std::uint32_t x : {1u, 0u}) put(sectors_pattern, x);
  const std::size_t sectors_at = body.rfind(sectors_pattern);
  REQUIRE(sectors_at != std::string::npos);
  write_file(dir / "short.sgt", with_checksum(body.substr(0, body.size() - 1)));
  CHECK_THROWS_WITH(Tables::load((dir / "short.sgt").string()), Catch::Contains("truncated"));
  refused(sectors_at, 1000000, "truncated sector list");
  refused(sectors_at + 5, 0, "sector 0: invalid kind");
  refused(sectors_at + 5, 3, "a boundary vertex in three faces has the regular patch");
  refused(sectors_at + 4, 2u | (1u << 8), "a dart or cone point has at least three");  // rule 2 (a dart) in one face
  // Sector 0 is a boundary vertex in one face: B, e_0, e_1 and three more points (layout from byte 17, 12 bytes each).
  refused(sectors_at + 13, 100, "a layout of 100 points");
  refused(sectors_at + 13, 2, "a layout of 2 points");
  refused(sectors_at + 17 + 12 * 3 + 4, 5, "invalid layout point 3");       // beyond the wedge's third ring
  refused(sectors_at + 17 + 12 * 1 + 4, 2, "invalid layout point 1");       // e_0 out of place
  {
    std::string bytes = body;  // point 4 repeats point 3
    std::memcpy(bytes.data() + sectors_at + 17 + 12 * 4, bytes.data() + sectors_at + 17 + 12 * 3, 12);
    write_file(dir / "bad.sgt", with_checksum(bytes));
    CHECK_THROWS_WITH(Tables::load((dir / "bad.sgt").string()), Catch::Contains("layout point 4 is repeated"));
  }
  // After the layout its limit stencil (6 doubles), then its four cells: the first is the sector's own patch.
  refused(sectors_at + 17 + 12 * 6 + 8 * 6 + 4, 6, "cell 0 is not the sector's own patch");
  // The unchanged file loads, with its subdivision and Loop's quartic basis.
  write_file(dir / "good.sgt", with_checksum(body));
  const auto good = Tables::load((dir / "good.sgt").string());
  CHECK(good->triangle().has_descent());
  CHECK(good->triangle().polynomial_degree() == 4);
  // The degree (before 15 coefficients per valence-6 layout point and the
  // one-byte derivative flag): a huge one is refused before any arithmetic on
  // it (fuzzing found the overflow).
  const std::size_t degree_at = sectors_at - 1 - 8 * 15 * good->triangle().layout(6).size() - 4;
  refused(degree_at, 0x80000001u, "degree 2147483649 is above 8");
  refused(degree_at, 9, "degree 9 is above 8");
  // Loop's polynomial serves its derivatives: a flag claiming stored derivative stencils is refused.
  std::string flagged = body;
  flagged[sectors_at - 1] = 1;
  write_file(dir / "flag.sgt", with_checksum(flagged));
  CHECK_THROWS_WITH(Tables::load((dir / "flag.sgt").string()), Catch::Contains("invalid regular derivative flag"));
  fs::remove_all(dir);
}

TEST_CASE("single-precision tables say their values are not exact, with a bound that holds", "[runtime][robustness]") {
  // The same scheme in double and in single precision: every single value is
  // within its reported bound of the double one (itself exact to rounding),
  // and no single value claims to be exact.
  const auto exact = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 4", "sgs").string());
  const auto single = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 4 --binary-precision single", "sgs").string());
  const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 4 --binary-precision single", "sgt").string());
  CHECK(single->single_precision());
  CHECK(loop->single_precision());
  CHECK_FALSE(exact->single_precision());
  const Mesh mesh = read_obj((fs::path(STENCIL_SOURCE_DIR) / "meshes" / "chess-piece.obj").string());
  const Surface a = test_runtime::surface_of(exact, mesh), b = test_runtime::surface_of(single, mesh);
  double worst = 0;
  for (std::size_t face = 0; face < mesh.face_count(); face += 7)
    for (const ExactParameter& at : {test_runtime::grid(1, 3, 4), ExactParameter{Fraction::make(1, 3), Fraction::make(1, 7)}}) {
      const Evaluation x = a.evaluate(face, at, 1e-13), y = b.evaluate(face, at, 1e-13);
      CHECK_FALSE(y.exact);
      const double d = std::hypot(x.point[0] - y.point[0], x.point[1] - y.point[1], x.point[2] - y.point[2]);
      CHECK(d <= y.bound + x.bound);
      worst = std::max(worst, d);
    }
  CHECK(worst > 0);  // the rounding is there to be bounded
  const Mesh tri = read_obj((fs::path(STENCIL_SOURCE_DIR) / "meshes" / "tri-mix.obj").string());
  CHECK_FALSE(test_runtime::surface_of(loop, tri).evaluate(0, test_runtime::grid(1, 1, 4), 1e-13).exact);
  // stencileval will not print a bound above the tolerance asked for.
  const std::string tables = generated_table("nonpoly", "--valence 3-8 --n 4 --binary-precision single", "sgs").string();
  const std::string chess = (fs::path(STENCIL_SOURCE_DIR) / "meshes" / "chess-piece.obj").string();
  expect_error(run_stencileval("--tables " + tables + " --mesh " + chess + " --face 7 --uv 1/3,1/7"), "single precision");
  const CliResult r = run_stencileval("--tables " + tables + " --mesh " + chess + " --face 7 --uv 1/3,1/7 --tolerance 1e-4");
  CHECK(r.status == 0);
  CHECK(r.output.find("within") != std::string::npos);
}

TEST_CASE("outputs are staged under names of their own process, and what killed runs left is swept by the next", "[runtime][robustness]") {
  const fs::path dir = scratch_dir("robust-leftovers");
  const std::string target = (dir / "out.obj").string();
  const auto read = [](const fs::path& p) { std::ifstream in(p); return std::string(std::istreambuf_iterator<char>(in), {}); };
  // pid 999999999 is above any pid_max: a dead process. pid 1 is alive.
  write_file(dir / ".out.999999999.partial.obj", "half");
  write_file(dir / ".out.999999998.staged.obj", "staged");
  write_file(dir / ".out.999999997.previous.obj", "the old output");
  write_file(dir / ".out.1.partial.obj", "a live run's");
  write_file(dir / ".out.x1.partial.obj", "not ours");
  write_file(dir / ".out.999999999.partial.ply", "another target's");
  // A run killed between moving the old output aside and moving the new one in: the old one comes back.
  stencil_runtime::sweep_left_by_killed_runs(target);
  CHECK(read(target) == "the old output");
  CHECK_FALSE(fs::exists(dir / ".out.999999999.partial.obj"));
  CHECK_FALSE(fs::exists(dir / ".out.999999998.staged.obj"));
  CHECK_FALSE(fs::exists(dir / ".out.999999997.previous.obj"));
  CHECK(fs::exists(dir / ".out.1.partial.obj"));
  CHECK(fs::exists(dir / ".out.x1.partial.obj"));
  CHECK(fs::exists(dir / ".out.999999999.partial.ply"));
  // With the target in place a moved-aside one is dropped, not put back.
  write_file(dir / ".out.999999996.previous.obj", "older");
  stencil_runtime::sweep_left_by_killed_runs(target);
  CHECK(read(target) == "the old output");
  CHECK_FALSE(fs::exists(dir / ".out.999999996.previous.obj"));
  // Writing sweeps first, and stages under this process's own name, which does not outlive the write.
  write_file(dir / ".out.999999995.partial.obj", "half");
  stencil_runtime::write_file_atomically(target, [](std::FILE* f) { std::fputs("new", f); });
  CHECK(read(target) == "new");
  CHECK_FALSE(fs::exists(dir / ".out.999999995.partial.obj"));
  CHECK_FALSE(fs::exists(stencil_runtime::name_beside(target, "partial")));
  CHECK(stencil_runtime::name_beside(target, "partial") == (dir / (".out." + std::to_string(::getpid()) + ".partial.obj")).string());
  // A writer that throws leaves neither the target changed nor its partial file.
  CHECK_THROWS(stencil_runtime::write_file_atomically(target, [](std::FILE* f) {
    std::fputs("broken", f);
    throw stencil_runtime::LoadError("stopped");
  }));
  CHECK(read(target) == "new");
  CHECK_FALSE(fs::exists(stencil_runtime::name_beside(target, "partial")));
  fs::remove_all(dir);
}
