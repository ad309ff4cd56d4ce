// OpenSubdiv's OBJ tag lines: read with their line numbers, checked against
// the mesh, and refused where the runtime cannot honour them (creases,
// corners, smooth triangles), so that a tagged mesh is never evaluated as if
// its tags were absent (holes are honoured: test_holes.cpp). Tags without effect on a closed smooth mesh
// leave the surface exactly as the untagged file gives it.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.hpp"
#include "runtime_api.hpp"
#include "runtime_checks.hpp"

using namespace stencil_runtime;
using namespace test_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

std::string cube_text() {
  std::ifstream in(kMeshes / "cube.obj");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

long line_count(const std::string& text) {
  long n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

// The cube with `tags` appended; returns the path.
fs::path tagged_cube(const fs::path& dir, const std::string& name, const std::string& tags) {
  const fs::path path = dir / (name + ".obj");
  std::ofstream(path) << cube_text() << tags;
  return path;
}

}  // namespace

TEST_CASE("OBJ tags are read with their lines and checked against the mesh", "[runtime][tags]") {
  const fs::path dir = scratch_dir("obj-tags");
  const long first = line_count(cube_text()) + 1;  // the first appended line
  const Mesh m = read_obj(tagged_cube(dir, "all",
                                      "t crease 3/2/0 0 1 3 2.5 0.5\n"
                                      "t corner 1/1/0 7 4\n"
                                      "t hole 2/0/0 1 5\n"
                                      "t interpolateboundary 1/0/0 1\n"
                                      "t creasemethod 0/0/1 chaikin\n"
                                      "t smoothtriangles 0/0/1 smooth\n"
                                      "t somethingnew 1/0 3\n")
                              .string());
  REQUIRE(m.tags.creases.size() == 2);  // the chain 0-1-3: two edges, one sharpness each
  CHECK(m.tags.creases[0].a == 0);
  CHECK(m.tags.creases[0].b == 1);
  CHECK(m.tags.creases[0].sharpness == 2.5);
  CHECK(m.tags.creases[1].a == 1);
  CHECK(m.tags.creases[1].b == 3);
  CHECK(m.tags.creases[1].sharpness == 0.5);
  CHECK(m.tags.creases[1].line == first);
  REQUIRE(m.tags.corners.size() == 1);
  CHECK(m.tags.corners[0].vertex == 7);
  CHECK(m.tags.corners[0].sharpness == 4);
  CHECK(m.tags.corners[0].line == first + 1);
  REQUIRE(m.tags.holes.size() == 2);
  CHECK(m.tags.holes[1].face == 5);
  CHECK(m.tags.boundary == BoundaryInterpolation::EdgeAndCorner);
  CHECK(m.tags.chaikin_creases);
  CHECK(m.tags.smooth_triangles);
  REQUIRE(m.warnings.size() == 1);
  CHECK_THAT(m.warnings[0], Catch::Contains(":" + std::to_string(first + 6) + ": warning: unknown tag `somethingnew`"));

  // Malformed tags and tags naming what is not there: errors with the line.
  const std::pair<const char*, const char*> bad[] = {
      {"t crease 2/1/0 0 6 1\n", "not joined by an edge"},  // 0-6 is a diagonal of a cube face
      {"t crease 2/1/0 0 1\n", "1 numbers announced, 0 given"},
      {"t crease 2/1/0 0 1 -1\n", "negative"},
      {"t crease 3/2/0 0 1 3 1 2 3\n", "more arguments"},
      {"t crease 3/3/0 0 1 3 1 2 3\n", "one sharpness or one per edge"},
      {"t corner 1/1/0 8 1\n", "refers to vertex 8, but the mesh has 8"},
      {"t hole 1/0/0 6\n", "refers to face 6, but the mesh has 6"},
      {"t hole 1/0/0 -1\n", "negative"},
      {"t interpolateboundary 1/0/0 3\n", "interpolateboundary"},
      {"t creasemethod 0/0/1 sharp\n", "normal or chaikin"},
      {"t crease a/1/0 0 1 1\n", "argument count"},
      {"t crease 2/nan/0 0 1 1\n", "argument count"},
      {"t corner 1/1/0 3 nan\n", "not a finite number"},
      {"t\n", "needs a name"},
  };
  for (const auto& [tag, message] : bad) {
    INFO(tag);
    const fs::path path = tagged_cube(dir, "bad", tag);
    CHECK_THROWS_WITH(read_obj(path.string()), Catch::Contains(path.string() + ":" + std::to_string(first)) &&
                                                   Catch::Contains(message));
  }
  fs::remove_all(dir);
}

TEST_CASE("tags the runtime cannot honour are refused, tags without effect change nothing", "[runtime][tags]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").string());
  const fs::path dir = scratch_dir("obj-tags-use");
  // A sharp vertex on no sharp edge is a cone point: it stays where its control vertex is (OpenSubdiv's corner rule
  // holds it at every step), the tool evaluates it and says it has no normal; tables without cone sectors (a
  // descent.json of version 3, from before them) are refused naming the vertex and the command that covers it.
  {
    const fs::path tables_dir = generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").parent_path();
    for (const char* tag : {"t corner 1/1/0 3 10\n", "t corner 1/1/0 3 12.5\n"}) {
      INFO(tag);
      const fs::path path = tagged_cube(dir, "cone", tag);
      const CliResult r = run_stencileval("--tables " + tables_dir.string() + " --mesh " + path.string() + " --face 1 --uv 0,1");
      CHECK(r.status == 0);
      CHECK_THAT(r.output, Catch::Contains("\n-0.5 0.5 0.5\n"));  // face 1 = (1, 5, 7, 3): vertex 3 at (0, 1)
      const CliResult n = run_stencileval("--tables " + tables_dir.string() + " --mesh " + path.string() + " --face 1 --uv 0,1 --normal");
      CHECK(n.status == 1);
      CHECK_THAT(n.output, Catch::Contains("cone point has no tangent plane"));
    }
    const fs::path old = dir / "tables-without-cones";
    fs::copy(tables_dir, old, fs::copy_options::recursive);
    for (const auto& e : fs::directory_iterator(old))
      if (e.path().extension() == ".sgs") fs::remove(e.path());  // the exact JSON tables alone
    nlohmann::ordered_json descent = nlohmann::ordered_json::parse(std::ifstream(old / "descent.json"));
    nlohmann::ordered_json kept = nlohmann::ordered_json::array();
    for (const auto& s : descent["sectors"])
      if (s["kind"] != "cone") kept.push_back(s);
    REQUIRE(kept.size() < descent["sectors"].size());
    descent["sectors"] = kept;
    descent["version"] = 3;
    std::ofstream(old / "descent.json") << descent.dump();
    const auto without = Tables::load(old.string());
    const Mesh m = read_obj(tagged_cube(dir, "cone", "t corner 1/1/0 3 10\n").string());
    CHECK_THROWS_WITH(SurfaceTopology::create(without, m), Catch::Contains("vertex 3 is a cone point") &&
                                                               Catch::Contains("no patches for cone points") &&
                                                               Catch::Contains("regenerate them"));
    CHECK_NOTHROW(SurfaceTopology::create(tables, m));
  }
  // An infinitely sharp crease of one edge on Loop's tetrahedron: darts of
  // valence 3 at both ends, which the tables cover; a dart of valence 7 with
  // tables up to valence 6 is refused naming the vertex and the call that
  // covers it.
  {
    const auto loop = Tables::load(generated_table("loop", "--valence 3-8 --n 4", "sgt").string());
    std::ofstream(dir / "tet-crease.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                                             "t crease 2/1/0 0 1 11\n";
    CHECK_NOTHROW(SurfaceTopology::create(loop, read_obj((dir / "tet-crease.obj").string())));
    {
      std::ifstream in(kMeshes / "tri-torus.obj");
      std::ofstream out(dir / "torus-dart.obj");
      out << in.rdbuf() << "t crease 2/1/0 18 9 11\n";  // vertex 18 has valence 7, vertex 9 valence 6
    }
    const auto up_to_6 = Tables::load(generated_table("loop", "--valence 3-6 --n 4", "sgt").string());
    CHECK_THROWS_WITH(SurfaceTopology::create(up_to_6, read_obj((dir / "torus-dart.obj").string())),
                      Catch::Contains("vertex 18 ends an infinitely sharp crease (a dart) at valence 7") &&
                          Catch::Contains("--valence"));
    CHECK_NOTHROW(SurfaceTopology::create(loop, read_obj((dir / "torus-dart.obj").string())));
  }
  // Smooth triangles are Catmull-Clark's rule: refused, with the line, on nonpoly's mesh with triangles.
  {
    std::ofstream(dir / "tet.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                                      "t smoothtriangles 0/0/1 smooth\n";
    const auto nonpoly = Tables::load(generated_table("nonpoly", "--valence 3-8 --n 4", "sgs").string());
    CHECK_THROWS_WITH(SurfaceTopology::create(nonpoly, read_obj((dir / "tet.obj").string())),
                      Catch::Contains("tet.obj:9") && Catch::Contains("smoothtriangles") && Catch::Contains("nonpoly"));
    CHECK_NOTHROW(SurfaceTopology::create(tables, read_obj((dir / "tet.obj").string())));
  }
  // Without effect on a closed smooth mesh: the same surface, bit for bit.
  const Mesh plain = read_obj((kMeshes / "cube.obj").string());
  const Mesh tagged = read_obj(tagged_cube(dir, "inert",
                                           "t crease 2/1/0 0 1 0\nt corner 1/1/0 3 0\nt interpolateboundary 1/0/0 0\n"
                                           "t creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n")
                                   .string());
  const Surface a(SurfaceTopology::create(tables, plain), plain.positions);
  const Surface b(SurfaceTopology::create(tables, tagged), tagged.positions);
  for (std::size_t f = 0; f < plain.face_count(); ++f) CHECK(a.evaluate(f, grid(1, 3, 4)) == b.evaluate(f, grid(1, 3, 4)));
  fs::remove_all(dir);
}

TEST_CASE("semi-sharp crease and corner tags give the surface of the same features given in code", "[runtime][tags][creases]") {
  const auto tables = Tables::load(generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").string());
  const fs::path dir = scratch_dir("obj-tags-creases");
  for (bool chaikin : {false, true}) {
    const std::string method = chaikin ? "t creasemethod 0/0/1 chaikin\n" : "";
    const Mesh tagged = read_obj(tagged_cube(dir, "creased", "t crease 3/2/0 0 1 3 2.5 0.5\nt corner 1/1/0 6 1.5\n" + method).string());
    const Mesh plain = read_obj((kMeshes / "cube.obj").string());
    MeshFeatures features;
    features.edges = {{0, 1, 2.5}, {1, 3, 0.5}};
    features.vertices = {{6, 1.5}};
    features.chaikin = chaikin;
    const Surface from_tags(SurfaceTopology::create(tables, tagged), tagged.positions);
    const Surface from_code(SurfaceTopology::create(tables, plain.vertex_count(), plain.face_sizes, plain.face_vertices, {}, features),
                            plain.positions);
    const Surface smooth(SurfaceTopology::create(tables, plain), plain.positions);
    double moved = 0;
    for (std::size_t f = 0; f < plain.face_count(); ++f)
      for (long j = 0; j <= 4; ++j)
        for (long i = 0; i <= 4; ++i) {
          CHECK(from_tags.evaluate(f, grid(i, j, 4)) == from_code.evaluate(f, grid(i, j, 4)));
          moved = std::max(moved, distance(from_tags.evaluate(f, grid(i, j, 4)), smooth.evaluate(f, grid(i, j, 4))));
        }
    CHECK(moved > 1e-2);  // the tags are honoured, not ignored
    // stencileval reads the tags too.
    const CliResult r = run_stencileval("--tables " + generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").parent_path().string() +
                                        " --mesh " + (dir / "creased.obj").string() + " --face 0 --uv 1/4,0");
    REQUIRE(r.status == 0);
    const Point expected = from_code.evaluate(0, grid(1, 0, 4));
    double x = 0, y = 0, z = 0;
    std::istringstream out(r.output);
    std::string heading;
    std::getline(out, heading);  // "face 0 at (1/4,0): limit point of ..."
    out >> x >> y >> z;
    CHECK(distance({x, y, z}, expected) < 1e-12);
    // stenciltess too: its output is closed along the creases.
    const fs::path written = dir / "creased-out.obj";
    const CliResult t = run_stenciltess("--tables " + generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").parent_path().string() +
                                        " --mesh " + (dir / "creased.obj").string() + " --rate 4 --out " + written.string());
    REQUIRE(t.status == 0);
    const Mesh soup = read_obj(written.string());
    CHECK(soup.face_count() > 0);
    CHECK(euler_characteristic(soup) == 2);
    const auto directed = directed_edges(soup);
    for (const auto& [e, count] : directed) {
      INFO("output edge " << e.first << " -> " << e.second);
      CHECK(count == 1);
      CHECK(directed.count({e.second, e.first}) == 1);
    }
  }
}

TEST_CASE("write_obj keeps the tags, so that a written control mesh (stencilfit's output) is the same surface",
          "[runtime][tags]") {
  const fs::path dir = scratch_dir("obj-tags-round-trip");
  for (const std::string tags : {"t crease 3/2/0 0 1 3 2.5 0.1\nt corner 1/1/0 7 0.3\nt hole 2/0/0 1 5\n"
                                 "t interpolateboundary 1/0/0 1\nt creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n",
                                 "t interpolateboundary 1/0/0 0\n", "t interpolateboundary 1/0/0 2\n", ""}) {
    INFO(tags);
    const Mesh m = read_obj(tagged_cube(dir, "in", tags).string());
    write_obj(m, (dir / "out.obj").string());
    const Mesh back = read_obj((dir / "out.obj").string());
    REQUIRE(back.tags.creases.size() == m.tags.creases.size());
    for (std::size_t k = 0; k < m.tags.creases.size(); ++k) {
      CHECK(back.tags.creases[k].a == m.tags.creases[k].a);
      CHECK(back.tags.creases[k].b == m.tags.creases[k].b);
      CHECK(back.tags.creases[k].sharpness == m.tags.creases[k].sharpness);
    }
    REQUIRE(back.tags.corners.size() == m.tags.corners.size());
    for (std::size_t k = 0; k < m.tags.corners.size(); ++k) {
      CHECK(back.tags.corners[k].vertex == m.tags.corners[k].vertex);
      CHECK(back.tags.corners[k].sharpness == m.tags.corners[k].sharpness);
    }
    REQUIRE(back.tags.holes.size() == m.tags.holes.size());
    for (std::size_t k = 0; k < m.tags.holes.size(); ++k) CHECK(back.tags.holes[k].face == m.tags.holes[k].face);
    CHECK(back.tags.boundary == m.tags.boundary);
    CHECK(back.tags.chaikin_creases == m.tags.chaikin_creases);
    CHECK(back.tags.smooth_triangles == m.tags.smooth_triangles);
    CHECK(back.positions == m.positions);
    CHECK(back.face_vertices == m.face_vertices);
    CHECK(back.warnings.empty());
  }
  fs::remove_all(dir);
}
