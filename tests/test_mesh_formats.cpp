// OFF and PLY control meshes (read_off, read_ply_mesh, and the tools through
// read_mesh): every bundled OBJ mesh written as OFF and PLY by the test's own
// conversion reads as the same mesh, the variants real writers produce read
// alike, and each way a file can be wrong is refused with a message naming
// its line, item or face.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <array>
#include <string>
#include <vector>

#include "cli.hpp"
#include "runtime_api.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/mesh_io.hpp"

using namespace stencil_runtime;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(STENCIL_SOURCE_DIR) / "meshes";

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// An OBJ file's `v` and `f` lines as OFF, written here without the runtime:
// `header` replaces the keyword line (and may hold the counts), `vertex_tail`
// and `face_tail` are appended to every vertex and face line.
std::string obj_to_off(const fs::path& obj, const std::string& keyword = "OFF\n", const std::string& vertex_tail = "",
                       const std::string& face_tail = "") {
  std::ifstream in(obj);
  std::vector<std::string> vertices, faces;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      std::string x, y, z;
      words >> x >> y >> z;
      vertices.push_back(x + " " + y + " " + z + vertex_tail);
    } else if (tag == "f") {
      std::vector<long> index;
      for (std::string item; words >> item;) index.push_back(std::stol(item.substr(0, item.find('/'))) - 1);
      std::string face = std::to_string(index.size());
      for (const long i : index) face += " " + std::to_string(i);
      faces.push_back(face + face_tail);
    }
  }
  std::string out = keyword;
  if (keyword.find_first_of("0123456789") == std::string::npos)
    out += std::to_string(vertices.size()) + " " + std::to_string(faces.size()) + " 0\n";
  for (const std::string& v : vertices) out += v + "\n";
  for (const std::string& f : faces) out += f + "\n";
  return out;
}

// An OBJ file's vertices and faces (indices from 0), read here without the runtime.
struct Plain {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<long>> faces;
};
Plain plain_of(const fs::path& obj) {
  Plain out;
  std::ifstream in(obj);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      std::array<double, 3> p{};
      words >> p[0] >> p[1] >> p[2];
      out.vertices.push_back(p);
    } else if (tag == "f") {
      std::vector<long> face;
      for (std::string item; words >> item;) face.push_back(std::stol(item.substr(0, item.find('/'))) - 1);
      out.faces.push_back(face);
    }
  }
  return out;
}

// The bytes of `value` in the given byte order.
template <class T>
std::string bytes_of(T value, bool big) {
  std::string raw(reinterpret_cast<const char*>(&value), sizeof value);
  if (big != (std::endian::native == std::endian::big)) std::reverse(raw.begin(), raw.end());
  return raw;
}

// The mesh as PLY: "ascii", "binary_little_endian" or "binary_big_endian",
// with a uchar before x on every vertex and a uchar after every face's list
// (list uchar int in little-endian and text, list ushort uint in big-endian).
std::string plain_to_ply(const Plain& m, const std::string& format) {
  const bool text = format == "ascii", big = format == "binary_big_endian";
  std::string out = "ply\nformat " + format + " 1.0\ncomment by the test\nelement vertex " + std::to_string(m.vertices.size()) +
                    "\nproperty uchar quality\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(m.faces.size()) + "\nproperty list " + (big ? "ushort uint" : "uchar int") +
                    " vertex_indices\nproperty uchar red\nend_header\n";
  for (const auto& p : m.vertices) {
    if (text) {
      std::ostringstream line;
      line.precision(17);
      line << "7 " << p[0] << " " << p[1] << " " << p[2] << "\n";
      out += line.str();
    } else {
      out += '\7';
      for (const double x : p) out += bytes_of(x, big);
    }
  }
  for (const auto& f : m.faces) {
    if (text) {
      out += std::to_string(f.size());
      for (const long i : f) out += " " + std::to_string(i);
      out += " 200\n";
    } else {
      out += big ? bytes_of(static_cast<std::uint16_t>(f.size()), true) : std::string(1, static_cast<char>(f.size()));
      for (const long i : f) out += big ? bytes_of(static_cast<std::uint32_t>(i), true) : bytes_of(static_cast<std::int32_t>(i), false);
      out += '\310';
    }
  }
  return out;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  return a.positions == b.positions && a.face_sizes == b.face_sizes && a.face_vertices == b.face_vertices;
}

}  // namespace

