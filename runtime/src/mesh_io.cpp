#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "stencil_runtime/mesh.hpp"

namespace stencil_runtime {

Mesh read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw MeshError(path + ": cannot open");
  Mesh mesh;
  std::string line;
  long number = 0;
  auto fail = [&](const std::string& what) { throw MeshError(path + ":" + std::to_string(number) + ": " + what); };
  while (std::getline(in, line)) {
    ++number;
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag)) continue;
    if (tag == "v") {
      std::array<double, 3> p{};
      if (!(ls >> p[0] >> p[1] >> p[2])) fail("a vertex needs three coordinates");
      mesh.positions.push_back(p);
    } else if (tag == "f") {
      int count = 0;
      std::string item;
      while (ls >> item) {
        long index = 0;
        try {
          std::size_t used = 0;
          index = std::stol(item, &used);
          if (used < item.size() && item[used] != '/') throw std::invalid_argument(item);
        } catch (const std::exception&) {
          fail("bad face index '" + item + "'");
        }
        const long n = static_cast<long>(mesh.positions.size());
        if (index < 0) index += n + 1;
        if (index < 1 || index > n) fail("face index " + item + " refers to no vertex defined so far");
        mesh.face_vertices.push_back(static_cast<int>(index - 1));
        ++count;
      }
      if (count < 3) fail("a face needs at least three vertices");
      mesh.face_sizes.push_back(count);
    }
  }
  if (mesh.face_sizes.empty()) throw MeshError(path + ": no faces");
  return mesh;
}

namespace {

void write_obj(const PolygonSoup& s, std::FILE* f) {
  for (const auto& p : s.positions) std::fprintf(f, "v %.9g %.9g %.9g\n", p[0], p[1], p[2]);
  for (const auto& q : s.quads) std::fprintf(f, "f %d %d %d %d\n", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1);
  for (const auto& t : s.triangles) std::fprintf(f, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
}

void write_ply(const PolygonSoup& s, std::FILE* f) {
  std::fprintf(f,
               "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\nproperty float y\n"
               "property float z\nelement face %zu\nproperty list uchar int vertex_indices\nend_header\n",
               s.positions.size(), s.quads.size() + s.triangles.size());
  std::fwrite(s.positions.data(), sizeof(float) * 3, s.positions.size(), f);
  for (const auto& q : s.quads) {
    const unsigned char n = 4;
    std::fwrite(&n, 1, 1, f);
    std::fwrite(q.data(), sizeof(int), 4, f);
  }
  for (const auto& t : s.triangles) {
    const unsigned char n = 3;
    std::fwrite(&n, 1, 1, f);
    std::fwrite(t.data(), sizeof(int), 3, f);
  }
}

}  // namespace

void write_polygons(const PolygonSoup& soup, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".obj" && ext != ".ply") throw MeshError(path + ": output must end in .obj or .ply");
  const std::string temp = path + ".partial";
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw MeshError(path + ": cannot write");
  if (ext == ".obj") write_obj(soup, f);
  else write_ply(soup, f);
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) {
    std::remove(temp.c_str());
    throw MeshError(path + ": write failed");
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::remove(temp.c_str());
    throw MeshError(path + ": cannot move the finished file into place: " + ec.message());
  }
}

}  // namespace stencil_runtime
