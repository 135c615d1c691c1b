// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.templates.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <rsfcycle/ids.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/split_fault.h>
#include <rsfcycle/solvers/amg_correction.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace physics
  {
    template <int dim>
    Discretisation<dim>::Discretisation(const MeshParameters      &mesh,
                                        const physics::Scene<dim> &scene,
                                        const Options             &options)
      : triangulation(MPI_COMM_WORLD,
                      Triangulation<dim>::limit_level_difference_at_vertices,
                      parallel::distributed::Triangulation<
                        dim>::construct_multigrid_hierarchy)
      , fe(FE_Q<dim>(1), options.antiplane ? 1 : dim)
      , dof_handler(triangulation)
      , scalar_fe(1)
      , scalar_dof_handler(triangulation)
      , mesh(mesh)
      , scene(scene)
      , options(options)
      , prestress(scene.shear_prestress())
    {}


    template <int dim>
    Discretisation<dim>::~Discretisation()
    {
      dof_handler.clear();
      scalar_dof_handler.clear();
    }


    /**
     * Every local cycle refines the cells that the refinement law
     * (`Mesh/Refinement law`) puts near the patch: `centre distance` compares
     * the distance of the cell's centre with a multiple of its diameter,
     * `band` refines the cells whose bounding box meets the patch widened by
     * the band, and those closer to it than a multiple of their shortest
     * edge. Either way the zone shrinks with the
     * cell size, so the patch gets the finest cells. A scene's zone
     * (Scene::zone_refinements(), `Mesh file/Refine zone`) is refined in
     * the cycles below its count whatever the law says. deal.II's level
     * difference limit at vertices (needed by the multigrid) grades the
     * rest 2:1.
     */
    template <int dim>
    bool
    Discretisation<dim>::near_patch(
      const typename Triangulation<dim>::active_cell_iterator &cell) const
    {
      if (mesh.refinement_law == MeshParameters::RefinementLaw::band)
        {
          const double gap =
            scene.distance_to_patch(cell->bounding_box(), mesh.refinement_band);
          return gap == 0 || gap < mesh.refinement_band_layers *
                                     cell->minimum_vertex_distance();
        }
      const Point<dim> c = cell->center();
      return scene.distance_to_patch(BoundingBox<dim>({c, c}), 0.) <
             mesh.refinement_distance * cell->diameter();
    }


    template <int dim>
    void
    Discretisation<dim>::make_grid()
    {
      scene.create_coarse_mesh(triangulation);
      triangulation.refine_global(mesh.global_refinements);
      for (unsigned int cycle = 0; cycle < mesh.local_refinements; ++cycle)
        {
          for (const auto &cell : triangulation.active_cell_iterators())
            if (cell->is_locally_owned() &&
                (near_patch(cell) ||
                 scene.zone_refinements(cell->center()) > cycle))
              cell->set_refine_flag();
          triangulation.execute_coarsening_and_refinement();
          if (scene.split_fault())
            refine_fault_sides_alike(triangulation);
        }
      // every level: the multigrid assembles level matrices with them
      for (const auto &cell : triangulation.cell_iterators())
        cell->set_material_id(
          scene.material_id(cell->center(), cell->material_id()));
    }


    template <int dim>
    void
    Discretisation<dim>::setup_system()
    {
      const MPI_Comm comm = triangulation.get_communicator();
      dof_handler.distribute_dofs(fe);
      dof_handler.distribute_mg_dofs();
      scalar_dof_handler.distribute_dofs(scalar_fe);
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      const IndexSet  relevant =
        DoFTools::extract_locally_relevant_dofs(dof_handler);

      hanging_constraints.clear();
      hanging_constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
      hanging_constraints.close();
      const IndexSet scalar_relevant =
        DoFTools::extract_locally_relevant_dofs(scalar_dof_handler);
      scalar_constraints.clear();
      scalar_constraints.reinit(scalar_relevant);
      DoFTools::make_hanging_node_constraints(scalar_dof_handler,
                                              scalar_constraints);
      scalar_constraints.close();
      scalar_partitioner = std::make_shared<Utilities::MPI::Partitioner>(
        scalar_dof_handler.locally_owned_dofs(), scalar_relevant, comm);

      // The rows of other ranks' dofs that this rank's cells add to go to
      // their owners; the ghosts of the vectors are the relevant dofs and
      // every column of an owned row (the kernels read them).
      DynamicSparsityPattern dsp(relevant);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      dsp,
                                      hanging_constraints,
                                      true);
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      const IndexSet ghosts = la::matrix_ghosts(dsp, owned, relevant);
      for (auto *matrix : {&mass_matrix, &viscosity_matrix, &stiffness_matrix})
        matrix->reinit(owned, owned, dsp, comm);
      partitioner =
        std::make_shared<Utilities::MPI::Partitioner>(owned, ghosts, comm);
      reinit(body_force);
      step_matrices.clear();
    }


    template <int dim>
    void
    Discretisation<dim>::setup_boundary_conditions()
    {
      const unsigned int n_local =
        partitioner->locally_owned_size() + partitioner->n_ghost_indices();
      fixed.assign(n_local, false);
      backstop_dofs.clear();
      for (unsigned int i = 0; i < n_local; ++i)
        if (hanging_constraints.is_constrained(partitioner->local_to_global(i)))
          fixed[i] = true;

      // The boundary faces of the rank's cells and their ghost neighbours;
      // the backstop dofs set directly are the owned ones that are not
      // hanging (the backstop velocity has no normal component, so a base
      // vertex of the backstop keeps u.n = 0 either way).
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (!face->at_boundary())
                continue;
              const types::boundary_id id = face->boundary_id();
              for (const unsigned int v : face->vertex_indices())
                for (unsigned int c = 0; c < fe.n_components(); ++c)
                  {
                    const auto dof = face->vertex_dof_index(v, c);
                    if (!is_local(dof))
                      continue;
                    const unsigned int i = local_index(dof);
                    // creep: the tangential components as on the backstop,
                    // the normal one as on the contact
                    if (loaded(id, c))
                      {
                        if (!fixed[i] && partitioner->in_local_range(dof) &&
                            !hanging_constraints.is_constrained(dof))
                          backstop_dofs.push_back(
                            {i,
                             c,
                             id == boundary_id::backstop_opposite ? -1. : 1.});
                        fixed[i] = true;
                      }
                    else if (prescribed(id, c))
                      fixed[i] = true;
                  }
            }
        }
    }


    template <int dim>
    std::vector<std::pair<types::boundary_id, ComponentMask>>
    Discretisation<dim>::prescribed_components() const
    {
      std::vector<std::pair<types::boundary_id, ComponentMask>> masks;
      for (const types::boundary_id id : {boundary_id::backstop,
                                          boundary_id::backstop_opposite,
                                          boundary_id::creep,
                                          boundary_id::contact,
                                          boundary_id::lateral,
                                          boundary_id::parallel})
        {
          std::vector<bool> mask(fe.n_components());
          for (unsigned int c = 0; c < mask.size(); ++c)
            mask[c] = prescribed(id, c);
          if (std::find(mask.begin(), mask.end(), true) != mask.end())
            masks.emplace_back(id, ComponentMask(mask));
        }
      return masks;
    }


    /**
     * Mass M (density), viscosity C (Kelvin-Voigt, shear and bulk
     * viscosity; the sponge is added after the condensation, add_sponge)
     * and stiffness K (bulk modulus, Poisson ratio). A stress of
     * "the same form" is lambda tr(e) I + 2 mu e with
     * lambda = bulk - 2/3 shear.
     */
    template <int dim>
    template <class Iterator>
    void
    Discretisation<dim>::cell_matrices(
      const Iterator                    &cell,
      FEValues<dim>                     &fe_values,
      std::array<FullMatrix<double>, 3> &matrices,
      Vector<double>                    &cell_force) const
    {
      const physics::Material material = scene.material(cell->material_id());
      const double            bulk_modulus  = material.bulk_modulus;
      const double            shear_modulus = material.shear_modulus();
      const double            lambda  = bulk_modulus - 2. / 3. * shear_modulus;
      const Tensor<1, dim>    gravity = scene.gravity();
      const double            eta_lambda =
        material.bulk_viscosity - 2. / 3. * material.shear_viscosity;
      const FEValuesExtractors::Vector displacement(0);

      fe_values.reinit(cell);
      for (auto &matrix : matrices)
        matrix = 0;
      cell_force                                        = 0;
      auto &[cell_mass, cell_viscosity, cell_stiffness] = matrices;
      if (options.antiplane)
        antiplane_cell_matrices(fe_values, material, matrices);
      else
        for (const unsigned int q : fe_values.quadrature_point_indices())
          {
            const double JxW = fe_values.JxW(q);
            for (const unsigned int i : fe_values.dof_indices())
              {
                const Tensor<1, dim> phi_i =
                  fe_values[displacement].value(i, q);
                const SymmetricTensor<2, dim> eps_i =
                  fe_values[displacement].symmetric_gradient(i, q);
                const double div_i = trace(eps_i);
                for (const unsigned int j : fe_values.dof_indices())
                  {
                    const SymmetricTensor<2, dim> eps_j =
                      fe_values[displacement].symmetric_gradient(j, q);
                    const double div_j   = trace(eps_j);
                    const double eps_eps = eps_i * eps_j;
                    cell_mass(i, j) += material.density * phi_i *
                                       fe_values[displacement].value(j, q) *
                                       JxW;
                    cell_stiffness(i, j) +=
                      (lambda * div_i * div_j + 2. * shear_modulus * eps_eps) *
                      JxW;
                    cell_viscosity(i, j) +=
                      (eta_lambda * div_i * div_j +
                       2. * material.shear_viscosity * eps_eps) *
                      JxW;
                  }
                cell_force(i) += material.density * gravity * phi_i * JxW;
              }
          }
      if (options.radiation_damping)
        add_contact_terms(cell, &material, &cell_viscosity, nullptr);
      add_absorbing_terms(cell, material, cell_viscosity);
      if (options.lumped_mass)
        for (unsigned int i = 0; i < cell_mass.m(); ++i)
          {
            double row = 0;
            for (unsigned int j = 0; j < cell_mass.n(); ++j)
              {
                row += cell_mass(i, j);
                cell_mass(i, j) = 0;
              }
            cell_mass(i, i) = row;
          }
    }


    /**
     * The antiplane model: w the out-of-plane displacement, stress
     * G grad w, viscous stress eta_s grad w; in-plane gravity does not load
     * it.
     */
    template <int dim>
    void
    Discretisation<dim>::antiplane_cell_matrices(
      const FEValues<dim>               &fe_values,
      const physics::Material           &material,
      std::array<FullMatrix<double>, 3> &matrices) const
    {
      auto &[cell_mass, cell_viscosity, cell_stiffness] = matrices;
      const double shear_modulus = material.shear_modulus();
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const double JxW = fe_values.JxW(q);
          for (const unsigned int i : fe_values.dof_indices())
            for (const unsigned int j : fe_values.dof_indices())
              {
                const double grad_grad =
                  fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q);
                cell_mass(i, j) += material.density *
                                   fe_values.shape_value(i, q) *
                                   fe_values.shape_value(j, q) * JxW;
                cell_stiffness(i, j) += shear_modulus * grad_grad * JxW;
                cell_viscosity(i, j) +=
                  material.shear_viscosity * grad_grad * JxW;
              }
        }
    }


    template <int dim>
    void
    Discretisation<dim>::assemble_matrices()
    {
      const QGauss<dim> quadrature(fe.degree + 1);
      FEValues<dim>     fe_values(
        fe, quadrature, update_values | update_gradients | update_JxW_values);
      const unsigned int                n = fe.n_dofs_per_cell();
      std::array<FullMatrix<double>, 3> cell{
        {FullMatrix<double>(n), FullMatrix<double>(n), FullMatrix<double>(n)}};
      Vector<double>                       cell_force(n);
      std::vector<types::global_dof_index> dof_indices(n);

      for (const auto &active_cell : dof_handler.active_cell_iterators())
        {
          if (!active_cell->is_locally_owned())
            continue;
          cell_matrices(active_cell, fe_values, cell, cell_force);
          active_cell->get_dof_indices(dof_indices);
          hanging_constraints.distribute_local_to_global(
            cell[0], cell_force, dof_indices, mass_matrix, body_force);
          hanging_constraints.distribute_local_to_global(cell[1],
                                                         dof_indices,
                                                         viscosity_matrix);
          hanging_constraints.distribute_local_to_global(cell[2],
                                                         dof_indices,
                                                         stiffness_matrix);
        }
      for (auto *matrix : {&mass_matrix, &viscosity_matrix, &stiffness_matrix})
        matrix->compress(VectorOperation::add);
      body_force.compress(VectorOperation::add);
      add_sponge(fe_values, cell, dof_indices);

      // the shear prestress, kept apart from gravity: the gravity
      // equilibrium (frictionless base) must not see it
      reinit(prestress_force);
      if (prestress)
        for (const auto &active_cell : dof_handler.active_cell_iterators())
          if (active_cell->is_locally_owned())
            {
              cell_force = 0;
              add_contact_terms(active_cell, nullptr, nullptr, &cell_force);
              active_cell->get_dof_indices(dof_indices);
              hanging_constraints.distribute_local_to_global(cell_force,
                                                             dof_indices,
                                                             prestress_force);
            }
      prestress_force.compress(VectorOperation::add);
      mass_local.initialize(mass_matrix, partitioner);
      viscosity_local.initialize(viscosity_matrix, partitioner);
      stiffness_local.initialize(stiffness_matrix, partitioner);
    }


    template <int dim>
    std::pair<la::Vector, la::Vector>
    Discretisation<dim>::gravity_equilibrium()
    {
      for (const auto &[name, matrix] :
           {std::make_pair("mass (densities)", &mass_matrix),
            std::make_pair("viscosity", &viscosity_matrix),
            std::make_pair("stiffness (bulk modulus, Poisson ratio)",
                           &stiffness_matrix)})
        if (!std::isfinite(matrix->frobenius_norm()))
          throw std::runtime_error(std::string("the ") + name +
                                   " matrix has non-finite entries: the "
                                   "material parameters overflow double");
      if (!std::isfinite(body_force.l2_norm()))
        throw std::runtime_error("the gravity load is not finite (Gravity, "
                                 "densities)");
      TrilinosWrappers::SparseMatrix K;
      K.copy_from(stiffness_matrix);
      la::Vector rhs(body_force);
      la::for_each_entry(K,
                         [&](const types::global_dof_index row,
                             const types::global_dof_index column,
                             double                       &value) {
                           if (fixed[local_index(row)] ||
                               fixed[local_index(column)])
                             value = (row == column) ? 1. : 0.;
                         });
      for (unsigned int i = 0; i < partitioner->locally_owned_size(); ++i)
        if (fixed[i])
          rhs.local_element(i) = 0;
      // CG with algebraic multigrid (Trilinos ML): memory and time grow
      // linearly with the unknowns (the sparse LU it replaced took 232 s and
      // 2.8 GB for the 3D wedge; this takes 5 s and 70 iterations). The
      // residual left is a spurious load on the first velocity solves, from
      // rest: at 1e-12 they needed twice the TNNMG iterations, at 1e-14 as
      // many as after the LU.
      TrilinosWrappers::PreconditionAMG amg;
      amg.initialize(K, solvers::elasticity_amg_data(dof_components()));
      const la::LocalMatrix K_local(K, partitioner);
      la::Vector            u;
      reinit(u);
      SolverControl control(2000, 1e-14 * rhs.l2_norm(), false, false);
      try
        {
          SolverCG<la::Vector>(control).solve(K_local, u, rhs, amg);
        }
      catch (const SolverControl::NoConvergence &failure)
        {
          throw std::runtime_error(
            "the gravity equilibrium did not converge (CG with algebraic "
            "multigrid: relative residual " +
            std::to_string(failure.last_residual / rhs.l2_norm()) + " after " +
            std::to_string(failure.last_step) + " iterations)");
        }
      gravity_iterations = control.last_step();
      u.zero_out_ghost_values();
      hanging_constraints.distribute(u);

      la::Vector reaction;
      reinit(reaction);
      stiffness_local.vmult(reaction, u);
      reaction -= body_force;
      return {u, reaction};
    }


    template <int dim>
    void
    Discretisation<dim>::reinit(la::Vector &v) const
    {
      v.reinit(partitioner);
    }


    template <int dim>
    void
    Discretisation<dim>::set_fixed_values(la::Vector &v, const double t) const
    {
      const Tensor<1, dim> velocity = scene.backstop_velocity(t);
      for (const auto &[i, component, sign] : backstop_dofs)
        v.local_element(i) = sign * velocity[component];
    }


    /** The last four are kept: step doubling alternates tau/2, tau, 2 tau. */
    template <int dim>
    typename Discretisation<dim>::StepMatrix &
    Discretisation<dim>::cached_step_matrix(
      const std::array<double, 3> &coefficients)
    {
      for (auto &entry : step_matrices)
        if (entry.coefficients == coefficients)
          return entry;
      if (step_matrices.size() >= 4)
        step_matrices.erase(step_matrices.begin());
      auto A = std::make_unique<la::LocalMatrix>();
      A->combine({{coefficients[1], &viscosity_local},
                  {coefficients[2], &stiffness_local},
                  {coefficients[0], &mass_local}});
      step_matrices.push_back({coefficients, std::move(A), nullptr});
      return step_matrices.back();
    }


    template <int dim>
    const la::LocalMatrix &
    Discretisation<dim>::step_matrix(const std::array<double, 3> &coefficients)
    {
      return *cached_step_matrix(coefficients).local;
    }


    template <int dim>
    const TrilinosWrappers::SparseMatrix &
    Discretisation<dim>::assembled_step_matrix(
      const std::array<double, 3> &coefficients)
    {
      StepMatrix &entry = cached_step_matrix(coefficients);
      if (!entry.assembled)
        {
          if (stiffness_matrix.m() == 0)
            throw std::logic_error("Discretisation: the assembled matrices "
                                   "were released");
          entry.assembled = std::make_unique<TrilinosWrappers::SparseMatrix>();
          entry.assembled->copy_from(viscosity_matrix);
          if (coefficients[1] != 1)
            entry.assembled->operator*=(coefficients[1]);
          entry.assembled->add(coefficients[2], stiffness_matrix);
          if (coefficients[0] != 0)
            entry.assembled->add(coefficients[0], mass_matrix);
        }
      return *entry.assembled;
    }


    template <int dim>
    void
    Discretisation<dim>::release_assembled_matrices()
    {
      for (auto *matrix : {&mass_matrix, &viscosity_matrix, &stiffness_matrix})
        matrix->clear();
    }


    template <int dim>
    std::vector<unsigned int>
    Discretisation<dim>::dof_components() const
    {
      std::vector<unsigned int> component(partitioner->locally_owned_size());
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (partitioner->in_local_range(indices[i]))
                component[local_index(indices[i])] =
                  fe.system_to_component_index(i).first;
          }
      return component;
    }


    template class Discretisation<2>;
    template class Discretisation<3>;
    template void
    Discretisation<2>::cell_matrices(
      const DoFHandler<2>::active_cell_iterator &,
      FEValues<2> &,
      std::array<FullMatrix<double>, 3> &,
      Vector<double> &) const;
    template void
    Discretisation<3>::cell_matrices(
      const DoFHandler<3>::active_cell_iterator &,
      FEValues<3> &,
      std::array<FullMatrix<double>, 3> &,
      Vector<double> &) const;
    template void
    Discretisation<2>::cell_matrices(const DoFHandler<2>::level_cell_iterator &,
                                     FEValues<2> &,
                                     std::array<FullMatrix<double>, 3> &,
                                     Vector<double> &) const;
    template void
    Discretisation<3>::cell_matrices(const DoFHandler<3>::level_cell_iterator &,
                                     FEValues<3> &,
                                     std::array<FullMatrix<double>, 3> &,
                                     Vector<double> &) const;
  } // namespace physics
} // namespace rsfcycle