TEST_CASE("OFF meshes read as the OBJ meshes they were written from, in the variants writers use", "[runtime][mesh]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-off-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(kMeshes)) {
    if (entry.path().extension() != ".obj") continue;
    INFO(entry.path().filename().string());
    const Mesh obj = read_obj(entry.path().string());
    const fs::path off = dir / (entry.path().stem().string() + ".off");
    write_file(off, obj_to_off(entry.path()));
    CHECK(same_mesh(read_off(off.string()), obj));
    CHECK(same_mesh(read_mesh(off.string()), obj));  // by its extension
  }
  // The variants, on the chess piece: a colour (and a comment glued to it) on
  // every vertex and face, the counts on the keyword's line, CRLF ends and a
  // byte-order mark, comments and blank lines between the counts and the
  // vertices, an upper-case extension.
  const fs::path chess = kMeshes / "chess-piece.obj";
  const Mesh expected = read_obj(chess.string());
  std::string counts_on_keyword = obj_to_off(chess);
  counts_on_keyword.replace(0, counts_on_keyword.find('\n', 4) + 1,
                            "OFF " + std::to_string(expected.positions.size()) + " " + std::to_string(expected.face_sizes.size()) + " 0\n");
  std::string crlf;
  for (const char c : obj_to_off(chess, "# written by a test\n\nNOFF\n")) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::string spaced = obj_to_off(chess);
  spaced.insert(spaced.find('\n', 4) + 1, "\n# the vertices\n   \n");
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"colours.off", obj_to_off(chess, "COFF\n", " 0.9 0.1 0.1 1#red", " 255 0 0")},
      {"keyword.off", counts_on_keyword},
      {"crlf.off", "\xEF\xBB\xBF" + crlf},
      {"spaced.OFF", spaced},
  };
  for (const auto& [name, text] : variants) {
    INFO(name);
    write_file(dir / name, text);
    Mesh m;
    REQUIRE_NOTHROW(m = read_mesh((dir / name).string()));
    CHECK(same_mesh(m, expected));
  }
  fs::remove_all(dir);
}

