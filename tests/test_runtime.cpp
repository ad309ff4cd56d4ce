// The runtime against independent references: OpenSubdiv's Catmull-Clark limit
// on the bundled meshes (through the runtime's own topology, isolation step,
// patch gathering and rotations), continuity across shared edges for the
// non-polynomial scheme, watertightness by an independent edge count, and the
// command-line tools' errors.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>

#include "bfr_reference.hpp"
#include "cli.hpp"
#include "runtime_checks.hpp"
#include "runtime_api.hpp"
#include "mesh/uniform_topology.hpp"
#include "tables/quad_tables.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

// Tables generated once per test process.
fs::path tables_for(const std::string& scheme) { return generated_table(scheme, "--valence 3-8 --n 24", "sgs"); }

const char* kBundled[] = {"cube", "torus-3-5", "chess-piece", "bumpy-sphere"};

}  // namespace

TEST_CASE("runtime Catmull-Clark evaluation equals OpenSubdiv on every bundled mesh", "[runtime][opensubdiv]") {
  const auto tables = Tables::load(tables_for("catmull-clark").string());
  for (const char* name : kBundled) {
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface surface = surface_of(tables, mesh);
    bfr_reference::BfrLimit reference(mesh.positions, mesh.face_sizes, mesh.face_vertices);
    const double size = extent(mesh);
    double worst = 0;
    for (std::size_t f = 0; f < mesh.face_count(); f += (mesh.face_count() > 100 ? 3 : 1))
      for (long n : {1L, 2L, 3L, 5L, 8L})
        for (long j = 0; j <= n; ++j)
          for (long i = 0; i <= n; ++i) {
            const Point ours = at_grid(surface, f, i, j, n);
            const auto ref = reference.evaluate(static_cast<int>(f), double(i) / n, double(j) / n);
            const double err = distance(ours, ref) / size;
            worst = std::max(worst, err);
            INFO(name << " face " << f << " at (" << i << "/" << n << ", " << j << "/" << n << "): " << err);
            REQUIRE(err < 1e-12);
          }
    INFO(name << ": largest difference " << worst);
    SUCCEED();
  }
}

TEST_CASE("the non-polynomial surface is continuous across every edge and vertex of the bundled meshes", "[runtime]") {
  const auto tables = Tables::load(tables_for("nonpoly").string());
  for (const char* name : kBundled) {
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface surface = surface_of(tables, mesh);
    const QuadTopology topo(Connectivity{mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices});
    const double size = extent(mesh);
    const long n = 12;
    // A point on edge c -> c+1 of face f at fraction t/n from corner c, in f's parameters.
    auto on_edge = [&](std::size_t f, int c, long t) {
      const long u[4] = {t, n, n - t, 0}, v[4] = {0, t, n, n - t};
      return at_grid(surface, f, u[c & 3], v[c & 3], n);
    };
    for (std::uint32_t h = 0; h < 4 * topo.faces(); ++h) {
      const std::uint32_t o = topo.twin(h);
      for (long t = 0; t <= n; ++t) {
        const Point a = on_edge(QuadTopology::face_of(h), QuadTopology::corner_of(h), t);
        const Point b = on_edge(QuadTopology::face_of(o), QuadTopology::corner_of(o), n - t);
        INFO(name << " half-edge " << h << " t = " << t << "/" << n);
        REQUIRE(distance(a, b) / size < 1e-13);
      }
    }
  }
}

TEST_CASE("tessellations are closed oriented 2-manifolds for random rate mixes 1..24", "[runtime][tessellation]") {
  const auto tables = Tables::load(tables_for("nonpoly").string());
  std::mt19937 rng(20261122u);
  for (const char* name : kBundled) {
    const Mesh mesh = read_obj((kMeshes / (std::string(name) + ".obj")).string());
    const Surface surface = surface_of(tables, mesh);
    const long chi_expected = euler_characteristic(mesh);
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<int> rates(mesh.face_count());
      for (int& r : rates) r = std::uniform_int_distribution<int>(1, 24)(rng);
      const PolygonSoup soup = tessellate(surface, rates);
      INFO(name << " trial " << trial);
      REQUIRE(tessellation_defect(soup, chi_expected) == "");
    }
  }
}

