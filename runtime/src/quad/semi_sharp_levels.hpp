#pragma once
// Semi-sharp features refined where they are (issue 17, item 3): OpenSubdiv's
// creasing changes the limit surface of a face only when a vertex of it has a
// semi-sharp feature (its own sharpness or an edge's), so only such faces are
// subdivided, level by level, until the sharpness has decayed; every other
// face keeps its stationary patch at the level where it was left.
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
#include <vector>

#include "family/boundary_rules.hpp"
#include "family/crease_step.hpp"
#include "family/refinement.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/sharpness.hpp"
#include "tables/quad_tables.hpp"

namespace stencil_runtime {

// The most faces whole-mesh steps may make for a mesh's semi-sharp features;
// beyond it the quad family refines only round them.
std::size_t whole_mesh_crease_faces();
void set_whole_mesh_crease_faces(std::size_t faces);

// Which way the quad family takes semi-sharp features within that budget.
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

struct SemiSharpLevel {
  Connectivity mesh;  // every face a quad; its border is the region's, plus the mesh's own boundary
  LevelSharpness sharpness;
  RefinementStep step;                // its vertices from those of the level before
  std::vector<std::uint32_t> parent;  // per face: the face of the level before it is a quadrant of (corner: face % 4)
  std::vector<char> exact;            // per face: a child of a face refined at the level before (it and its 1-ring exact)
  std::vector<char> refined;          // per face: subdivided again at the next level
};

struct SemiSharpRefinement {
  std::vector<char> refined;         // per face of the input mesh: subdivided at level 1
  std::vector<SemiSharpLevel> levels;  // levels[0] is level 1
  std::size_t faces() const;         // of all levels
};

// From a quad mesh, closed or with boundaries (`boundary`: their rules, needed
// on a closed mesh too, for the regions' borders), and
// its sharpness: levels until no exact face has a semi-sharp feature. `crease`
// and `edge_and_corner` as for sharpen_step. Throws MeshError when the levels
// would hold more than limits::kMaxCreaseStepFaces faces.
SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const QuadTables& tables, const CurveCreaseRule& crease,
                                            const BoundaryRules& boundary, bool edge_and_corner);

}  // namespace stencil_runtime
