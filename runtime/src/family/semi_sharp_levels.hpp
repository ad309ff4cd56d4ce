#pragma once
// Semi-sharp features refined where they are (issue 17, item 3), for any
// scheme whose step splits every face in four (Catmull-Clark, nonpoly, Loop):
// OpenSubdiv's creasing changes the limit surface of a face only when a vertex
// of it has a semi-sharp feature (its own sharpness or an edge's), so only
// such faces are subdivided, level by level, until the sharpness has decayed;
// every other face keeps its stationary patch at the level where it was left.
//
// Each level is a mesh of its own: the children of the region refined at the
// level before, that region being the faces to refine grown by one vertex
// ring (local_region.hpp). The points of the refined faces' children and of
// those children's 1-rings are then exact: they are the vertex points of the
// refined faces' corners, whose whole 1-rings were in the region, and the edge
// and face points of the edges and faces at those corners; only points next
// to the region's border follow boundary rules there. So the faces to refine
// next are taken among those children, and their patches can be gathered at
// that level (checked against Far: tests/test_semi_sharp_levels.cpp; with no
// ring the points next to the refined faces are wrong).

#include <cstdint>
#include <functional>
#include <vector>

#include "family/crease_step.hpp"
#include "family/refinement.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/sharpness.hpp"

namespace stencil_runtime {

// The most faces whole-mesh steps may make for a mesh's semi-sharp features;
// beyond it a family refines only round them.
std::size_t whole_mesh_crease_faces();
void set_whole_mesh_crease_faces(std::size_t faces);

// Which way semi-sharp features are taken within that budget.
// Automatic: round them when at most a quarter of the faces have a corner
// with a semi-sharp feature (bench_creases, 2026-12-03: with every 100th edge
// creased, 0.82-0.96 of the smooth mesh's tessellation rate round the
// features against 0.48-0.77 by whole-mesh steps; with every 10th, where 81%
// of the faces have such a corner, 0.41-0.55 against 0.58-0.81: a face
// refined round a feature is tessellated point by point, a face of
// whole-mesh steps by the fast kernels), else by whole-mesh steps. Tests
// choose one way to compare it with the other.
enum class CreaseRefinementChoice { Automatic, WholeMesh, RoundFeatures };
CreaseRefinementChoice crease_refinement_choice();
void set_crease_refinement_choice(CreaseRefinementChoice choice);

// Whether a mesh's semi-sharp features are refined round them rather than by
// whole-mesh steps: they must be when those steps from `first` faces (the
// first step's) would pass the budget, and otherwise by the choice above.
bool prefer_round_features(const Connectivity& mesh, const LevelSharpness& sharpness, std::size_t first);

struct SemiSharpLevel {
  Connectivity mesh;  // its border is the region's, plus the mesh's own boundary
  LevelSharpness sharpness;
  RefinementStep step;                // its vertices from those of the level before
  std::vector<std::uint32_t> parent;  // per face: the face of the level before it is a child of (which child: face % 4)
  std::vector<char> exact;            // per face: a child of a face refined at the level before (it and its 1-ring exact)
  std::vector<char> refined;          // per face: subdivided again at the next level
};

struct SemiSharpRefinement {
  std::vector<char> refined;         // per face of the input mesh: subdivided at level 1
  std::vector<SemiSharpLevel> levels;  // levels[0] is level 1
  std::size_t faces() const;         // of all levels
};

// One step of the scheme's own rules on a region cut out of a level: the
// children (face f's at 4f .. 4f + 3, in the step's order), the step over the
// region's vertices (its border under the scheme's boundary rules), and per
// face corner of the region the edge point of the corner's edge to the next
// corner (sharpen_step's `edge_points`).
struct RegionStep {
  Connectivity mesh;
  RefinementStep step;
  std::vector<int> edge_points;
};
using RegionStepper = std::function<RegionStep(const Connectivity& region)>;

// From a mesh, closed or with boundaries, and its sharpness: levels until no
// exact face has a semi-sharp feature. `crease` and `boundary_corners` as for
// sharpen_step. Throws MeshError when the levels would hold more than
// limits::kMaxCreaseStepFaces faces.
SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const RegionStepper& step, const CurveCreaseRule& crease, bool boundary_corners);

}  // namespace stencil_runtime
