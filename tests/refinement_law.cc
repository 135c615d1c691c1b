// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the refinement laws of `Mesh/Refinement law`:
//  - Wedge::distance_to_patch of a box against a brute-force minimum over a
//    fine sampling of box and patch (the patch written out here from the
//    documented geometry: s_down = Patch down-dip end / cos(dip), s_up =
//    s_down - Patch length in 2D; in 3D the along-base length grows
//    linearly from 0.15 m at z = 0 to 0.25 m at z = Width; the margin
//    widens it by a disc in the base plane), for margins 0 and 0.05 m and
//    40 boxes each: the exact distance never exceeds the sampled one and is
//    within the sampling spacing of it;
//  - `centre distance` (the law of every mesh before the band law): the 2D
//    mesh 2 + 6 keeps its 3825 cells (the count logged by rsfcycle before
//    the law became a choice);
//  - `band`: every contact face on the widened patch (band 0.1 m) is at the
//    finest level, the finest cells stay close to it (within two of their
//    diameters: one layer and the 2:1 balance), and the band law needs
//    fewer cells than the centre law at the same finest cell size. The band
//    law's cell counts pin its meshes;
//  - `Mesh file/Refine zone` (the law switched off by Refinement distance =
//    0): a zone of n = 2 everywhere makes 16 cells of every coarse cell; a
//    zone |y| < 8 km, whose edges are coarse vertices (1.6 km cells), refines
//    exactly the coarse cells whose centre is in it twice (16 cells each, at
//    level 2) and their vertex neighbours once for the 2:1 balance (4 cells
//    each, at level 1), counted here from the coarse mesh; an empty zone
//    leaves the coarse mesh. (The zone is evaluated at every cycle's cells,
//    so a zone edge inside a coarse cell is followed by its children.)
#include "tests.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <rsfcycle/app/simulation.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/scenes/scenes.h>
#include <rsfcycle/scenes/wedge.h>
#include <set>

using namespace dealii;
using namespace rsfcycle;

// The patch at the lateral position z, from the documented geometry.
std::pair<double, double>
patch(const double z, const int dim)
{
  const double cos_phi = 1. / std::hypot(1., 0.27);
  const double s_down  = 0.35 / cos_phi;
  if (dim == 2)
    return {s_down - 0.2, s_down};
  const double s_up = s_down - 0.2;
  return {s_up, s_up + 0.15 + 0.1 * std::clamp(z / 0.6, 0., 1.)};
}

template <int dim>
void
check_box_distance(const scenes::Wedge<dim> &wedge)
{
  unsigned int seed = 12345;
  auto         next = [&seed]() {
    seed = 1103515245u * seed + 12345u;
    return (seed >> 8) / double(1u << 24);
  };
  const int n         = (dim == 2) ? 2000 : 200;
  double    worst_gap = 0;
  bool      below     = true;
  for (const double margin : {0., 0.05})
    for (unsigned int trial = 0; trial < 40; ++trial)
      {
        Point<dim> lo, hi;
        lo[0] = -0.1 + 0.8 * next();
        hi[0] = lo[0] + 0.2 * next();
        lo[1] = (trial % 3 == 0) ? 0. : 0.05 * next();
        hi[1] = lo[1] + 0.05 * next();
        if constexpr (dim == 3)
          {
            lo[2] = -0.2 + next();
            hi[2] = lo[2] + 0.3 * next();
          }
        const double exact =
          wedge.distance_to_patch(BoundingBox<dim>({lo, hi}), margin);
        // in the base plane: the patch's sample points against the box's
        // footprint; the margin widens the patch by a disc in the plane
        double in_plane = 1e9;
        for (int i = 0; i <= n; ++i)
          for (int k = 0; k <= (dim == 3 ? n : 0); ++k)
            {
              const double z            = 0.6 * k / std::max(n, 1);
              const auto [s_up, s_down] = patch(z, dim);
              const double s            = s_up + (s_down - s_up) * i / n;
              const double gx           = std::max({0., lo[0] - s, s - hi[0]});
              const double gz =
                (dim == 3) ? std::max({0., lo[dim - 1] - z, z - hi[dim - 1]}) :
                             0.;
              in_plane = std::min(in_plane, std::hypot(gx, gz));
            }
        const double sampled =
          std::hypot(std::max(0., in_plane - margin), lo[1]);
        below     = below && exact <= sampled + 1e-12;
        worst_gap = std::max(worst_gap, sampled - exact);
      }
  const double spacing = 0.6 / n;
  deallog << dim << "D box distance: never above the sampled one: "
          << (below ? "yes" : "no") << ", within the sampling spacing: "
          << (worst_gap <= spacing ? "yes" : "no") << std::endl;
}

