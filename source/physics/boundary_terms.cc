// SPDX-License-Identifier: LGPL-2.1-or-later
// The lumped terms of Discretisation's matrices: the contact's radiation
// damping and shear prestress, the absorbing faces' dashpots, the sponge.
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <memory>
#include <rsfcycle/ids.h>
#include <rsfcycle/physics/discretisation.h>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    template <class Iterator>
    void
    Discretisation<dim>::add_absorbing_terms(
      const Iterator          &cell,
      const physics::Material &material,
      FullMatrix<double>      &cell_viscosity) const
    {
      const double c_s = std::sqrt(material.shear_modulus() / material.density);
      const double c_p =
        std::sqrt((material.bulk_modulus + 4. / 3. * material.shear_modulus()) /
                  material.density);
      // lumped (vertex quadrature): at each vertex the dashpot
      // rho (c_p n n^T + c_s (I - n n^T)) couples the components of the
      // vertex's own dofs only
      for_each_boundary_face(
        cell,
        boundary_id::absorbing,
        update_values | update_normal_vectors | update_JxW_values,
        [&](const FEFaceValues<dim> *fe_face) {
          for (const unsigned int q : fe_face->quadrature_point_indices())
            {
              const Tensor<1, dim> &n   = fe_face->normal_vector(q);
              const double          JxW = fe_face->JxW(q);
              for (const unsigned int i : fe_face->dof_indices())
                for (const unsigned int j : fe_face->dof_indices())
                  {
                    const double phi_phi =
                      fe_face->shape_value(i, q) * fe_face->shape_value(j, q);
                    if (phi_phi == 0)
                      continue;
                    double impedance = material.density * c_s;
                    if (!options.antiplane)
                      {
                        const unsigned int ci =
                          fe.system_to_component_index(i).first;
                        const unsigned int cj =
                          fe.system_to_component_index(j).first;
                        impedance =
                          material.density *
                          ((c_p - c_s) * n[ci] * n[cj] + (ci == cj ? c_s : 0.));
                      }
                    cell_viscosity(i, j) += impedance * phi_phi * JxW;
                  }
            }
        });
    }


    template <int dim>
    template <class Iterator, class FaceFunction>
    void
    Discretisation<dim>::for_each_boundary_face(
      const Iterator          &cell,
      const types::boundary_id id,
      const UpdateFlags        flags,
      const FaceFunction      &function) const
    {
      std::unique_ptr<FEFaceValues<dim>> fe_face;
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary() ||
              cell->face(f)->boundary_id() != id)
            continue;
          if (!fe_face)
            fe_face = std::make_unique<FEFaceValues<dim>>(fe,
                                                          QTrapezoid<dim - 1>(),
                                                          flags);
          fe_face->reinit(cell, f);
          function(fe_face.get());
        }
    }


    template <int dim>
    template <class Iterator>
    void
    Discretisation<dim>::add_contact_terms(const Iterator          &cell,
                                           const physics::Material *material,
                                           FullMatrix<double> *cell_viscosity,
                                           Vector<double>     *cell_force) const
    {
      for_each_boundary_face(
        cell,
        boundary_id::contact,
        update_values | update_quadrature_points | update_JxW_values,
        [&](const FEFaceValues<dim> *fe_face) {
          // lumped (vertex quadrature, as the friction's weights) on every
          // tangential component (not y, the normal of the base in the
          // rotated frame): eta w_i on the diagonal, tau_0 w_i in the force
          for (const unsigned int q : fe_face->quadrature_point_indices())
            {
              const Point<dim> &x   = fe_face->quadrature_point(q);
              const double      JxW = fe_face->JxW(q);
              const double      eta_JxW =
                cell_viscosity ? scene.radiation_damping(x, *material) * JxW :
                                      0.;
              const Tensor<1, dim> traction =
                cell_force ? prestress(x) : Tensor<1, dim>();
              for (const unsigned int i : fe_face->dof_indices())
                {
                  const unsigned int component =
                    fe.system_to_component_index(i).first;
                  if (component == normal_component())
                    continue;
                  const double phi = fe_face->shape_value(i, q);
                  if (cell_viscosity)
                    (*cell_viscosity)(i, i) += eta_JxW * phi * phi;
                  if (cell_force)
                    (*cell_force)(i) += traction[component] * phi * JxW;
                }
            }
        });
    }


    // both terms for the active and the level cells of both dimensions
    /**
     * The sponge (Scene::sponge_damping): C += alpha M lumped, the row sums
     * of each cell's alpha M condensed like a load (at a hanging node a
     * cell's diagonal would otherwise couple the node's parents) and added
     * to C's diagonal, so that the implicit and the explicit step take the
     * same diagonal damping. (The multigrid's level matrices leave it out:
     * they only precondition.)
     */
    template <int dim>
    void
    Discretisation<dim>::add_sponge(
      FEValues<dim>                        &fe_values,
      std::array<FullMatrix<double>, 3>    &cell,
      std::vector<types::global_dof_index> &dof_indices)
    {
      la::Vector sponge;
      reinit(sponge);
      bool           any = false;
      Vector<double> cell_force(fe.n_dofs_per_cell()),
        cell_sponge(fe.n_dofs_per_cell());
      for (const auto &active_cell : dof_handler.active_cell_iterators())
        if (active_cell->is_locally_owned())
          if (const double alpha = scene.sponge_damping(active_cell->center());
              alpha != 0)
            {
              any = true;
              cell_matrices(active_cell, fe_values, cell, cell_force);
              for (unsigned int i = 0; i < cell_sponge.size(); ++i)
                {
                  cell_sponge(i) = 0;
                  for (unsigned int j = 0; j < cell_sponge.size(); ++j)
                    cell_sponge(i) += alpha * cell[0](i, j);
                }
              active_cell->get_dof_indices(dof_indices);
              hanging_constraints.distribute_local_to_global(cell_sponge,
                                                             dof_indices,
                                                             sponge);
            }
      sponge.compress(VectorOperation::add);
      if (!Utilities::MPI::logical_or(any, triangulation.get_communicator()))
        return;
      for (const auto row : sponge.locally_owned_elements())
        if (sponge[row] != 0)
          viscosity_matrix.add(row, row, sponge[row]);
      viscosity_matrix.compress(VectorOperation::add);
    }


    template void
    Discretisation<2>::add_sponge(FEValues<2> &,
                                  std::array<FullMatrix<double>, 3> &,
                                  std::vector<types::global_dof_index> &);
    template void
    Discretisation<3>::add_sponge(FEValues<3> &,
                                  std::array<FullMatrix<double>, 3> &,
                                  std::vector<types::global_dof_index> &);


#define RSFCYCLE_BOUNDARY_TERMS(dim, Iterator)            \
  template void Discretisation<dim>::add_contact_terms(   \
    const DoFHandler<dim>::Iterator &,                    \
    const physics::Material *,                            \
    FullMatrix<double> *,                                 \
    Vector<double> *) const;                              \
  template void Discretisation<dim>::add_absorbing_terms( \
    const DoFHandler<dim>::Iterator &,                    \
    const physics::Material &,                            \
    FullMatrix<double> &) const;
    RSFCYCLE_BOUNDARY_TERMS(2, active_cell_iterator)
    RSFCYCLE_BOUNDARY_TERMS(2, level_cell_iterator)
    RSFCYCLE_BOUNDARY_TERMS(3, active_cell_iterator)
    RSFCYCLE_BOUNDARY_TERMS(3, level_cell_iterator)
#undef RSFCYCLE_BOUNDARY_TERMS
  } // namespace physics
} // namespace rsfcycle
