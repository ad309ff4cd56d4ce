#pragma once
// The stated limits of the runtime, in one place. Every reader checks counts,
// indices and sizes against these before use, and every error names the limit.
#include <cstddef>
#include <cstdint>

namespace stencil_runtime::limits {

// Largest vertex valence (and number of faces of a vertex on a boundary): the
// tessellation's polygon round a vertex and the stencil buffers hold up to
// kMaxPatchPoints points.
inline constexpr int kMaxValence = 64;
// Most control points of one patch: 2v + 8 round an interior vertex, 2k + 9
// for a face in the middle of a boundary vertex's k faces.
inline constexpr int kMaxPatchPoints = 2 * kMaxValence + 9;
// Largest face size of a polygon mesh: its centre becomes a vertex of that valence.
inline constexpr int kMaxFaceSize = kMaxValence;
// Largest tessellation or table rate.
inline constexpr int kMaxRate = 4096;
// Most whole-mesh refinement steps the preparation applies to isolate
// extraordinary vertices (each multiplies the faces by 4, or 9 for sqrt(3)).
inline constexpr int kMaxRefinementSteps = 3;
// Most faces the steps that resolve semi-sharp creases may make: a crease of
// sharpness s takes ceil(s) whole-mesh steps, each multiplying the faces by 4
// (2^21 faces: about 0.7 GB and 3 s to prepare on the 2-core test machine).
inline constexpr std::size_t kMaxCreaseStepFaces = std::size_t{1} << 21;
// Vertices and faces of a mesh (input and prepared): indices are 32-bit.
inline constexpr std::size_t kMaxMeshElements = std::size_t{1} << 30;
// Points of one tessellation (output indices are 32-bit signed).
inline constexpr std::size_t kMaxTessellationPoints = std::size_t{1} << 31;
// Largest table file (binary or one JSON table) and mesh file read, in bytes.
inline constexpr std::uintmax_t kMaxTableFileBytes = std::uintmax_t{2} << 30;
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{4} << 30;
// Longest line of an OBJ file (bytes).
inline constexpr std::size_t kMaxMeshLineBytes = std::size_t{1} << 20;
// Largest coordinate magnitude of a control point: tessellations are written
// as 32-bit floats, so larger coordinates could not be represented.
inline constexpr double kMaxCoordinate = 1e37;
// The smallest extent (control points' bounding-box diagonal) closest-point
// queries accept: squared distances of its 1e-9 (the default tolerance) stay
// far above the doubles' denormals, where digits are lost.
inline constexpr double kMinQueryExtent = 1e-100;

}  // namespace stencil_runtime::limits
