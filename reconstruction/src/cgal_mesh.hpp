#pragma once
// The CGAL types this layer shares between its files.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace stencil_reconstruction {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint = Kernel::Point_3;
using TriangleMesh = CGAL::Surface_mesh<CgalPoint>;

}  // namespace stencil_reconstruction
