// An outside program on the installed stencil runtime: load a scheme's
// tables and a control mesh, evaluate a limit point and its stencil row over
// the control vertices, then animate: the topology and the tessellation plan
// are made once, and every frame only replaces the control positions.
//
//   animate_surface TABLES MESH.obj OUT.ply [FRAMES]
#include <stencil_runtime/stencil_runtime.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: animate_surface TABLES MESH.obj OUT.ply [FRAMES]\n");
    return 2;
  }
  try {
    using namespace stencil_runtime;
    const int frames = argc > 4 ? std::stoi(argv[4]) : 10;
    const auto tables = Tables::load(argv[1]);
    const Mesh mesh = read_obj(argv[2]);
    // Topology once: face sizes and indices only.
    const auto topology = SurfaceTopology::create(tables, mesh.vertex_count(), mesh.face_sizes, mesh.face_vertices);
    Surface surface(topology, mesh.positions);

    // An exact limit point, and the same point as a row over the control vertices.
    const ExactParameter centre = topology->domain(0).kind == FaceDomain::Kind::Triangle
                                      ? ExactParameter{Fraction::make(1, 3), Fraction::make(1, 3)}
                                      : ExactParameter{Fraction::make(1, 4), Fraction::make(1, 4)};
    const Point p = surface.evaluate(0, centre);
    const StencilRows row = topology->stencil(0, centre);
    const Point q = row.apply(mesh.positions)[0];
    std::printf("scheme %s: face 0 at %s = %.12g %.12g %.12g (row of %zu control vertices: %.12g %.12g %.12g)\n",
                tables->scheme().c_str(), centre.str().c_str(), p[0], p[1], p[2], row.vertices.size(), q[0], q[1], q[2]);

    // Animation: plan once, then per frame new positions in, tessellated positions out.
    const TessellationPlan plan(topology, std::vector<int>(mesh.face_count(), 6));
    PolygonSoup soup = plan.make_soup();
    std::vector<Point> moved = mesh.positions;
    for (int k = 0; k < frames; ++k) {
      const double angle = 0.1 * k, c = std::cos(angle), s = std::sin(angle);
      for (std::size_t v = 0; v < moved.size(); ++v) {
        const Point& r = mesh.positions[v];
        moved[v] = {c * r[0] - s * r[1], s * r[0] + c * r[1], r[2] * (1 + 0.05 * std::sin(angle + r[0]))};
      }
      surface.set_positions(moved);
      plan.evaluate(surface, soup.positions.data());
    }
    write_polygons(soup, argv[3]);
    std::printf("%d frames of %zu points and %zu triangles; wrote %s\n", frames, soup.positions.size(), soup.triangle_count(), argv[3]);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "animate_surface: error: %s\n", e.what());
    return 1;
  }
}
