#include "local_region.hpp"

namespace stencil_runtime {

namespace {

bool semi_sharp(float s) { return s > 0 && s < kInfiniteSharpness; }

// The first corner of each face (concatenated face-vertex order).
std::vector<std::size_t> face_starts(const Connectivity& mesh) {
  std::vector<std::size_t> start(mesh.face_count() + 1, 0);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) start[f + 1] = start[f] + static_cast<std::size_t>(mesh.face_sizes[f]);
  return start;
}

}  // namespace

VertexFaces::VertexFaces(const Connectivity& mesh) : offsets(mesh.vertex_count + 1, 0) {
  for (int v : mesh.face_vertices) ++offsets[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < mesh.vertex_count; ++v) offsets[v + 1] += offsets[v];
  faces.resize(mesh.face_vertices.size());
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  std::size_t corner = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    for (int c = 0; c < mesh.face_sizes[f]; ++c)
      faces[fill[static_cast<std::size_t>(mesh.face_vertices[corner++])]++] = static_cast<std::uint32_t>(f);
}

std::vector<char> grow_region(const Connectivity& mesh, const VertexFaces& incidence, std::vector<char> region, int rings) {
  const std::vector<std::size_t> start = face_starts(mesh);
  std::vector<char> at(mesh.vertex_count, 0);
  // Every face round the marked vertices joins.
  auto add_stars = [&] {
    bool grew = false;
    for (std::size_t v = 0; v < mesh.vertex_count; ++v) {
      if (!at[v]) continue;
      for (std::size_t k = incidence.offsets[v]; k < incidence.offsets[v + 1]; ++k)
        if (!region[incidence.faces[k]]) region[incidence.faces[k]] = 1, grew = true;
    }
    return grew;
  };
  for (int r = 0; r < rings; ++r) {
    std::fill(at.begin(), at.end(), 0);
    for (std::size_t f = 0; f < mesh.face_count(); ++f)
      if (region[f])
        for (std::size_t h = start[f]; h < start[f + 1]; ++h) at[static_cast<std::size_t>(mesh.face_vertices[h])] = 1;
    add_stars();
  }
  // Pinches: round a vertex, k region faces in one fan share k - 1 edges (k
  // when they close round it); fewer shared edges mean two fans or more.
  std::vector<int> faces_at(mesh.vertex_count), shared_at(mesh.vertex_count);
  // Whether the half-edge b -> a is in a region face (so a -> b's edge is shared).
  auto reversed_in_region = [&](int a, int b) {
    const auto bv = static_cast<std::size_t>(b);
    for (std::size_t k = incidence.offsets[bv]; k < incidence.offsets[bv + 1]; ++k) {
      const std::uint32_t g = incidence.faces[k];
      if (!region[g]) continue;
      const std::size_t n = start[g + 1] - start[g];
      for (std::size_t c = 0; c < n; ++c)
        if (mesh.face_vertices[start[g] + c] == b && mesh.face_vertices[start[g] + (c + 1) % n] == a) return true;
    }
    return false;
  };
  for (;;) {
    std::fill(faces_at.begin(), faces_at.end(), 0);
    std::fill(shared_at.begin(), shared_at.end(), 0);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      if (!region[f]) continue;
      const std::size_t n = start[f + 1] - start[f];
      for (std::size_t c = 0; c < n; ++c) {
        const int a = mesh.face_vertices[start[f] + c], b = mesh.face_vertices[start[f] + (c + 1) % n];
        ++faces_at[static_cast<std::size_t>(a)];
        if (reversed_in_region(a, b)) ++shared_at[static_cast<std::size_t>(a)];
      }
    }
    std::fill(at.begin(), at.end(), 0);
    bool pinched = false;
    for (std::size_t v = 0; v < mesh.vertex_count; ++v)
      if (faces_at[v] > 0 && shared_at[v] < faces_at[v] - 1) at[v] = 1, pinched = true;
    if (!pinched || !add_stars()) return region;
  }
}

SubMesh cut_out(const Connectivity& mesh, const std::vector<char>& region) {
  SubMesh out;
  std::vector<int> number(mesh.vertex_count, -1);
  std::size_t corner = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const int n = mesh.face_sizes[f];
    if (region[f]) {
      out.faces.push_back(static_cast<std::uint32_t>(f));
      out.mesh.face_sizes.push_back(n);
      for (int c = 0; c < n; ++c) {
        const auto v = static_cast<std::size_t>(mesh.face_vertices[corner + static_cast<std::size_t>(c)]);
        if (number[v] < 0) {
          number[v] = static_cast<int>(out.vertices.size());
          out.vertices.push_back(static_cast<std::uint32_t>(v));
        }
        out.mesh.face_vertices.push_back(number[v]);
      }
    }
    corner += static_cast<std::size_t>(n);
  }
  out.mesh.vertex_count = out.vertices.size();
  return out;
}

LevelSharpness restrict_sharpness(const LevelSharpness& parent, const SubMesh& sub) {
  LevelSharpness out = parent.empty_like();
  if (parent.smooth()) return out;
  std::size_t corner = 0;
  for (std::size_t f = 0; f < sub.mesh.face_count(); ++f) {
    const auto n = static_cast<std::size_t>(sub.mesh.face_sizes[f]);
    for (std::size_t c = 0; c < n; ++c) {
      const int a = sub.mesh.face_vertices[corner + c], b = sub.mesh.face_vertices[corner + (c + 1) % n];
      // Set from both sides where two faces share it: the same value.
      out.set_edge(a, b, parent.edge(static_cast<int>(sub.vertices[static_cast<std::size_t>(a)]),
                                     static_cast<int>(sub.vertices[static_cast<std::size_t>(b)])));
    }
    corner += n;
  }
  for (std::size_t v = 0; v < sub.vertices.size(); ++v) out.set_vertex(static_cast<int>(v), parent.vertex(static_cast<int>(sub.vertices[v])));
  return out;
}

std::vector<char> semi_sharp_vertices(const Connectivity& mesh, const LevelSharpness& sharpness) {
  std::vector<char> out(mesh.vertex_count, 0);
  sharpness.for_each_edge([&](int a, int b, float s) {
    if (semi_sharp(s)) out[static_cast<std::size_t>(a)] = out[static_cast<std::size_t>(b)] = 1;
  });
  sharpness.for_each_vertex([&](int v, float s) {
    if (semi_sharp(s)) out[static_cast<std::size_t>(v)] = 1;
  });
  return out;
}

std::vector<char> semi_sharp_faces(const Connectivity& mesh, const LevelSharpness& sharpness) {
  const std::vector<char> at = semi_sharp_vertices(mesh, sharpness);
  std::vector<char> out(mesh.face_count(), 0);
  std::size_t corner = 0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (int c = 0; c < mesh.face_sizes[f]; ++c) out[f] |= at[static_cast<std::size_t>(mesh.face_vertices[corner + static_cast<std::size_t>(c)])];
    corner += static_cast<std::size_t>(mesh.face_sizes[f]);
  }
  return out;
}

}  // namespace stencil_runtime