template <int dim>
unsigned int
check_mesh(ParameterHandler  &prm,
           const std::string &law,
           const unsigned int global,
           const unsigned int local)
{
  prm.enter_subsection("Mesh");
  prm.set("Global refinements", std::to_string(global));
  prm.set("Local refinements", std::to_string(local));
  prm.set("Refinement law", law);
  prm.set("Refinement band", "0.1");
  prm.set("Refinement band layers", "1");
  prm.leave_subsection();
  MeshParameters mesh;
  mesh.parse_parameters(prm);
  scenes::Wedge<dim>           wedge(prm);
  physics::Discretisation<dim> discretisation(mesh, wedge);
  discretisation.make_grid();
  const auto &tria         = discretisation.triangulation;
  const int   finest       = tria.n_global_levels() - 1;
  bool        faces_finest = true, cells_near = true;
  for (const auto &cell : tria.active_cell_iterators())
    {
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() &&
            face->boundary_id() == boundary_id::contact &&
            wedge.distance_to_patch(face->bounding_box(), 0.1) == 0 &&
            wedge.distance_to_patch(
              BoundingBox<dim>({face->center(), face->center()}), 0.1) == 0)
          faces_finest = faces_finest && cell->level() == finest;
      if (cell->level() == finest)
        cells_near =
          cells_near && wedge.distance_to_patch(cell->bounding_box(), 0.1) <
                          2.01 * cell->diameter();
    }
  deallog << dim << "D " << global << " + " << local << ", " << law << ": "
          << tria.n_global_active_cells() << " cells";
  if (law == "band")
    deallog << ", contact faces on the widened patch at the finest level: "
            << (faces_finest ? "yes" : "no")
            << ", finest cells within two cells of it: "
            << (cells_near ? "yes" : "no");
  deallog << std::endl;
  return tria.n_global_active_cells();
}

// The whole-fault mesh with the law off and the given zone: the cells
// per level against those counted from the coarse mesh.
void
check_zone(const std::string &zone, const std::string &label)
{
  const std::string source = SOURCE_DIR;
  ParameterHandler  prm;
  app::declare_parameters(prm);
  prm.parse_input_from_string(
    "set Dimension = 2\n"
    "set Scene = mesh-file\n"
    "subsection Mesh file\n"
    "  set File = " +
    source +
    "/meshes/whole-fault-2d.msh\n"
    "  set Boundary roles = 1: contact, 2: load\n"
    "  set Materials = 10: density 2670, bulk modulus 5.34e10, Poisson "
    "ratio 0.25, shear viscosity 0, bulk viscosity 0\n"
    "  set Gravity = 0, 0\n"
    "  set Load velocity = 0, 1e-9\n"
    "  set Refine zone = " +
    zone +
    "\n"
    "  subsection Friction\n"
    "    set a = 0.01\n"
    "    set b - a = 0.005\n"
    "    set Normal stress = 50e6\n"
    "  end\n"
    "end\n"
    "subsection Mesh\n"
    "  set Global refinements = 0\n"
    "  set Local refinements = 2\n"
    "  set Refinement distance = 0\n"
    "end\n");
  MeshParameters mesh;
  mesh.parse_parameters(prm);
  const auto                 scene = scenes::make_scene<2>("mesh-file", prm);
  physics::Discretisation<2> discretisation(mesh, *scene);
  discretisation.make_grid();
  const auto &tria = discretisation.triangulation;

  // the coarse cells in the zone, and their vertex neighbours outside it
  std::set<unsigned int> zone_vertices;
  unsigned int           n_coarse = 0, n_zone = 0, n_neighbours = 0;
  for (const auto &cell : tria.cell_iterators_on_level(0))
    if (scene->zone_refinements(cell->center()) >= 2)
      for (const unsigned int v : cell->vertex_indices())
        zone_vertices.insert(cell->vertex_index(v));
  for (const auto &cell : tria.cell_iterators_on_level(0))
    {
      ++n_coarse;
      if (scene->zone_refinements(cell->center()) >= 2)
        ++n_zone;
      else
        for (const unsigned int v : cell->vertex_indices())
          if (zone_vertices.count(cell->vertex_index(v)))
            {
              ++n_neighbours;
              break;
            }
    }
  std::array<unsigned int, 3> per_level      = {{0, 0, 0}};
  bool                        in_zone_finest = true;
  for (const auto &cell : tria.active_cell_iterators())
    {
      ++per_level[cell->level()];
      if (scene->zone_refinements(cell->center()) >= 2)
        in_zone_finest = in_zone_finest && cell->level() == 2;
    }
  const bool counts = per_level[2] == 16 * n_zone &&
                      per_level[1] == 4 * n_neighbours &&
                      per_level[0] == n_coarse - n_zone - n_neighbours;
  deallog << "zone " << label << ": " << tria.n_active_cells() << " cells from "
          << n_coarse << " coarse ones (" << n_zone << " in the zone, "
          << n_neighbours
          << " beside it), levels 0/1/2 as counted: " << (counts ? "yes" : "no")
          << ", cells in the zone at level 2: "
          << (in_zone_finest ? "yes" : "no") << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  ParameterHandler prm;
  scenes::Wedge<2>::declare_parameters(prm);
  MeshParameters::declare_parameters(prm);
  {
    scenes::Wedge<2> wedge(prm);
    check_box_distance<2>(wedge);
  }
  {
    scenes::Wedge<3> wedge(prm);
    check_box_distance<3>(wedge);
  }
  const unsigned int centre = check_mesh<2>(prm, "centre distance", 2, 6);
  const unsigned int band   = check_mesh<2>(prm, "band", 2, 6);
  deallog << "2D band law needs fewer cells than the centre law: "
          << (band < centre ? "yes" : "no") << std::endl;
  check_mesh<3>(prm, "band", 0, 3);
  check_zone("2", "everywhere");
  check_zone("if(abs(y) < 8e3, 2, 0)", "|y| < 8 km");
  check_zone("", "empty");
}
