// The runtime on triangle meshes against independent references: OpenSubdiv's
// Loop limit surface on the bundled triangle meshes (through the runtime's own
// topology, Loop isolation step, chart walks and rotations), the tessellation's
// centre points against OpenSubdiv too, watertightness by an independent edge
// count, and the command-line tools with .sgt tables.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>

#include "bfr_reference.hpp"
#include "bundled_meshes.hpp"
#include "cli.hpp"
#include "runtime_checks.hpp"
#include "runtime_api.hpp"
#include "triangle/triangle_family.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;
using test_meshes::bundled;
using test_meshes::kMeshes;
using test_meshes::kTriangleMeshes;

namespace {

// Loop tables as the quick start makes them, once per test process.
fs::path loop_tables() { return generated_table("loop", "--valence 3-8 --n 24", "sgt"); }


bfr_reference::BfrLimit loop_reference(const Mesh& mesh) {
  return {mesh.positions, mesh.face_sizes, mesh.face_vertices, OpenSubdiv::Sdc::SCHEME_LOOP};
}

}  // namespace

TEST_CASE("runtime Loop evaluation equals OpenSubdiv on every bundled triangle mesh", "[runtime][triangle][opensubdiv]") {
  const auto tables = Tables::load(loop_tables().string());
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    CHECK(surface.topology().refinement_steps() == 1);  // every bundled mesh has faces with two extraordinary corners
    auto reference = loop_reference(mesh);
    const double size = extent(mesh);
    double worst = 0;
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      for (long n : {1L, 2L, 3L, 4L, 5L, 6L, 7L, 8L, 24L}) {
        if (n == 24 && f % 5 != 0) continue;
        for (long j = 0; j <= n; ++j)
          for (long i = 0; i + j <= n; ++i) {
            const Point ours = at_grid(surface, f, i, j, n);
            const auto ref = reference.evaluate(static_cast<int>(f), double(i) / n, double(j) / n);
            const double err = distance(ours, ref) / size;
            worst = std::max(worst, err);
            INFO(name << " face " << f << " at (" << i << "/" << n << ", " << j << "/" << n << "): " << err);
            REQUIRE(err < 1e-12);
          }
      }
    INFO(name << ": largest difference " << worst);
    SUCCEED();
  }
}

TEST_CASE("triangle tessellation points equal OpenSubdiv at the up and down centres", "[runtime][triangle][opensubdiv]") {
  const auto tables = Tables::load(loop_tables().string());
  for (const char* name : kTriangleMeshes) {
    // The prepared mesh itself, so that each face's centres are Bfr parameters of that face.
    const Mesh prepared = surface_of(tables, bundled(name)).prepared_mesh();
    const Surface surface = surface_of(tables, prepared);
    REQUIRE(surface.topology().refinement_steps() == 0);
    auto reference = loop_reference(prepared);
    const double size = extent(prepared);
    for (int n : {1, 2, 3, 5, 24}) {
      // A uniform rate: face f's n^2 centres are points [f n^2, (f+1) n^2).
      const PolygonSoup soup = tessellate(surface, std::vector<int>(prepared.face_count(), n));
      for (std::size_t f = 0; f < prepared.face_count(); f += 3) {
        const auto* centres = soup.positions.data() + f * static_cast<std::size_t>(n * n);
        for (int j = 0; j < n; ++j)
          for (int i = 0; i + j < n; ++i)
            for (int kind = 1; kind <= 2; ++kind) {
              if (kind == 2 && i + j > n - 2) continue;
              const int k = kind == 1 ? up_centre_index(i, j, n) : down_centre_index(i, j, n);
              const auto ref = reference.evaluate(static_cast<int>(f), (3.0 * i + kind) / (3 * n), (3.0 * j + kind) / (3 * n));
              const auto& c = centres[static_cast<std::size_t>(k)];
              INFO(name << " face " << f << " n " << n << (kind == 1 ? " up " : " down ") << i << "," << j);
              REQUIRE(distance({c[0], c[1], c[2]}, ref) / size < 1e-6);
            }
      }
    }
  }
}

TEST_CASE("triangle tessellations are closed oriented 2-manifolds for random rate mixes 1..24", "[runtime][triangle][tessellation]") {
  const auto tables = Tables::load(loop_tables().string());
  std::mt19937 rng(20261122u);
  for (const char* name : kTriangleMeshes) {
    const Mesh mesh = bundled(name);
    const Surface surface = surface_of(tables, mesh);
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<int> rates(mesh.face_count());
      for (int& r : rates) r = trial == 0 ? 1 : std::uniform_int_distribution<int>(1, 24)(rng);
      const PolygonSoup soup = tessellate(surface, rates);
      INFO(name << " trial " << trial);
      REQUIRE(tessellation_defect(soup, euler_characteristic(mesh)) == "");
    }
  }
}

