// Reading OFF meshes (Geomview's Object File Format, as CGAL, Meshlab and the
// Princeton shape benchmark write it): the keyword, the counts, one vertex a
// line, one face a line with its vertex count first, indices from 0.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "line_tokens.hpp"
#include "mesh_file.hpp"
#include "stencil_runtime/error.hpp"
#include "stencil_runtime/limits.hpp"
#include "stencil_runtime/mesh_io.hpp"

namespace stencil_runtime {

namespace {

// The words of a line before its comment, which starts at any '#' (CGAL's
// own data has `0 0#red` after a vertex).
std::vector<std::string_view> words_of(std::string_view line, std::size_t pos = 0) {
  line = line.substr(0, line.find('#'));
  return detail::split_words(line.substr(std::min(pos, line.size())));
}

using detail::real_number;
using detail::whole_number;

// The keyword's prefixes name what each vertex line holds besides x y z:
// ST texture coordinates, C a colour, N a normal; 4 (homogeneous) and n (any
// dimension) are other shapes of vertex, which a surface mesh is not.
struct Keyword {
  bool valid = false;
  bool homogeneous = false;  // 4OFF
  bool dimension = false;    // nOFF
};
Keyword parse_keyword(std::string_view word) {
  Keyword k;
  if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return k;
  std::string_view prefix = word.substr(0, word.size() - 3);
  for (const std::string_view p : {"ST", "C", "N", "4", "n"})
    if (prefix.substr(0, p.size()) == p) {
      if (p == "4") k.homogeneous = true;
      if (p == "n") k.dimension = true;
      prefix.remove_prefix(p.size());
    }
  k.valid = prefix.empty();
  return k;
}

}  // namespace

Mesh read_off(const std::string& path) {
  std::ifstream in = detail::open_mesh_file(path);
  Mesh mesh;
  mesh.source = path;
  long number = 0;
  const auto fail = [&](const std::string& what) { throw LoadError(path + ":" + std::to_string(number) + ": " + what); };
  const auto too_long = [&](const std::string& what) {
    ++number;
    fail(what);
  };
  // The smallest vertex line ("0 0 0\n") and face line ("3 0 1 2\n"): counts
  // that the file cannot hold are refused before anything is allocated.
  in.seekg(0, std::ios::end);
  const auto bytes = static_cast<unsigned long long>(std::max<std::streamoff>(0, in.tellg()));
  in.seekg(0);
  enum class Stage { Keyword, Counts, Vertices, Faces, Done } stage = Stage::Keyword;
  long long vertices = 0, faces = 0;
  std::string line;
  while (detail::next_line(*in.rdbuf(), line, too_long)) {
    ++number;
    std::size_t pos = 0;
    if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) pos = 3;  // a UTF-8 byte-order mark
    std::vector<std::string_view> words = words_of(line, pos);
    if (words.empty()) continue;  // blank, or a comment
    if (stage == Stage::Keyword) {
      const Keyword k = parse_keyword(words[0]);
      if (!k.valid) fail("not an OFF file: it must start with the keyword OFF (or COFF, NOFF, STOFF, ...), got " + quoted_excerpt(words[0]));
      if (k.homogeneous || k.dimension)
        fail(quoted_excerpt(words[0]) + ": vertices of 4 or n coordinates are not read (a control mesh's vertices are x y z)");
      words.erase(words.begin());
      if (!words.empty() && words[0] == "BINARY") fail("binary OFF files are not read (write it as text OFF or OBJ)");
      stage = Stage::Counts;
      if (words.empty()) continue;  // the counts on the next line, as usual; on this one, as some writers put them
    }
    if (stage == Stage::Counts) {
      if (words.size() != 2 && words.size() != 3)
        fail("expected the counts `vertices faces edges`, got " + std::to_string(words.size()) + " words");
      if (!whole_number(words[0], vertices) || vertices < 0 || vertices > static_cast<long long>(limits::kMaxMeshElements))
        fail("the vertex count " + quoted_excerpt(words[0]) + " is not a number from 0 to 2^30");
      if (!whole_number(words[1], faces) || faces < 0 || faces > static_cast<long long>(limits::kMaxMeshElements))
        fail("the face count " + quoted_excerpt(words[1]) + " is not a number from 0 to 2^30");
      long long edges = 0;
      if (words.size() == 3 && (!whole_number(words[2], edges) || edges < 0))
        fail("the edge count " + quoted_excerpt(words[2]) + " is not a number >= 0 (it is not used, but must be one)");
      if (static_cast<unsigned long long>(vertices) * 6 + static_cast<unsigned long long>(faces) * 8 > bytes)
        fail(std::to_string(vertices) + " vertices and " + std::to_string(faces) + " faces cannot fit in a file of " +
             std::to_string(bytes) + " bytes");
      mesh.positions.reserve(static_cast<std::size_t>(vertices));
      mesh.face_sizes.reserve(static_cast<std::size_t>(faces));
      stage = vertices > 0 ? Stage::Vertices : faces > 0 ? Stage::Faces : Stage::Done;
      continue;
    }
    if (stage == Stage::Vertices) {
      if (words.size() < 3) fail("a vertex needs three numbers `x y z`, got " + std::to_string(words.size()));
      Point p{};
      for (std::size_t k = 0; k < 3; ++k) {
        if (!real_number(words[k], p[k]) || !std::isfinite(p[k]) || std::fabs(p[k]) > limits::kMaxCoordinate)
          fail("coordinate " + quoted_excerpt(words[k]) + " is not a finite number of magnitude at most 1e37");
      }
      // What may follow: texture coordinates, a normal, a colour (numbers, not read).
      for (std::size_t k = 3; k < words.size(); ++k) {
        double x = 0;
        if (!real_number(words[k], x) || k >= 12)
          fail("a vertex is x y z (then at most a normal, a colour and texture coordinates, as numbers), got " +
               quoted_excerpt(words[k]) + " after them");
      }
      mesh.positions.push_back(p);
      if (static_cast<long long>(mesh.positions.size()) == vertices) stage = faces > 0 ? Stage::Faces : Stage::Done;
      continue;
    }
    if (stage == Stage::Faces) {
      long long n = 0;
      if (!whole_number(words[0], n) || n < 0) fail("a face line starts with its vertex count, got " + quoted_excerpt(words[0]));
      if (n < 3) fail("a face needs at least three vertices, got " + std::to_string(n));
      if (n > limits::kMaxFaceSize) fail("a face has more than " + std::to_string(limits::kMaxFaceSize) + " vertices");
      if (static_cast<long long>(words.size()) - 1 < n)
        fail("the face has " + std::to_string(n) + " vertices but the line lists " + std::to_string(words.size() - 1));
      for (long long i = 1; i <= n; ++i) {
        long long index = 0;
        if (!whole_number(words[static_cast<std::size_t>(i)], index))
          fail("bad face index " + quoted_excerpt(words[static_cast<std::size_t>(i)]));
        if (index < 0 || index >= vertices)
          fail("face index " + std::to_string(index) + " refers to no vertex (OFF counts them from 0; the file has " +
               std::to_string(vertices) + ")");
        mesh.face_vertices.push_back(static_cast<int>(index));
      }
      // What may follow: the face's colour (three or four numbers, or a colour-map index).
      if (static_cast<long long>(words.size()) - 1 - n > 4)
        fail("after the face's " + std::to_string(n) + " indices, at most a colour (four numbers), got " +
             std::to_string(static_cast<long long>(words.size()) - 1 - n) + " more words");
      for (std::size_t k = static_cast<std::size_t>(n) + 1; k < words.size(); ++k) {
        double x = 0;
        if (!real_number(words[k], x)) fail("after the face's indices, a colour as numbers, got " + quoted_excerpt(words[k]));
      }
      mesh.face_sizes.push_back(static_cast<int>(n));
      if (static_cast<long long>(mesh.face_sizes.size()) == faces) stage = Stage::Done;
      continue;
    }
    fail("more lines than the " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
         " faces the counts declare");
  }
  if (stage == Stage::Keyword) throw LoadError(path + ": the file is empty (an OFF file starts with the keyword OFF)");
  if (stage == Stage::Counts) throw LoadError(path + ": the file ends before its counts `vertices faces edges`");
  if (stage == Stage::Vertices)
    throw LoadError(path + ": truncated: the file ends after " + std::to_string(mesh.positions.size()) + " of " +
                    std::to_string(vertices) + " vertices");
  if (stage == Stage::Faces)
    throw LoadError(path + ": truncated: the file ends after " + std::to_string(mesh.face_sizes.size()) + " of " +
                    std::to_string(faces) + " faces");
  if (mesh.face_sizes.empty()) throw LoadError(path + ": no faces");
  return mesh;
}

}  // namespace stencil_runtime
