#pragma once
// A polygon mesh as OpenSubdiv's Far::TopologyDescriptor takes it: per-face
// vertex counts, the concatenated face-vertex indices (counter-clockwise seen
// from outside), and positions; and the polygons a tessellation produces.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "error.hpp"

namespace stencil_runtime {

using Point = std::array<double, 3>;

// OpenSubdiv's boundary interpolation options (Sdc::Options::VtxBoundaryInterpolation).
enum class BoundaryInterpolation { None, EdgeOnly, EdgeAndCorner };

// The OBJ tag lines of OpenSubdiv's test shapes (`t name I/F/S ints floats
// strings`), as read_obj found them. Each feature keeps the file line it came
// from, so that whoever cannot honour it can name it. Vertex and face indices
// are 0-based, as in the tags.
struct MeshTags {
  struct Crease {
    int a = 0, b = 0;
    double sharpness = 0;
    long line = 0;
  };
  struct Corner {
    int vertex = 0;
    double sharpness = 0;
    long line = 0;
  };
  struct Hole {
    int face = 0;
    long line = 0;
  };
  std::vector<Crease> creases;  // one per edge, in file order (sharpness 0 included)
  std::vector<Corner> corners;
  std::vector<Hole> holes;
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;  // OpenSubdiv's tools' default
  bool chaikin_creases = false;                                      // `creasemethod chaikin`
  bool smooth_triangles = false;                                     // `smoothtriangles smooth`
  long smooth_triangles_line = 0;
};

// What changes a mesh's subdivision rules, in OpenSubdiv's conventions:
// semi-sharp creases and corners (Sdc::Crease), a sharpness per edge (its two
// end vertices) and per vertex; 0 is smooth, a sharpness s keeps the feature
// sharp for about s subdivision steps, 10 or more is infinitely sharp.
// Chaikin's method spreads an edge's sharpness along the crease as it decays;
// the default is uniform (subtract 1 a step). `smooth_triangles` is
// OpenSubdiv's Catmull-Clark option TRI_SUB_SMOOTH (the `smoothtriangles`
// tag): the first step's edge points next to triangles lean towards the
// triangles' centres.
struct MeshFeatures {
  struct Edge {
    int a = 0, b = 0;
    double sharpness = 0;
  };
  struct Vertex {
    int vertex = 0;
    double sharpness = 0;
  };
  std::vector<Edge> edges;
  std::vector<Vertex> vertices;
  bool chaikin = false;
  bool smooth_triangles = false;
  // How a mesh with boundaries is interpolated there (docs/runtime.md,
  // "Boundaries"); closed meshes ignore it.
  BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
};

struct Mesh {
  std::vector<Point> positions;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;  // concatenated, counter-clockwise seen from outside
  MeshTags tags;
  std::string source;                 // the file it was read from (empty when made in code), for messages
  std::vector<std::string> warnings;  // e.g. unknown tag lines, each naming its file and line

  std::size_t face_count() const { return face_sizes.size(); }
  std::size_t vertex_count() const { return positions.size(); }
};

// Output of a tessellation: positions (and unit normals when asked for) and
// polygons (quads and triangles) indexing them.
struct PolygonSoup {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // empty, or one per position
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  std::size_t triangle_count() const { return triangles.size() + 2 * quads.size(); }
};

}  // namespace stencil_runtime