TEST_CASE("bad OFF files are refused with the line and what is wrong", "[runtime][mesh][robustness]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-off-bad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string tetra_vertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::string tetra_faces = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string tetra = "OFF\n4 4 6\n" + tetra_vertices + tetra_faces;
  write_file(dir / "tetra.off", tetra);
  REQUIRE(read_off((dir / "tetra.off").string()).face_sizes.size() == 4);
  const auto refused = [&](const std::string& text, const std::string& message) {
    write_file(dir / "bad.off", text);
    INFO(text);
    try {
      read_off((dir / "bad.off").string());
      FAIL("read: " + message);
    } catch (const LoadError& e) {
      CHECK_THAT(e.what(), Catch::Contains(message));
    }
  };
  refused("", "the file is empty");
  refused("v 0 0 0\n", "bad.off:1: not an OFF file");
  refused("4OFF\n4 4 6\n", "bad.off:1: '4OFF': vertices of 4 or n coordinates are not read");
  refused("OFF BINARY\n", "bad.off:1: binary OFF files are not read");
  refused("OFF\n", "ends before its counts");
  refused("OFF\n4 4 6 7\n", "bad.off:2: expected the counts");
  refused("OFF\n-4 4 6\n", "bad.off:2: the vertex count '-4'");
  refused("OFF\n4 x 6\n", "bad.off:2: the face count 'x'");
  refused("OFF\n4000000 4 6\n" + tetra_vertices, "bad.off:2: 4000000 vertices and 4 faces cannot fit in a file of");
  // One line of the whole tetrahedron replaced: vertex lines are 3..6, face lines 7..10.
  const auto with_line = [&](int number, const std::string& line) {
    std::istringstream in(tetra);
    std::string out, l;
    for (int k = 1; std::getline(in, l); ++k) out += (k == number ? line : l) + "\n";
    return out;
  };
  refused(with_line(3, "0 0"), "bad.off:3: a vertex needs three numbers");
  refused(with_line(3, "0 0 nan"), "bad.off:3: coordinate 'nan' is not a finite number");
  refused(with_line(4, "0 0 1e38"), "bad.off:4: coordinate '1e38'");
  refused(with_line(5, "0 0 0 red"), "bad.off:5: a vertex is x y z");
  refused(with_line(7, "2 0 1"), "bad.off:7: a face needs at least three vertices, got 2");
  refused(with_line(8, "3 0 1 4"), "bad.off:8: face index 4 refers to no vertex (OFF counts them from 0; the file has 4)");
  refused(with_line(8, "3 0 1 -1"), "bad.off:8: face index -1 refers to no vertex");
  refused(with_line(9, "4 0 1 2"), "bad.off:9: the face has 4 vertices but the line lists 3");
  refused(with_line(9, "3 0 1 2.5"), "bad.off:9: bad face index '2.5'");
  refused(with_line(10, "3 1 2 3 1 1 1 1 1"), "bad.off:10: after the face's 3 indices, at most a colour");
  refused(with_line(10, "3 1 2 3 red"), "bad.off:10: after the face's indices, a colour as numbers");
  // Cut short, with the bytes the counts need (a long comment): truncated; without them: refused at the counts.
  const std::string padding = "# " + std::string(80, '-') + "\n";
  refused("OFF\n4 4 6\n" + padding + "0 0 0\n", "truncated: the file ends after 1 of 4 vertices");
  refused("OFF\n4 4 6\n" + padding + tetra_vertices + "3 0 2 1\n", "truncated: the file ends after 1 of 4 faces");
  refused("OFF\n4 4 6\n0 0 0\n", "bad.off:2: 4 vertices and 4 faces cannot fit in a file of 16 bytes");
  refused(tetra + "3 0 1 2\n", "bad.off:11: more lines than the 4 vertices and 4 faces the counts declare");
  refused("OFF\n4 0 0\n" + tetra_vertices, "bad.off: no faces");
  // An OFF file named .obj is read as OBJ, which finds nothing in it: the message says what it is.
  write_file(dir / "tetra.obj", tetra);
  CHECK_THROWS_WITH(read_mesh((dir / "tetra.obj").string()), Catch::Contains("no faces (it starts like an OFF file: name it .off"));
  write_file(dir / "tetra-ply.obj", "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
  CHECK_THROWS_WITH(read_mesh((dir / "tetra-ply.obj").string()), Catch::Contains("it is a PLY file"));
  fs::remove_all(dir);
}

TEST_CASE("the tools read OFF control meshes and refuse bad ones with nothing written", "[runtime][mesh][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-off-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").string();
  write_file(dir / "cube.off", obj_to_off(kMeshes / "cube.obj"));
  const CliResult off = run_stencileval("--tables " + tables + " --mesh " + (dir / "cube.off").string() + " --face 3 --uv 1/4,3/4 --normal");
  const CliResult obj = run_stencileval("--tables " + tables + " --mesh " + (kMeshes / "cube.obj").string() + " --face 3 --uv 1/4,3/4 --normal");
  INFO(off.output);
  CHECK(off.status == 0);
  CHECK(off.output == obj.output);
  const std::string out = (dir / "cube.ply").string();
  CHECK(run_stenciltess("--tables " + tables + " --mesh " + (dir / "cube.off").string() + " --rate 4 --out " + out).status == 0);
  CHECK(fs::exists(out));
  fs::remove(out);
  write_file(dir / "cut.off", "OFF\n8 6 0\n0 0 0\n");
  const CliResult bad = run_stenciltess("--tables " + tables + " --mesh " + (dir / "cut.off").string() + " --rate 4 --out " + out);
  CHECK(bad.status == 1);
  CHECK_THAT(bad.output, Catch::Contains("cut.off:2: 8 vertices and 6 faces cannot fit in a file of 16 bytes"));
  CHECK_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

TEST_CASE("PLY meshes in text and both byte orders read as the OBJ meshes they were written from", "[runtime][mesh]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-ply-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(kMeshes)) {
    if (entry.path().extension() != ".obj") continue;
    const Mesh obj = read_obj(entry.path().string());
    const Plain plain = plain_of(entry.path());
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
      INFO(entry.path().filename().string() << " as " << format);
      const fs::path ply = dir / (entry.path().stem().string() + ".ply");
      write_file(ply, plain_to_ply(plain, format));
      Mesh m;
      REQUIRE_NOTHROW(m = read_mesh(ply.string()));
      CHECK(same_mesh(m, obj));
    }
  }
  fs::remove_all(dir);
}

