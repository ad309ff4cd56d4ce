#pragma once
// Reading and writing control meshes (Wavefront OBJ) and writing
// tessellations (OBJ or binary PLY).
#include <string>

#include "mesh.hpp"

namespace stencil_runtime {

// Wavefront OBJ: `v x y z` and `f a b c ...` lines (1-based or negative
// indices, `a/t/n` forms accepted), and OpenSubdiv's tag lines `t name I/F/S
// ...` into Mesh::tags (crease, corner, hole, interpolateboundary,
// creasemethod, smoothtriangles; an unknown tag becomes a warning in
// Mesh::warnings); other lines are ignored. A line ending in a backslash
// continues on the next (not a comment's: a comment may end in a Windows
// folder); messages name a continued line's first. Refuses, with a
// LoadError naming the file and line: a file that is not a regular file or is
// larger than limits::kMaxMeshFileBytes, a line longer than
// limits::kMaxMeshLineBytes, coordinates that are not finite or exceed
// limits::kMaxCoordinate, bad or out-of-range indices, faces with fewer than
// three or more than limits::kMaxFaceSize vertices, more than
// limits::kMaxMeshElements vertices or faces, a file without faces, a
// malformed tag line, and tags naming vertices, edges or faces that do not
// exist. Reading a tag does not mean it is honoured: SurfaceTopology::create
// with the Mesh refuses the ones the runtime cannot evaluate.
Mesh read_obj(const std::string& path);

// OFF (as CGAL, Meshlab and the Princeton shape benchmark write it): the
// keyword OFF (or COFF, NOFF, STOFF, ..., with the counts after it or on the
// next line), `vertices faces edges`, one `x y z` line per vertex (normals,
// colours and texture coordinates after it are allowed and not read), one
// `n i0 ... i(n-1)` line per face with indices from 0 (a colour after it
// allowed); '#' comments. Refused with a LoadError naming the file and line,
// as for OBJ: the file limits, counts out of range or more than the file can
// hold, coordinates that are not finite, indices out of range, faces of fewer
// than three vertices, a file that ends early or goes on past its counts,
// binary OFF and 4OFF/nOFF (other shapes of vertex). No tags (OFF has none).
Mesh read_off(const std::string& path);

// PLY (ASCII, binary little- or big-endian): the element `vertex` first, with
// float or double x, y, z, and an element `face` with a list
// `vertex_indices` (or `vertex_index`) of indices from 0; other elements and
// properties are walked and not read. Refused with a LoadError naming the
// file and the header line, text line, binary item or face: the file limits,
// counts the file cannot hold, a file cut short or longer than its header
// says, coordinates that are not finite, indices out of range, faces of
// fewer than three vertices. As for OFF, no tags.
Mesh read_ply_mesh(const std::string& path);

// A control mesh by its extension (any case): .off is OFF, .ply PLY, anything else OBJ.
Mesh read_mesh(const std::string& path);

// A path's extension in lower case ("scan.PLY" gives ".ply"): what every
// reader and writer chooses its format by, so "OUT.OBJ" is an OBJ file.
std::string lowercase_extension(const std::string& path);

// OBJ (text) or binary little-endian PLY, chosen by the extension (.obj/.ply,
// any case), with per-vertex normals when the soup has them. A soup holds
// floats: one whose coordinates are all below 1.2e-38 in magnitude (the
// smallest normal float) has lost digits, and is refused, as are points or
// normals that are not finite and polygons naming missing points (MeshError,
// before anything is written). Writes a
// temporary file beside `path` and renames it, so a failure leaves nothing
// behind.
void write_polygons(const PolygonSoup& soup, const std::string& path);

// A control mesh as OBJ (`v` lines with every digit of the doubles, then `f`
// lines, 1-based, then its OpenSubdiv tag lines: creases, corners, holes, the
// boundary interpolation, the crease method, smooth triangles), in the mesh's
// vertex and face order, so that read_obj gives back the same surface; written
// like write_polygons, so a failure leaves nothing behind. What read_obj would
// refuse is refused first (MeshError naming it): no faces, a face size outside
// 3..limits::kMaxFaceSize, sizes that do not add up to the index count, an
// index naming no vertex, a coordinate that is not finite or beyond
// limits::kMaxCoordinate, a tag naming no vertex, edge or face, or a sharpness
// that is not a number >= 0.
void write_obj(const Mesh& mesh, const std::string& path);

}  // namespace stencil_runtime