TEST_CASE("stencileval and stenciltess take triangle meshes with .sgt tables", "[runtime][triangle][tessellation]") {
  const fs::path dir = scratch_dir("triangle-tools");
  const std::string tables = loop_tables().parent_path().string();  // the directory stencilgen wrote
  const std::string torus = (kMeshes / "tri-torus.obj").string();
  const Mesh mesh = bundled("tri-torus");
  auto reference = loop_reference(mesh);
  {
    std::ofstream q(dir / "q.txt");
    q << "0 0 0\n5 1/3 1/3\n17 1/2 1/4\n191 0 1\n100 5/24 7/12\n";
  }
  const CliResult r = run_stencileval("--tables " + tables + " --mesh " + torus + " --batch " + (dir / "q.txt").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  std::istringstream lines(r.output);
  const double queries[][3] = {{0, 0, 0}, {5, 1.0 / 3, 1.0 / 3}, {17, 0.5, 0.25}, {191, 0, 1}, {100, 5.0 / 24, 7.0 / 12}};
  for (const auto& q : queries) {
    Point p{};
    REQUIRE(static_cast<bool>(lines >> p[0] >> p[1] >> p[2]));
    REQUIRE(distance(p, reference.evaluate(static_cast<int>(q[0]), q[1], q[2])) / extent(mesh) < 1e-12);
  }
  {
    std::ofstream rates(dir / "rates.txt");
    for (std::size_t f = 0; f < mesh.face_count(); ++f) rates << 1 + (f * 7) % 24 << "\n";
  }
  for (const std::string& mode : {std::string("--rate 5"), "--rates " + (dir / "rates.txt").string(),
                                  std::string("--tolerance 0.002"), std::string("--camera 0,-6,3,0,0,0 --pixels 5")}) {
    const fs::path out = dir / "t.obj";
    const CliResult t = run_stenciltess("--tables " + tables + " --mesh " + torus + " " + mode + " --out " + out.string());
    INFO(mode << "\n" << t.output);
    REQUIRE(t.status == 0);
    const Mesh m = read_obj(out.string());
    const auto directed = directed_edges(m);
    for (const auto& [e, count] : directed) REQUIRE((count == 1 && directed.count({e.second, e.first}) == 1));
    REQUIRE(static_cast<long>(m.vertex_count()) - static_cast<long>(directed.size() / 2) + static_cast<long>(m.face_count()) == 0);
  }
  fs::remove_all(dir);
}

TEST_CASE("triangle meshes and tables: bad input gets clear errors, and nothing is written", "[runtime][triangle][errors]") {
  const fs::path dir = scratch_dir("triangle-errors");
  const std::string loop = loop_tables().string();
  auto eval = [&](const std::string& tables, const std::string& mesh, const std::string& extra = "--face 0 --uv 1/3,1/3") {
    return run_stencileval("--tables " + tables + " --mesh " + mesh + " " + extra);
  };
  auto expect = [](const CliResult& r, const std::string& text) {
    INFO(r.output);
    REQUIRE(r.status != 0);
    REQUIRE(r.output.find(text) != std::string::npos);
  };
  expect(eval(loop, (kMeshes / "cube.obj").string()), "face 0 has 4 vertices; triangle schemes need a mesh of triangles");
  expect(eval(loop, (kMeshes / "icosahedron.obj").string(), "--face 0 --uv 2/3,1/2"),
         "lies outside face 0 (its domain is u, v >= 0 and u + v <= 1)");
  expect(eval(loop, (kMeshes / "icosahedron.obj").string(), "--face 20 --uv 0,0"), "face 20 does not exist");
  // A valence the tables lack, named with the call that adds it.
  REQUIRE(run_stencilgen("-q --scheme loop --valence 3-5 --n 2 --out " + dir.string()).status == 0);
  expect(eval((dir / "loop").string(), (kMeshes / "tri-mix.obj").string()),
         "has valence 8, which the tables do not cover (missing valence 8); generate tables that cover this mesh with: "
         "stencilgen --scheme loop --valence 3-5,8 --n 1-2 --out");
  // A corrupt table file, and stenciltess leaves no output behind.
  {
    std::string bytes;
    {
      std::ifstream in(loop, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    bytes[bytes.size() / 2] ^= 0x5a;
    std::ofstream(dir / "bad.sgt", std::ios::binary) << bytes;
  }
  expect(eval((dir / "bad.sgt").string(), (kMeshes / "icosahedron.obj").string()), "bad.sgt: checksum mismatch");
  // A version 1 file (before the sqrt(3) band regions), its checksum made valid
  // again (FNV-1a 64 over every byte before the last eight): refused by version.
  {
    std::string bytes;
    {
      std::ifstream in(loop, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    bytes[8] = 1, bytes[9] = bytes[10] = bytes[11] = 0;  // the u32 after the 8-byte magic
    std::uint64_t h = 14695981039346656037ull;
    for (std::size_t k = 0; k + 8 < bytes.size(); ++k) h = (h ^ static_cast<unsigned char>(bytes[k])) * 1099511628211ull;
    for (int k = 0; k < 8; ++k) bytes[bytes.size() - 8 + static_cast<std::size_t>(k)] = static_cast<char>((h >> (8 * k)) & 0xff);
    std::ofstream(dir / "old.sgt", std::ios::binary) << bytes;
  }
  expect(eval((dir / "old.sgt").string(), (kMeshes / "icosahedron.obj").string()),
         "old.sgt: format version 1 is not supported (expected 2 to 7; regenerate the tables");
  const fs::path out = dir / "never.ply";
  expect(run_stenciltess("--tables " + (dir / "bad.sgt").string() + " --mesh " + (kMeshes / "icosahedron.obj").string() +
                         " --rate 3 --out " + out.string()),
         "checksum mismatch");
  expect(run_stenciltess("--tables " + loop + " --mesh " + (kMeshes / "cube.obj").string() + " --rate 3 --out " + out.string()),
         "triangle schemes need a mesh of triangles");
  REQUIRE(!fs::exists(out));
  fs::remove_all(dir);
}
