#include "semi_sharp_levels.hpp"

#include <atomic>
#include <string>

#include "family/local_region.hpp"
#include "quad_creases.hpp"
#include "quad_refinement.hpp"
#include "stencil_runtime/limits.hpp"

namespace stencil_runtime {

namespace {

// Per face: `exact` and a corner with a semi-sharp feature.
std::vector<char> faces_to_refine(const Connectivity& mesh, const LevelSharpness& sharpness, const std::vector<char>* exact) {
  std::vector<char> out = semi_sharp_faces(mesh, sharpness);
  if (exact)
    for (std::size_t f = 0; f < out.size(); ++f) out[f] &= (*exact)[f];
  return out;
}

bool any(const std::vector<char>& flags) {
  for (char c : flags)
    if (c) return true;
  return false;
}

// Rows over the sub-mesh's vertices, rewritten over the mesh's.
void renumber_columns(RefinementStep& step, const SubMesh& sub, std::size_t mesh_vertices) {
  for (std::uint32_t& c : step.columns) c = sub.vertices[c];
  step.input_vertices = mesh_vertices;
}

std::atomic<std::size_t> whole_mesh_budget{limits::kMaxCreaseStepFaces};
std::atomic<CreaseRefinementChoice> refinement_choice{CreaseRefinementChoice::Automatic};

}  // namespace

std::size_t whole_mesh_crease_faces() { return whole_mesh_budget.load(); }
void set_whole_mesh_crease_faces(std::size_t faces) { whole_mesh_budget.store(faces); }
CreaseRefinementChoice crease_refinement_choice() { return refinement_choice.load(); }
void set_crease_refinement_choice(CreaseRefinementChoice choice) { refinement_choice.store(choice); }

std::size_t SemiSharpRefinement::faces() const {
  std::size_t n = refined.size();
  for (const SemiSharpLevel& l : levels) n += l.mesh.face_count();
  return n;
}

SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const QuadTables& tables, const CurveCreaseRule& crease,
                                            const BoundaryRules& boundary, bool edge_and_corner) {
  SemiSharpRefinement out;
  out.refined = faces_to_refine(mesh, sharpness, nullptr);
  std::size_t faces = mesh.face_count();
  const Connectivity* level = &mesh;
  const LevelSharpness* level_sharpness = &sharpness;
  const std::vector<char>* refined = &out.refined;
  // Sharpness decays by at least 1 a level (below 10, OpenSubdiv's infinite): at most 10 levels.
  for (int depth = 0; any(*refined); ++depth) {
    if (depth == static_cast<int>(kInfiniteSharpness))
      throw MeshError("internal: semi-sharp features left after " + std::to_string(depth) + " levels of refinement");
    const VertexFaces incidence(*level);
    const SubMesh sub = cut_out(*level, grow_region(*level, incidence, *refined, 1));
    if (faces + 4 * sub.mesh.face_count() > limits::kMaxCreaseStepFaces)
      throw MeshError("the semi-sharp creases and corners need more than " + std::to_string(limits::kMaxCreaseStepFaces) +
                      " faces of refinement round them (the limit) at level " + std::to_string(depth + 1) +
                      "; lower their sharpness");
    const QuadTopology topo(sub.mesh, true);
    QuadStep step = subdivide_quads(topo, tables, &boundary);
    const LevelSharpness sub_sharpness = restrict_sharpness(*level_sharpness, sub);
    SemiSharpLevel next;
    next.sharpness = sharpen_step(sub.mesh, sub_sharpness, crease, quad_step_edge_points(sub.mesh, step.mesh), step.step,
                                  edge_and_corner);
    renumber_columns(step.step, sub, level->vertex_count);
    next.step = std::move(step.step);
    next.mesh = std::move(step.mesh);
    next.parent.resize(next.mesh.face_count());
    next.exact.resize(next.mesh.face_count());
    for (std::size_t f = 0; f < next.mesh.face_count(); ++f) {
      next.parent[f] = sub.faces[f / 4];
      next.exact[f] = (*refined)[next.parent[f]];
    }
    next.refined = faces_to_refine(next.mesh, next.sharpness, &next.exact);
    faces += next.mesh.face_count();
    out.levels.push_back(std::move(next));
    level = &out.levels.back().mesh;
    level_sharpness = &out.levels.back().sharpness;
    refined = &out.levels.back().refined;
  }
  return out;
}

}  // namespace stencil_runtime