TEST_CASE("bad PLY meshes are refused with the line, item or face", "[runtime][mesh][robustness]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-ply-bad-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Plain tetra;
  tetra.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const auto refused = [&](const std::string& text, const std::string& message) {
    write_file(dir / "bad.ply", text);
    try {
      read_mesh((dir / "bad.ply").string());
      FAIL("read: " + message);
    } catch (const LoadError& e) {
      CHECK_THAT(e.what(), Catch::Contains(message));
    }
  };
  const std::string text = plain_to_ply(tetra, "ascii");
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string s = text;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  // Header lines 1-12, vertices 13-16, faces 17-20.
  refused(text.substr(0, text.find("3 0 2 1 200")).replace(text.find("element face 4"), std::string("element face 4\nproperty list uchar int vertex_indices\nproperty uchar red\n").size(), ""),
          "no faces (a PLY control mesh needs an element 'face' with a list 'vertex_indices')");
  Plain no_faces = tetra;
  no_faces.faces.clear();
  refused(plain_to_ply(no_faces, "ascii"), "bad.ply: no faces");
  refused(with("3 0 2 1 200", "2 0 2 200"), "face 0 (numbered from 0) has 2 vertices; a face needs at least three");
  refused(with("3 0 1 3 200", "3 0 1 4 200"), "face 1 (numbered from 0): vertex index 4 refers to no vertex (PLY counts them from 0; the file has 4)");
  refused(with("3 0 1 3 200", "3 0 1 -1 200"), "vertex index -1 refers to no vertex");
  refused(with("3 0 3 2 200", "3 0 3 2"), "bad.ply:19: face 3: fewer values than its properties declare");
  refused(with("3 0 3 2 200", "3 0 3 2 200 1"), "bad.ply:19: face 3: more values than its properties declare");
  refused(with("3 0 3 2 200", "3 0 3 x 200"), "bad.ply:19: 'x' is not a vertex index");
  refused(with("3 0 3 2 200", "3 0 3 2.5 200"), "bad.ply:19: '2.5' is not a vertex index");
  refused(with("3 1 2 3 200\n", ""), "truncated: the file ends after 3 of the 4 lines of the elements after the points (face");
  refused(text + "3 1 2 3 200\n", "bad.ply:21: more lines than the header's 4 points and later elements declare");
  refused(with("property list uchar int vertex_indices", "property list uchar float vertex_indices"),
          "bad.ply:10: a face's vertex indices must be integers");
  // Binary: a negative signed index, an index past the vertices, and a face cut short.
  std::string binary = plain_to_ply(tetra, "binary_little_endian");
  const std::size_t last_face = binary.size() - (1 + 3 * 4 + 1);
  std::string negative = binary;
  negative.replace(last_face + 1, 4, bytes_of(std::int32_t{-1}, false));
  refused(negative, "face 3 (numbered from 0): vertex index -1 refers to no vertex");
  std::string beyond = plain_to_ply(tetra, "binary_big_endian");
  beyond.replace(beyond.size() - 5, 4, bytes_of(std::uint32_t{70000}, true));
  refused(beyond, "face 3 (numbered from 0): vertex index 70000 refers to no vertex");
  refused(binary.substr(0, binary.size() - 2), "truncated: the file ends within face 4 of 4 (binary)");
  fs::remove_all(dir);
}

TEST_CASE("the tools read PLY control meshes, the tessellations they write among them", "[runtime][mesh][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("stencil-ply-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string tables = generated_table("catmull-clark", "--valence 3-8 --n 4", "sgs").string();
  write_file(dir / "cube.ply", plain_to_ply(plain_of(kMeshes / "cube.obj"), "binary_big_endian"));
  const CliResult ply = run_stencileval("--tables " + tables + " --mesh " + (dir / "cube.ply").string() + " --face 3 --uv 1/4,3/4 --normal");
  const CliResult obj = run_stencileval("--tables " + tables + " --mesh " + (kMeshes / "cube.obj").string() + " --face 3 --uv 1/4,3/4 --normal");
  INFO(ply.output);
  CHECK(ply.status == 0);
  CHECK(ply.output == obj.output);
  // stenciltess's own PLY (binary, float coordinates, quads) is a control mesh too: the same mesh as its OBJ.
  const std::string tess_ply = (dir / "tess.ply").string(), tess_obj = (dir / "tess.obj").string();
  REQUIRE(run_stenciltess("--tables " + tables + " --mesh " + (kMeshes / "cube.obj").string() + " --rate 2 --out " + tess_ply).status == 0);
  REQUIRE(run_stenciltess("--tables " + tables + " --mesh " + (kMeshes / "cube.obj").string() + " --rate 2 --out " + tess_obj).status == 0);
  const Mesh from_ply = read_mesh(tess_ply), from_obj = read_mesh(tess_obj);
  CHECK(from_ply.face_sizes == from_obj.face_sizes);
  CHECK(from_ply.face_vertices == from_obj.face_vertices);
  REQUIRE(from_ply.positions.size() == from_obj.positions.size());
  for (std::size_t i = 0; i < from_ply.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) CHECK(from_ply.positions[i][k] == Approx(from_obj.positions[i][k]).margin(1e-7));
  fs::remove_all(dir);
}
