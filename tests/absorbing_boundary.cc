// SPDX-License-Identifier: LGPL-2.1-or-later
// Checks the absorbing boundary (boundary_id::absorbing, the mesh file's
// role `absorbing`): the Lysmer-Kuhlemeyer dashpots that Discretisation
// adds to C on such faces, so that a plane wave meeting the boundary
// normally leaves without reflection (the dashpot's impedance equals the
// medium's: reflection coefficient (Z_b - Z) / (Z_b + Z) = 0).
//  - The block of block_scene.h (inviscid, so C is the dashpots alone)
//    with its top y = 0.25 m absorbing, refined twice globally and twice
//    toward the origin. Material: rho = 1000 kg/m^3, K = 1 MPa, nu = 0.25:
//    G = 0.6 MPa, c_s = sqrt(G / rho) = 24.4949 m/s, c_p = sqrt((K + 4/3
//    G) / rho) = 42.4264 m/s.
//  - Plane strain: C applied to a unit x velocity (tangential to the top)
//    gives row sums rho c_s w_i at the top vertices (w_i the lumped
//    vertex weights, 1/16 or 1/8 m here), adding up to rho c_s x 1 m =
//    24494.9 N s/m, and nothing in y; a unit y velocity (normal) gives
//    rho c_p w_i, adding up to 42426.4 N s/m, nothing in x; nothing at
//    vertices off the top (not the traction-free sides, not the base,
//    which carries no radiation damping here; hanging vertices, whose rows
//    AffineConstraints fills with a diagonal, not counted).
//  - Antiplane (one component): rho c_s w_i, adding up to 24494.9 N s/m.
// Printed: the sums and the expected values, and yes/no for the
// node-wise agreement rho c w_i (1e-10 relative) and for "nothing
// elsewhere".
#include "block_scene.h"
#include "tests.h"

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/vector_tools.h>
#include <rsfcycle/physics/discretisation.h>

void
check(const bool antiplane, const unsigned int component, const double c)
{
  MeshParameters mesh;
  mesh.global_refinements = 2;
  mesh.local_refinements  = 2;
  Block scene;
  scene.absorbing_top = true;
  const double rho    = scene.material(0).density;

  physics::Discretisation<2> discretisation(mesh, scene, {antiplane, false});
  discretisation.make_grid();
  discretisation.setup_system();
  discretisation.setup_boundary_conditions();
  discretisation.assemble_matrices();

  const unsigned int  n_components = antiplane ? 1 : 2;
  std::vector<double> unit(n_components, 0.);
  unit[component] = 1;
  la::Vector e, Ce;
  discretisation.reinit(e);
  discretisation.reinit(Ce);
  VectorTools::interpolate(discretisation.dof_handler,
                           Functions::ConstantFunction<2>(unit),
                           e);
  discretisation.viscosity_local.vmult(Ce, e);

  // the top vertices' lumped weights: half of each adjacent top face
  std::map<double, double> weight; // x -> w
  for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          cell->face(f)->boundary_id() == boundary_id::absorbing)
        for (const unsigned int v : cell->face(f)->vertex_indices())
          weight[cell->face(f)->vertex(v)[0]] += cell->face(f)->measure() / 2;

  bool   nodes_agree = true;
  double total = 0, elsewhere = 0;
  for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      for (unsigned int d = 0; d < n_components; ++d)
        {
          const double value = Ce(cell->vertex_dof_index(v, d));
          const bool   top   = std::abs(cell->vertex(v)[1] - 0.25) < 1e-12;
          if (top && d == component)
            {
              const double expected = rho * c * weight.at(cell->vertex(v)[0]);
              nodes_agree =
                nodes_agree && std::abs(value - expected) < 1e-10 * expected;
            }
          else if (!discretisation.hanging_constraints.is_constrained(
                     cell->vertex_dof_index(v, d)))
            elsewhere = std::max(elsewhere, std::abs(value));
        }
  for (const auto &[x, w] : weight)
    total += rho * c * w; // each vertex once
  double sum = 0;
  {
    std::set<types::global_dof_index> seen;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[1] - 0.25) < 1e-12 &&
            seen.insert(cell->vertex_dof_index(v, component)).second)
          sum += Ce(cell->vertex_dof_index(v, component));
  }
  dealii::deallog << (antiplane ? "antiplane" : "plane strain")
                  << ", unit velocity in " << (component == 0 ? "x" : "y")
                  << ": " << weight.size() << " top vertices; sum of C e "
                  << sum << " N s/m, expected rho c x 1 m = " << rho * c
                  << " (from the weights " << total
                  << "); rho c w_i at every top vertex: "
                  << (nodes_agree ? "yes" : "no")
                  << "; nothing elsewhere: " << (elsewhere == 0 ? "yes" : "no")
                  << std::endl;
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog(6);
  const double rho = 1000, K = 1e6, G = 0.6e6;
  const double c_s = std::sqrt(G / rho),
               c_p = std::sqrt((K + 4. / 3. * G) / rho);
  check(false, 0, c_s);
  check(false, 1, c_p);
  check(true, 0, c_s);
}