TEST_CASE("tessellation vertices equal stencileval at their parameters", "[runtime][tessellation]") {
  const auto table = tables_for("nonpoly");
  const Mesh mesh = read_obj((kMeshes / "torus-3-5.obj").string());
  const Surface surface = surface_of(Tables::load(table.string()), mesh);
  // Original rate 6 -> prepared faces at rate 3 after one isolation step; the
  // centre (i, j) of child c of face F lies at an original parameter on the grid 1/12.
  const PolygonSoup soup = tessellate(surface, std::vector<int>(mesh.face_count(), 6));
  REQUIRE(surface.topology().refinement_steps() == 1);
  const long n = 3;
  const fs::path dir = scratch_dir("tess-eval");
  std::ofstream queries(dir / "q.txt");
  std::vector<std::size_t> sample;
  for (std::size_t k = 0; k < soup.positions.size(); k += 7) {
    const TessellationParameter t = tessellation_parameter(k, n);
    queries << t.face << " " << t.u << "/" << t.denominator << " " << t.v << "/" << t.denominator << "\n";
    sample.push_back(k);
  }
  queries.close();
  const CliResult r = run_stencileval("--tables " + table.string() + " --mesh " + (kMeshes / "torus-3-5.obj").string() +
                                      " --batch " + (dir / "q.txt").string());
  REQUIRE(r.status == 0);
  std::istringstream lines(r.output);
  for (std::size_t k : sample) {
    Point p{};
    REQUIRE(static_cast<bool>(lines >> p[0] >> p[1] >> p[2]));
    const auto& q = soup.positions[k];
    INFO("vertex " << k);
    REQUIRE(distance(p, {q[0], q[1], q[2]}) < 1e-6);
  }
  // A batch file with no query is an error, not a silent success.
  std::ofstream(dir / "empty.txt") << "# nothing to ask\n\n";
  const CliResult empty = run_stencileval("--tables " + table.string() + " --mesh " + (kMeshes / "torus-3-5.obj").string() +
                                          " --batch " + (dir / "empty.txt").string());
  CHECK(empty.status == 1);
  CHECK(empty.output.find("no queries") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("bad tables and bad meshes get clear errors, and nothing is written", "[runtime][errors]") {
  const fs::path dir = scratch_dir("runtime-errors");
  const auto good = tables_for("nonpoly");
  const std::string cube = (kMeshes / "cube.obj").string();
  auto eval = [&](const std::string& tables, const std::string& mesh, const std::string& extra = "--face 0 --uv 1/2,1/2") {
    return run_stencileval("--tables " + tables + " --mesh " + mesh + " " + extra);
  };
  auto write = [&](const std::string& file, const std::string& text) {
    std::ofstream(dir / file) << text;
    return (dir / file).string();
  };
  // Tables: truncated, corrupt, not a table, missing.
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  CHECK(eval(write("short.sgs", bytes.substr(0, bytes.size() / 2)), cube).output.find("checksum mismatch") != std::string::npos);
  std::string flipped = bytes;
  flipped[bytes.size() / 3] ^= 0x20;
  CHECK(eval(write("flipped.sgs", flipped), cube).output.find("checksum mismatch") != std::string::npos);
  CHECK(eval(write("text.sgs", "hello, this is not a table at all"), cube).output.find("bad magic") != std::string::npos);
  CHECK(eval((dir / "none.sgs").string(), cube).output.find("no such table file") != std::string::npos);
  // Meshes.
  const std::string quadv = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  // Two quads that meet only at a vertex: as in OpenSubdiv, a corner of both
  // (the surface passes through it); a vertex in no face is ignored.
  const std::string bowtie = quadv + "v 2 1 0\nv 2 2 0\nv 1 2 0\nv 5 5 5\nf 1 2 3 4\nf 3 5 6 7\n";
  const CliResult shared = eval(good.string(), write("bowtie.obj", bowtie), "--face 1 --uv 0,0 --boundary edge-only");
  CHECK(shared.status == 0);
  CHECK(shared.output.find("1 1 0") != std::string::npos);
  // An edge in three faces (a book of three pages): as in OpenSubdiv,
  // infinitely sharp, its ends corners of every page.
  const std::string book = quadv + "v 0 -1 0\nv 1 -1 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\nf 2 1 5 6\nf 1 2 7 8\n";
  const CliResult page = eval(good.string(), write("book.obj", book), "--face 2 --uv 1/2,0 --boundary edge-only");
  CHECK(page.status == 0);
  CHECK(page.output.find("\n0.5 0 ") != std::string::npos);  // the edge's midpoint (its crease curve is the edge)
  // A mesh folded onto itself along an edge: the edge (in three faces) is
  // cut, which leaves a pillow of two faces whose vertices are in two faces
  // each: refused, naming one.
  CHECK(eval(good.string(), write("fold.obj", quadv + "v 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\nf 2 3 6 5\n")).output.find("has valence 2") !=
        std::string::npos);
  CHECK(eval(good.string(), write("badindex.obj", quadv + "f 1 2 3 9\n")).output.find("badindex.obj:5: face index 9") != std::string::npos);
  CHECK(eval(good.string(), cube, "--face 6 --uv 0,0").output.find("face 6 does not exist") != std::string::npos);
  // A rational no stored rate holds, and a decimal: within a bound, said on the line before the point.
  const CliResult approximate = eval(good.string(), cube, "--face 0 --uv 1/29,0");
  CHECK(approximate.status == 0);
  CHECK(approximate.output.find("within") != std::string::npos);
  CHECK(approximate.output.find("of the exact one (bound; tolerance") != std::string::npos);
  CHECK(eval(good.string(), cube, "--face 0 --uv 0.3,0.7 --tolerance 0").output.find("--tolerance must be a positive finite number") !=
        std::string::npos);
  CHECK(eval(good.string(), cube, "--face 0 --uv 3/2,0").output.find("lies outside face 0 (its domain is 0 <= u, v <= 1)") != std::string::npos);
  // A valence the tables lack: name the vertex and the stencilgen call.
  const fs::path only5 = dir / "only5";
  REQUIRE(run_stencilgen("--scheme nonpoly --valence 5 --n 4 --out " + only5.string() + " -q").status == 0);
  const CliResult missing = eval((only5 / "nonpoly").string(), cube);
  CHECK(missing.status == 1);
  CHECK(missing.output.find("vertex 0 has valence 3") != std::string::npos);
  CHECK(missing.output.find("stencilgen --scheme nonpoly --valence 3") != std::string::npos);
  // stenciltess: no output file on failure.
  const CliResult tess = run_stenciltess("--tables " + good.string() + " --mesh " + write("fold2.obj", quadv + "v 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\nf 2 3 6 5\n") +
                                         " --rate 4 --out " + (dir / "out.ply").string());
  CHECK(tess.status == 1);
  CHECK_FALSE(fs::exists(dir / "out.ply"));
  CHECK_FALSE(fs::exists(dir / "out.ply.partial"));
  fs::remove_all(dir);
}

TEST_CASE("stenciltess writes closed meshes in every rate mode", "[runtime][tessellation]") {
  const fs::path dir = scratch_dir("tess-modes");
  const auto table = tables_for("nonpoly").string();
  const std::string torus = (kMeshes / "torus-3-5.obj").string();
  {
    std::ofstream rates(dir / "rates.txt");
    for (int f = 0; f < 96; ++f) rates << 1 + (f * 7) % 24 << "\n";
  }
  for (const std::string& mode : {std::string("--rate 5"), "--rates " + (dir / "rates.txt").string(),
                                  std::string("--tolerance 0.002"), std::string("--camera 0,-6,3,0,0,0 --pixels 5")}) {
    const fs::path out = dir / "t.obj";
    const CliResult r = run_stenciltess("--tables " + table + " --mesh " + torus + " " + mode + " --out " + out.string());
    INFO(mode << "\n" << r.output);
    REQUIRE(r.status == 0);
    const Mesh m = read_obj(out.string());
    const auto directed = directed_edges(m);
    for (const auto& [e, count] : directed) {
      REQUIRE(count == 1);
      REQUIRE(directed.count({e.second, e.first}) == 1);
    }
    REQUIRE(static_cast<long>(m.vertex_count()) - static_cast<long>(directed.size() / 2) + static_cast<long>(m.face_count()) == 0);
  }
  // Binary PLY: header and size match the counts.
  const fs::path ply = dir / "t.ply";
  REQUIRE(run_stenciltess("--tables " + table + " --mesh " + torus + " --rate 4 --out " + ply.string()).status == 0);
  std::ifstream in(ply, std::ios::binary);
  std::string header, line;
  while (std::getline(in, line) && line != "end_header") header += line + "\n";
  CHECK(header.find("format binary_little_endian 1.0") != std::string::npos);
  CHECK(header.find("element vertex ") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("the runtime loads the exact JSON tables too, with the same stencils as the binary file", "[runtime][tables]") {
  const fs::path dir = scratch_dir("json-tables");
  REQUIRE(run_stencilgen("--scheme nonpoly --valence 3,5 --n 1-6 --out " + dir.string() + " -q").status == 0);
  const fs::path json_dir = dir / "nonpoly";
  fs::rename(json_dir / "nonpoly.sgs", dir / "nonpoly.sgs");
  const QuadTables binary = QuadTables::load_binary((dir / "nonpoly.sgs").string());
  const QuadTables exact = QuadTables::load_json_directory(json_dir.string(), binary.scheme_hash());
  // Tables::load reads such a directory too, with the scheme's name from the tables.
  const auto loaded = Tables::load(json_dir.string());
  CHECK(loaded->scheme() == "nonpoly");
  CHECK(loaded->family() == SchemeFamily::Quad);
  REQUIRE(exact.rates() == binary.rates());
  REQUIRE(exact.valences() == binary.valences());
  REQUIRE(exact.face_corner() == binary.face_corner());
  REQUIRE(exact.vertex_rule(5)->edge == binary.vertex_rule(5)->edge);
  for (int v : {3, 4, 5})
    for (int n = 1; n <= 6; ++n) {
      std::vector<double> a(static_cast<std::size_t>(QuadTables::points(v))), b(a.size());
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          exact.centre_stencil(v, n, i, j, a.data());
          binary.centre_stencil(v, n, i, j, b.data());
          for (std::size_t h = 0; h < a.size(); ++h) REQUIRE(a[h] == Approx(b[h]).epsilon(1e-15).margin(1e-300));
          exact.node_stencil(v, n, i, j, a.data());
          binary.node_stencil(v, n, i, j, b.data());
          for (std::size_t h = 0; h < a.size(); ++h) REQUIRE(a[h] == Approx(b[h]).epsilon(1e-15).margin(1e-300));
        }
    }
  // The boundary sectors, from descent.json, expand to the binary file's stencils.
  REQUIRE(exact.sectors() == binary.sectors());
  // creases of 1, 3..5 faces, corners of 2..5, darts 3..5, cone points 3..5
  REQUIRE(exact.sectors().size() == (1 + 3 + 4 + 5) + (2 + 3 + 4 + 5) + (3 + 4 + 5) + 3);
  for (const SectorKey& key : exact.sectors()) {
    const int kind = sector_kind(key);
    std::vector<double> a(static_cast<std::size_t>(key.points())), b(a.size());
    for (int n : {1, 6})
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          exact.node_stencil(kind, n, i, j, a.data());
          binary.node_stencil(kind, n, i, j, b.data());
          for (std::size_t h = 0; h < a.size(); ++h) REQUIRE(a[h] == Approx(b[h]).epsilon(1e-15).margin(1e-300));
        }
  }
  CHECK_THROWS_WITH(QuadTables::load_json_directory(json_dir.string(), binary.scheme_hash() + 1), Catch::Contains("different scheme"));
  // descent.json: the JSON tables evaluate at any parameter as the binary file does.
  {
    const Mesh cube = read_obj((kMeshes / "cube.obj").string());
    const Surface from_json = surface_of(loaded, cube), from_binary = surface_of(Tables::load((dir / "nonpoly.sgs").string()), cube);
    for (std::size_t f = 0; f < cube.face_count(); ++f) {
      const Evaluation a = from_json.evaluate(f, 0.3, 1.0 / 7, 1e-9), b = from_binary.evaluate(f, 0.3, 1.0 / 7, 1e-9);
      REQUIRE(distance(a.point, b.point) < 1e-14);
      REQUIRE(a.bound == Approx(b.bound).epsilon(1e-9));
    }
  }
  fs::remove(json_dir / "v5" / "n4.json");
  CHECK_THROWS_WITH(Tables::load(json_dir.string()), Catch::Contains("different set of rates"));
  fs::remove_all(dir);
}

TEST_CASE("meshes with triangles get the scheme's polygon step, and Catmull-Clark then equals OpenSubdiv", "[runtime][opensubdiv]") {
  const auto cc = Tables::load(tables_for("catmull-clark").string());
  const Mesh m = prism();
  const Surface surface = surface_of(cc, m);
  CHECK(surface.topology().refinement_steps() == 2);  // polygon step, then isolation of the triangles' centres
  bfr_reference::BfrLimit reference(m.positions, m.face_sizes, m.face_vertices);
  const double size = extent(m);
  for (std::size_t f = 0; f < 5; ++f) {
    // A triangle's (u, v) is Bfr's: three sub-face tiles [a, a + 1/2] x [b, b + 1/2]
    // at (a, b) = (0,0), (1,0), (0,1); a quad's is [0,1]^2.
    const FaceDomain domain = surface.topology().domain(f);
    const int tiles = domain.kind == FaceDomain::Kind::Quad ? 1 : domain.corners;
    for (int s = 0; s < tiles; ++s)
      for (long n : {1L, 2L, 4L, 5L, 8L})
        for (long j = 0; j <= n; ++j)
          for (long i = 0; i <= n; ++i) {
            ExactParameter at = grid(i, j, n);
            if (tiles > 1)
              at = {add(Fraction{s % domain.u_tiles, 1}, Fraction::make(i, 2 * n)), add(Fraction{s / domain.u_tiles, 1}, Fraction::make(j, 2 * n))};
            const Point ours = surface.evaluate(f, at);
            const auto ref = reference.evaluate(static_cast<int>(f), at.u.to_double(), at.v.to_double());
            INFO("face " << f << " at " << at.str());
            REQUIRE(distance(ours, ref) / size < 1e-12);
          }
  }
  // The tessellation of the mixed mesh is closed, and a sphere.
  const PolygonSoup soup = tessellate(surface, {3, 7, 12, 5, 24});
  const auto directed = directed_edges(soup);
  for (const auto& [e, count] : directed) REQUIRE((count == 1 && directed.count({e.second, e.first}) == 1));
  CHECK(static_cast<long>(soup.positions.size()) - static_cast<long>(directed.size() / 2) +
            static_cast<long>(soup.quads.size() + soup.triangles.size()) == 2);
}
