#include "semi_sharp_levels.hpp"

#include <algorithm>
#include <atomic>
#include <string>

#include "family/local_region.hpp"
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

bool prefer_round_features(const Connectivity& mesh, const LevelSharpness& sharpness, std::size_t first) {
  if (!sharpness.has_semi_sharp()) return false;
  if (!crease_steps_fit(first, sharpness.max(), whole_mesh_crease_faces())) return true;
  switch (crease_refinement_choice()) {
    case CreaseRefinementChoice::WholeMesh: return false;
    case CreaseRefinementChoice::RoundFeatures: return true;
    case CreaseRefinementChoice::Automatic: break;
  }
  const std::vector<char> marked = semi_sharp_faces(mesh, sharpness);
  return 4 * static_cast<std::size_t>(std::count(marked.begin(), marked.end(), 1)) <= mesh.face_count();
}

std::size_t SemiSharpRefinement::faces() const {
  std::size_t n = refined.size();
  for (const SemiSharpLevel& l : levels) n += l.mesh.face_count();
  return n;
}

SemiSharpRefinement refine_round_semi_sharp(const Connectivity& mesh, const LevelSharpness& sharpness,
                                            const RegionStepper& stepper, const CurveCreaseRule& crease,
                                            bool boundary_corners) {
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
    RegionStep step = stepper(sub.mesh);
    const LevelSharpness sub_sharpness = restrict_sharpness(*level_sharpness, sub);
    SemiSharpLevel next;
    next.sharpness = sharpen_step(sub.mesh, sub_sharpness, crease, step.edge_points, step.step, boundary_corners);
    renumber_columns(step.step, sub, level->vertex_count);
    next.step = std::move(step.step);
    next.mesh = std::move(step.mesh);
    if (next.mesh.face_count() != 4 * sub.mesh.face_count())
      throw MeshError("internal: a refinement step round semi-sharp features did not split every face in four");
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
