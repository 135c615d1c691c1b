#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/array.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <chrono>
#include <cmath>
#include <csignal>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <rsfcycle/ids.h>
#include <rsfcycle/output/events.h>
#include <rsfcycle/problem_base.h>
#include <rsfcycle/solvers/amg_correction.h>
#include <rsfcycle/solvers/multigrid_correction.h>
#include <rsfcycle/time/rate_state_coupling.h>
#include <rsfcycle/time/step_doubling.h>

namespace rsfcycle
{
  template <int dim>
  ProblemBase<dim>::ProblemBase(const Parameters         &parameters,
                                const scenes::Scene<dim> &scene,
                                std::ostream             &log)
    : parameters(parameters)
    , scene(scene)
    , log(log)
    , timer(log, TimerOutput::never, TimerOutput::wall_times)
    , tria(Triangulation<dim>::limit_level_difference_at_vertices)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(tria)
    , scalar_fe(1)
    , scalar_dof_handler(tria)
    , state_law(friction::state_law_from_name(parameters.solver.state_law))
  {}


  template <int dim>
  ProblemBase<dim>::~ProblemBase()
  {
    dof_handler.clear();
    scalar_dof_handler.clear();
  }


  /**
   * The coarse mesh of the scene, refined globally and then locally: in
   * every local cycle the cells whose centre is closer to the patch than
   * `Refinement distance` times their diameter are refined, so the refined
   * zone shrinks with the level and the patch gets the finest cells.
   */
  template <int dim>
  void
  ProblemBase<dim>::make_grid()
  {
    scene.create_coarse_mesh(tria);
    tria.refine_global(parameters.mesh.global_refinements);
    for (unsigned int cycle = 0; cycle < parameters.mesh.local_refinements;
         ++cycle)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (scene.distance_to_patch(cell->center()) <
              parameters.mesh.refinement_distance * cell->diameter())
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(scene.material_id(cell->center()));
  }


  template <int dim>
  void
  ProblemBase<dim>::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    dof_handler.distribute_mg_dofs();
    scalar_dof_handler.distribute_dofs(scalar_fe);

    hanging_constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    scalar_constraints.clear();
    DoFTools::make_hanging_node_constraints(scalar_dof_handler,
                                            scalar_constraints);
    scalar_constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler,
                                    dsp,
                                    hanging_constraints,
                                    true);
    sparsity_pattern.copy_from(dsp);
    mass_matrix.reinit(sparsity_pattern);
    viscosity_matrix.reinit(sparsity_pattern);
    stiffness_matrix.reinit(sparsity_pattern);
    body_force.reinit(dof_handler.n_dofs());
  }


  /**
   * Mass M (density), viscosity C (Kelvin-Voigt, shear and bulk viscosity)
   * and stiffness K (bulk modulus, Poisson ratio) matrices and the gravity
   * load of one cell, active or on a multigrid level (the material is found
   * from the cell centre, so non-active cells get theirs too).
   * A stress of "the same form" is lambda tr(e) I + 2 mu e with
   * lambda = bulk - 2/3 shear.
   */
  template <int dim>
  template <class Iterator>
  void
  ProblemBase<dim>::cell_matrices(const Iterator                    &cell,
                                  FEValues<dim>                     &fe_values,
                                  std::array<FullMatrix<double>, 3> &matrices,
                                  Vector<double> &cell_force) const
  {
    const auto [bulk_modulus, nu] = scene.elastic_moduli();
    const double shear_modulus =
      3. * bulk_modulus * (1. - 2. * nu) / (2. * (1. + nu));
    const double           lambda  = bulk_modulus - 2. / 3. * shear_modulus;
    const Tensor<1, dim>   gravity = scene.gravity();
    const scenes::Material material =
      scene.material(scene.material_id(cell->center()));
    const double eta_lambda =
      material.bulk_viscosity - 2. / 3. * material.shear_viscosity;
    const FEValuesExtractors::Vector displacement(0);

    fe_values.reinit(cell);
    for (auto &matrix : matrices)
      matrix = 0;
    cell_force                                        = 0;
    auto &[cell_mass, cell_viscosity, cell_stiffness] = matrices;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        for (const unsigned int i : fe_values.dof_indices())
          {
            const Tensor<1, dim> phi_i = fe_values[displacement].value(i, q);
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
                                   fe_values[displacement].value(j, q) * JxW;
                cell_stiffness(i, j) +=
                  (lambda * div_i * div_j + 2. * shear_modulus * eps_eps) * JxW;
                cell_viscosity(i, j) +=
                  (eta_lambda * div_i * div_j +
                   2. * material.shear_viscosity * eps_eps) *
                  JxW;
              }
            cell_force(i) += material.density * gravity * phi_i * JxW;
          }
      }
  }


  /** M, C, K and the gravity load, with hanging nodes condensed. */
  template <int dim>
  void
  ProblemBase<dim>::assemble_matrices()
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
  }


  /**
   * The linear correction named in the parameters. Geometric multigrid
   * gets the level matrices from cell_matrices() and the lumped contact
   * weights of the active mesh.
   */
  template <int dim>
  void
  ProblemBase<dim>::setup_linear_correction()
  {
    const auto                      &solver = parameters.solver;
    solvers::LinearCorrectionControl control;
    control.max_cycles = solver.correction_cycles;
    control.tolerance  = solver.correction_tolerance;
    if (solver.linear_correction == "direct")
      linear_correction = std::make_unique<solvers::DirectCorrection>();
    else if (solver.linear_correction == "amg")
      {
        std::vector<unsigned int>            component(dof_handler.n_dofs());
        std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              component[indices[i]] = fe.system_to_component_index(i).first;
          }
        linear_correction =
          std::make_unique<solvers::AMGCorrection>(control, component);
      }
    else if (solver.linear_correction == "multigrid")
      {
        using MG = solvers::MultigridCorrection<dim>;
        std::vector<typename MG::DirichletBoundary> dirichlet = {
          {boundary_id::backstop, ComponentMask(dim, true)}};
        {
          std::vector<bool> normal(dim, false);
          normal[1] = true;
          dirichlet.push_back({boundary_id::contact, ComponentMask(normal)});
        }
        if (dim == 3)
          {
            std::vector<bool> lateral(dim, false);
            lateral[dim - 1] = true;
            dirichlet.push_back({boundary_id::lateral, ComponentMask(lateral)});
          }

        // Contact node -> vertex and components.
        std::map<types::global_dof_index, std::pair<unsigned int, unsigned int>>
          vertex_of_dof;
        for (const auto &cell : dof_handler.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == boundary_id::contact)
              for (const unsigned int v : cell->face(f)->vertex_indices())
                for (unsigned int c = 0; c < dim; ++c)
                  vertex_of_dof[cell->face(f)->vertex_dof_index(v, c)] = {
                    cell->face(f)->vertex_index(v), c};
        std::vector<typename MG::ContactVertex> vertices(contact.nodes.size());
        for (unsigned int k = 0; k < contact.nodes.size(); ++k)
          {
            const auto &node         = contact.nodes[k];
            vertices[k].vertex       = vertex_of_dof.at(node.dofs[0]).first;
            vertices[k].weight       = node_info[k].weight;
            vertices[k].n_components = node.n_dofs;
            for (unsigned int l = 0; l < node.n_dofs; ++l)
              vertices[k].components[l] = vertex_of_dof.at(node.dofs[l]).second;
          }

        const QGauss<dim> quadrature(fe.degree + 1);
        auto              fe_values = std::make_shared<FEValues<dim>>(
          fe, quadrature, update_values | update_gradients | update_JxW_values);
        auto force = std::make_shared<Vector<double>>(fe.n_dofs_per_cell());
        const auto level_cell_matrices =
          [this,
           fe_values,
           force](const typename MG::LevelCellIterator &cell,
                  std::array<FullMatrix<double>, 3>    &matrices) {
            cell_matrices(cell, *fe_values, matrices, *force);
          };
        const bool dynamic      = solver.dynamics == "dynamic";
        const auto coefficients = [dynamic](const double tau) {
          return std::array<double, 3>{{dynamic ? 2. / tau : 0., 1., tau / 2}};
        };
        typename MG::Settings settings;
        settings.smoothing_steps = solver.smoothing_steps;
        settings.control         = control;
        auto mg                  = std::make_unique<MG>(dof_handler,
                                       dirichlet,
                                       boundary_id::contact,
                                       vertices,
                                       level_cell_matrices,
                                       coefficients,
                                       settings);
        log << "Multigrid: " << mg->level_sizes().size()
            << " levels, dofs per level:";
        for (const auto n : mg->level_sizes())
          log << ' ' << n;
        log << std::endl;
        linear_correction = std::move(mg);
      }
    else
      throw std::invalid_argument(
        "Solver/Linear correction = " + solver.linear_correction +
        ": allowed are " + solvers::linear_correction_names());

    solvers::TNNMGControl tnnmg_control;
    tnnmg_control.max_iterations   = solver.max_tnnmg_iterations;
    tnnmg_control.truncation_ratio = solver.truncation_ratio;
    tnnmg = std::make_unique<solvers::TNNMG>(*linear_correction, tnnmg_control);
  }


  /**
   * Fixed dofs (backstop: all components; base: the normal component y;
   * lateral walls: z; hanging nodes), the contact nodes with their lumped
   * (trapezoidal) boundary weights w_i, condensed onto non-hanging nodes so
   * that the friction potential stays node-wise separable, and the
   * friction parameters of each node.
   */
  template <int dim>
  void
  ProblemBase<dim>::setup_contact()
  {
    const types::global_dof_index n_dofs = dof_handler.n_dofs();
    fixed.assign(n_dofs, false);
    backstop_dofs.clear();
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      if (hanging_constraints.is_constrained(i))
        fixed[i] = true;

    Vector<double>            weights(n_dofs);
    const QTrapezoid<dim - 1> trapezoid;
    FEFaceValues<dim> fe_face(fe, trapezoid, update_values | update_JxW_values);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    struct BaseVertex
    {
      Point<dim>              position;
      types::global_dof_index scalar_dof, normal_dof, lateral_dof;
    };
    std::map<types::global_dof_index, BaseVertex> base_vertices; // by x dof

    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (!face->at_boundary())
            continue;
          const types::boundary_id id = face->boundary_id();
          if (id == boundary_id::backstop)
            for (const unsigned int v : face->vertex_indices())
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const auto dof = face->vertex_dof_index(v, c);
                  if (!fixed[dof])
                    backstop_dofs.emplace_back(dof, c);
                  fixed[dof] = true;
                }
          else if (id == boundary_id::lateral && dim == 3)
            for (const unsigned int v : face->vertex_indices())
              fixed[face->vertex_dof_index(v, dim - 1)] = true;
          else if (id == boundary_id::contact)
            {
              const typename DoFHandler<dim>::active_cell_iterator scalar_cell(
                &tria, cell->level(), cell->index(), &scalar_dof_handler);
              for (const unsigned int v : face->vertex_indices())
                {
                  fixed[face->vertex_dof_index(v, 1)]         = true;
                  base_vertices[face->vertex_dof_index(v, 0)] = {
                    face->vertex(v),
                    scalar_cell->face(f)->vertex_dof_index(v, 0),
                    face->vertex_dof_index(v, 1),
                    face->vertex_dof_index(v, dim - 1)};
                }
              fe_face.reinit(cell, f);
              cell->get_dof_indices(dof_indices);
              for (const unsigned int i : fe_face.dof_indices())
                if (fe.system_to_component_index(i).first == 0)
                  for (const unsigned int q :
                       fe_face.quadrature_point_indices())
                    weights[dof_indices[i]] +=
                      fe_face.shape_value_component(i, q, 0) * fe_face.JxW(q);
            }
        }
    // backstop dofs that are hanging are set by distribute(), not directly
    backstop_dofs.erase(
      std::remove_if(backstop_dofs.begin(),
                     backstop_dofs.end(),
                     [&](const auto &d) {
                       return hanging_constraints.is_constrained(d.first);
                     }),
      backstop_dofs.end());
    hanging_constraints.condense(weights);

    // Contact nodes: base vertices with a free tangential component.
    contact.nodes.clear();
    node_info.clear();
    contact_area = 0;
    for (const auto &[x_dof, vertex] : base_vertices)
      {
        if (hanging_constraints.is_constrained(x_dof))
          continue;
        solvers::ContactNode                 node;
        std::vector<types::global_dof_index> tangential = {x_dof};
        if (dim == 3)
          tangential.push_back(vertex.lateral_dof);
        for (const auto dof : tangential)
          if (!fixed[dof])
            node.dofs[node.n_dofs++] = dof;
        if (node.n_dofs == 0)
          continue;
        NodeInfo info;
        info.position   = vertex.position;
        info.weight     = weights[x_dof];
        info.params     = scene.friction_parameters(vertex.position);
        info.scalar_dof = vertex.scalar_dof;
        info.normal_dof = vertex.normal_dof;
        contact.nodes.push_back(node);
        node_info.push_back(info);
        contact_area += info.weight;
      }
    contact.build_index(n_dofs);
  }


  /**
   * The initial displacement: static equilibrium under gravity with a
   * frictionless base (normal component fixed) and a fixed backstop. The
   * normal force of each contact node, w_i |sigma_n,i|, is the magnitude of
   * its normal reaction force, the residual K u - f of the y component.
   */
  template <int dim>
  void
  ProblemBase<dim>::compute_initial_state()
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
    SparseMatrix<double> K(sparsity_pattern);
    K.copy_from(stiffness_matrix);
    Vector<double> rhs(body_force);
    for (auto it = K.begin(); it != K.end(); ++it)
      if (fixed[it->row()] || fixed[it->column()])
        it->value() = (it->row() == it->column()) ? 1. : 0.;
    for (types::global_dof_index i = 0; i < rhs.size(); ++i)
      if (fixed[i])
        rhs[i] = 0;
    Vector<double>      u(dof_handler.n_dofs());
    SparseDirectUMFPACK direct;
    direct.initialize(K);
    direct.vmult(u, rhs);
    hanging_constraints.distribute(u);

    Vector<double> reaction(dof_handler.n_dofs());
    stiffness_matrix.vmult(reaction, u);
    reaction -= body_force;

    unsigned int n_tensile = 0;
    double       total     = 0;
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      total += reaction[node_info[k].normal_dof];
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      {
        const double r            = reaction[node_info[k].normal_dof];
        node_info[k].normal_force = std::abs(r);
        if (r * total < 0)
          ++n_tensile;
      }
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      if (!std::isfinite(node_info[k].normal_force))
        throw std::runtime_error(
          "non-finite normal stress from the gravity equilibrium at the base "
          "node at s = " +
          std::to_string(scene.along_base_coordinate(node_info[k].position)) +
          " m");
    if (n_tensile > 0)
      log << "Warning: " << n_tensile
          << " contact nodes carry a tensile normal reaction in the gravity "
             "equilibrium; their magnitude is used."
          << std::endl;

    initial.u = u;
    initial.v.reinit(dof_handler.n_dofs());
    initial.a.reinit(dof_handler.n_dofs());
    initial.alpha.assign(contact.nodes.size(), 0.);
    initial.shear_traction.assign(contact.nodes.size(), 0.);
  }


  template <int dim>
  void
  ProblemBase<dim>::setup()
  {
    {
      TimerOutput::Scope scope(timer, "Setup");
      make_grid();
      setup_system();
      setup_contact();
      assemble_matrices();
    }
    {
      TimerOutput::Scope scope(timer, "Normal stress");
      compute_initial_state();
    }
    {
      TimerOutput::Scope scope(timer, "Linear correction setup");
      setup_linear_correction();
    }

    // Observation points: u . vertical as a weighted sum of dofs.
    observation_weights.clear();
    const MappingQ1<dim> mapping;
    for (const auto &[name, point] : scene.observation_points())
      {
        const auto cell_and_point =
          GridTools::find_active_cell_around_point(mapping, dof_handler, point);
        const Quadrature<dim> q(
          GeometryInfo<dim>::project_to_unit_cell(cell_and_point.second));
        FEValues<dim> fe_values(mapping, fe, q, update_values);
        fe_values.reinit(cell_and_point.first);
        std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
        cell_and_point.first->get_dof_indices(indices);
        std::vector<std::pair<types::global_dof_index, double>> w;
        const Tensor<1, dim> up = scene.vertical();
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            w.emplace_back(indices[i], fe_values.shape_value(i, 0) * up[c]);
          }
        observation_weights.push_back(w);
      }
  }


  template <int dim>
  double
  ProblemBase<dim>::energy(const BodyState &state) const
  {
    return 0.5 * mass_matrix.matrix_norm_square(state.v) +
           0.5 * stiffness_matrix.matrix_norm_square(state.u) -
           body_force * state.u;
  }


  template <int dim>
  std::vector<double>
  ProblemBase<dim>::observed_uplift(const Vector<double> &u) const
  {
    // Hanging-node values are set in u (distribute), so the interpolation
    // may use any dof of the cell.
    std::vector<double> values;
    for (const auto &w : observation_weights)
      {
        double value = 0;
        for (const auto &[dof, weight] : w)
          value += weight * u[dof];
        values.push_back(value);
      }
    return values;
  }


  template <int dim>
  void
  ProblemBase<dim>::set_fixed_values(Vector<double> &v, const double t) const
  {
    const Tensor<1, dim> velocity = scene.backstop_velocity(t);
    for (const auto &[dof, component] : backstop_dofs)
      v[dof] = velocity[component];
  }


  /**
   * The step matrix A = 2/tau M + C + tau/2 K (quasi-static: without M), as
   * a linear combination of the matrices assembled once; the last few are
   * kept since step doubling alternates between tau/2, tau and 2 tau.
   */
  template <int dim>
  const SparseMatrix<double> &
  ProblemBase<dim>::step_matrix(const double tau)
  {
    for (auto &entry : step_matrices)
      if (entry.first == tau)
        return *entry.second;
    if (step_matrices.size() >= 4)
      step_matrices.erase(step_matrices.begin());
    auto A = std::make_unique<SparseMatrix<double>>(sparsity_pattern);
    A->copy_from(viscosity_matrix);
    A->add(tau / 2, stiffness_matrix);
    if (parameters.solver.dynamics == "dynamic")
      A->add(2. / tau, mass_matrix);
    step_matrices.emplace_back(tau, std::move(A));
    return *step_matrices.back().second;
  }


  template <int dim>
  double
  ProblemBase<dim>::state_distance(const std::vector<double> &alpha1,
                                   const std::vector<double> &alpha2) const
  {
    double sum = 0;
    for (unsigned int k = 0; k < alpha1.size(); ++k)
      {
        const double d = alpha1[k] - alpha2[k];
        sum += node_info[k].weight * d * d;
      }
    return std::sqrt(sum / contact_area);
  }


  template <int dim>
  std::vector<double>
  ProblemBase<dim>::slip_rates(const Vector<double> &v) const
  {
    std::vector<double> rates(contact.nodes.size());
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      {
        rates[k] = solvers::tangential_norm(contact.nodes[k], v);
      }
    return rates;
  }


  /**
   * One Newmark step (15) with the rate/state fixed-point iteration (18):
   * theta^0 = theta_{n-1}; v^k = TNNMG solution with theta^{k-1};
   * theta^k from (17) with V = |(v_{n-1} + v^k)/2|; stop at
   * d(theta^k, theta^{k-1}) <= epsilon. With explicit coupling, the state is
   * updated once from V = |v_{n-1}| and one spatial problem is solved.
   */
  template <int dim>
  std::optional<BodyState>
  ProblemBase<dim>::newmark_step(const BodyState &old,
                                 const double     t,
                                 const double     tau)
  {
    const bool dynamic            = parameters.solver.dynamics == "dynamic";
    const SparseMatrix<double> &A = step_matrix(tau);
    const unsigned int          n_nodes = contact.nodes.size();

    Vector<double> rhs(body_force), tmp(old.u);
    tmp.add(tau / 2, old.v);
    Vector<double> Ku(rhs.size());
    stiffness_matrix.vmult(Ku, tmp);
    rhs -= Ku;
    if (dynamic)
      {
        tmp = old.a;
        tmp.add(2. / tau, old.v);
        Vector<double> Mv(rhs.size());
        mass_matrix.vmult(Mv, tmp);
        rhs += Mv;
      }

    BodyState next;
    next.v = old.v;
    set_fixed_values(next.v, t + tau);
    hanging_constraints.distribute(next.v);

    std::vector<friction::NodePotential> potentials(n_nodes);
    const double                         cohesion = scene.cohesion();
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        potentials[k].params         = node_info[k].params;
        potentials[k].normal_force   = node_info[k].normal_force;
        potentials[k].cohesion_force = node_info[k].weight * cohesion;
      }
    solvers::SpatialProblem problem;
    problem.A          = &A;
    problem.rhs        = &rhs;
    problem.fixed      = &fixed;
    problem.contact    = &contact;
    problem.potentials = &potentials;
    problem.matrix_key = tau;

    const auto update_state = [&](const Vector<double> &v_new,
                                  const double          weight_new,
                                  std::vector<double>  &alpha) {
      for (unsigned int k = 0; k < n_nodes; ++k)
        {
          double vm[2] = {0, 0};
          for (unsigned int l = 0; l < contact.nodes[k].n_dofs; ++l)
            {
              const auto dof = contact.nodes[k].dofs[l];
              vm[l] = (1 - weight_new) * old.v[dof] + weight_new * v_new[dof];
            }
          alpha[k] = friction::update_state(state_law,
                                            node_info[k].params,
                                            old.alpha[k],
                                            std::hypot(vm[0], vm[1]),
                                            tau);
        }
    };

    // The rate/state coupling (18) is the generic one of
    // time/rate_state_coupling.h; the velocity solve is TNNMG.
    const bool explicit_coupling = parameters.solver.coupling == "explicit";
    // Inexact fixed point (`Inner tolerance factor`); a cap of one
    // fixed-point iteration needs that one solve at TNNMG tolerance.
    const bool inexact = !explicit_coupling &&
                         parameters.solver.inner_tolerance_factor >
                           parameters.solver.tnnmg_tolerance &&
                         parameters.solver.max_fixed_point_iterations > 1;
    std::vector<double> alpha = old.alpha;
    unsigned int        k     = 0;
    double              d     = 0;
    std::string         failure;
    const auto          solve_velocity = [&](const std::vector<double> &alpha_k,
                                    Vector<double>            &v) {
      ++k;
      for (unsigned int i = 0; i < n_nodes; ++i)
        potentials[i].alpha = alpha_k[i];
      // Inexact fixed point: the early iterations, whose state is still
      // far from converged, get a looser TNNMG tolerance (d is the state
      // distance of the previous iteration; d_0 = 1).
      const double inner_tolerance =
        inexact ? std::max(parameters.solver.tnnmg_tolerance,
                           parameters.solver.inner_tolerance_factor *
                             (k == 1 ? 1. : d)) :
                           parameters.solver.tnnmg_tolerance;
      const solvers::TNNMGStatistics stats =
        tnnmg->solve(problem, v, inner_tolerance);
      next.statistics.fixed_point_iterations = k;
      next.statistics.tnnmg_iterations += stats.iterations;
      next.statistics.linear_iterations += stats.linear_iterations;
      work.tnnmg_iterations += stats.iterations;
      work.linear_iterations += stats.linear_iterations;
      if (!stats.converged)
        {
          std::ostringstream why;
          why << "t = " << t + tau << " s, step " << tau << " s: TNNMG "
              << (std::isfinite(stats.relative_change) ?
                             "did not converge (relative change " :
                             "produced non-finite values (relative change ")
              << stats.relative_change << " after " << stats.iterations
              << " iterations) in fixed-point iteration " << k << "; "
              << first_non_finite(v);
          failure = why.str();
        }
      return stats.converged;
    };
    const auto coupled = time::couple_rate_and_state(
      explicit_coupling ? time::Coupling::explicit_decoupling :
                          time::Coupling::fixed_point,
      parameters.solver.fixed_point_tolerance,
      parameters.solver.max_fixed_point_iterations,
      old.v,
      next.v,
      alpha,
      solve_velocity,
      update_state,
      [this](const std::vector<double> &a1, const std::vector<double> &a2) {
        return state_distance(a1, a2);
      },
      &d,
      // a first solve at the loose tolerance factor * 1 is never accepted
      inexact ? 2 : 1);
    if (!coupled)
      {
        if (failure.empty())
          {
            std::ostringstream why;
            why << "t = " << t + tau << " s, step " << tau << " s: ";
            if (!std::isfinite(d))
              why << "non-finite state distance; " << first_non_finite(next.v);
            else
              why << "the fixed-point iteration did not converge in " << k
                  << " iterations (state distance " << d
                  << " > Fixed-point tolerance)";
            failure = why.str();
          }
        last_failure = failure;
        return {};
      }

    hanging_constraints.distribute(next.v);
    next.alpha = alpha;
    next.u     = old.u;
    next.u.add(tau / 2, old.v, tau / 2, next.v);
    if (dynamic)
      {
        next.a = next.v;
        next.a -= old.v;
        next.a *= 2. / tau;
        next.a -= old.a;
      }
    else
      next.a.reinit(old.a.size());

    // Friction force per node from the equilibrium, r - A v (tangential).
    Vector<double> residual(rhs.size());
    A.residual(residual, next.v, rhs);
    next.shear_traction.resize(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        double f2 = 0;
        for (unsigned int l = 0; l < contact.nodes[k].n_dofs; ++l)
          f2 += residual[contact.nodes[k].dofs[l]] *
                residual[contact.nodes[k].dofs[l]];
        next.shear_traction[k] = std::sqrt(f2) / node_info[k].weight;
      }

    if (!std::isfinite(next.u.l2_norm()) || !std::isfinite(next.v.l2_norm()) ||
        !std::isfinite(next.a.l2_norm()))
      {
        last_failure = "t = " + std::to_string(t + tau) +
                       " s: non-finite displacement, velocity or "
                       "acceleration; " +
                       first_non_finite(next.v);
        return {};
      }
    for (unsigned int k = 0; k < n_nodes; ++k)
      if (!std::isfinite(next.alpha[k]))
        {
          last_failure =
            "t = " + std::to_string(t + tau) +
            " s: non-finite friction state at the base node at s = " +
            std::to_string(scene.along_base_coordinate(node_info[k].position)) +
            " m";
          return {};
        }
    return next;
  }


  template <int dim>
  std::string
  ProblemBase<dim>::first_non_finite(const Vector<double> &v) const
  {
    for (unsigned int k = 0; k < contact.nodes.size(); ++k)
      for (unsigned int l = 0; l < contact.nodes[k].n_dofs; ++l)
        if (!std::isfinite(v[contact.nodes[k].dofs[l]]))
          return "non-finite slip rate at the base node at s = " +
                 std::to_string(
                   scene.along_base_coordinate(node_info[k].position)) +
                 " m";
    for (types::global_dof_index i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i]))
        return "non-finite velocity in the interior (dof " + std::to_string(i) +
               ")";
    return "all velocities finite";
  }


  namespace
  {
    /** DataOutFaces restricted to the faces of one boundary (the fault). */
    template <int dim>
    class BoundaryFaces : public DataOutFaces<dim>
    {
    public:
      using FaceDescriptor = typename DataOutFaces<dim>::FaceDescriptor;

      explicit BoundaryFaces(const types::boundary_id id)
        : id(id)
      {}

      FaceDescriptor
      first_face() override
      {
        for (const auto &cell : this->triangulation->active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (is_selected(cell, f))
              return {cell, f};
        return {};
      }

      FaceDescriptor
      next_face(const FaceDescriptor &face) override
      {
        auto         cell = face.first;
        unsigned int f    = face.second + 1;
        while (cell != this->triangulation->end())
          {
            for (; f < cell->n_faces(); ++f)
              if (is_selected(cell, f))
                return {cell, f};
            ++cell;
            while (cell != this->triangulation->end() && !cell->is_active())
              ++cell;
            f = 0;
          }
        return {};
      }

    private:
      bool
      is_selected(const typename Triangulation<dim>::cell_iterator &cell,
                  const unsigned int                                f) const
      {
        return cell->is_active() && cell->face(f)->at_boundary() &&
               cell->face(f)->boundary_id() == id;
      }

      const types::boundary_id id;
    };
  } // namespace


  template <int dim>
  void
  ProblemBase<dim>::output_results(const BodyState &state, const double t)
  {
    TimerOutput::Scope        scope(timer, "Output");
    const unsigned int        n_nodes = contact.nodes.size();
    const std::vector<double> rates   = slip_rates(state.v);
    Vector<double>            slip_rate(scalar_dof_handler.n_dofs()),
      log_slip_rate(scalar_dof_handler.n_dofs()),
      theta(scalar_dof_handler.n_dofs()), mu(scalar_dof_handler.n_dofs()),
      traction(scalar_dof_handler.n_dofs()),
      normal_stress(scalar_dof_handler.n_dofs()),
      rate_minus_v0(scalar_dof_handler.n_dofs()),
      slip_um(scalar_dof_handler.n_dofs());
    const double v0 = scene.convergence_rate();
    log_slip_rate   = std::log10(1e-20);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        const auto &info   = node_info[k];
        const auto  dof    = info.scalar_dof;
        slip_rate[dof]     = rates[k];
        log_slip_rate[dof] = std::log10(std::max(rates[k] / v0, 1e-20));
        theta[dof] =
          info.params.L / info.params.v_star * std::exp(state.alpha[k]);
        mu[dof] =
          friction::friction_coefficient(info.params, state.alpha[k], rates[k]);
        traction[dof]      = state.shear_traction[k];
        normal_stress[dof] = info.normal_force / info.weight;
        rate_minus_v0[dof] = rates[k] - v0;
        slip_um[dof] =
          1e6 * solvers::tangential_norm(contact.nodes[k], state.u);
      }
    for (auto *vec : {&slip_rate,
                      &theta,
                      &mu,
                      &traction,
                      &normal_stress,
                      &rate_minus_v0,
                      &slip_um})
      scalar_constraints.distribute(*vec);

    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_part(dim,
                  DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(state.u,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector_part);
    data_out.add_data_vector(state.v,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data,
                             vector_part);
    data_out.add_data_vector(scalar_dof_handler, slip_rate, "slip_rate");
    data_out.add_data_vector(scalar_dof_handler,
                             log_slip_rate,
                             "log10_slip_rate_over_v0");
    data_out.add_data_vector(scalar_dof_handler, theta, "state");
    data_out.add_data_vector(scalar_dof_handler, mu, "friction_coefficient");
    data_out.add_data_vector(scalar_dof_handler, traction, "shear_traction");
    data_out.add_data_vector(scalar_dof_handler,
                             normal_stress,
                             "normal_stress");
    Vector<float> material(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      material[cell->active_cell_index()] = cell->material_id();
    data_out.add_data_vector(material, "material_id");
    data_out.build_patches();

    DataOutBase::VtkFlags flags;
    flags.time  = t;
    flags.cycle = n_snapshots;
    data_out.set_flags(flags);
    const std::string name =
      "solution-" + Utilities::int_to_string(n_snapshots, 5) + ".vtu";
    std::ofstream vtu(parameters.run.output_directory + "/solution/" + name);
    data_out.write_vtu(vtu);
    pvd_records.emplace_back(t, "solution/" + name);
    std::ofstream pvd(parameters.run.output_directory + "/solution.pvd");
    DataOutBase::write_pvd_record(pvd, pvd_records);

    // The fault (contact faces) at the same times: fault/fault-NNNNN.vtu,
    // fault.pvd (the paper's figure 9 draws isolines of V - v0 on it).
    BoundaryFaces<dim> fault(boundary_id::contact);
    fault.attach_dof_handler(scalar_dof_handler);
    fault.add_data_vector(rate_minus_v0, "slip_rate_minus_v0");
    fault.add_data_vector(log_slip_rate, "log10_slip_rate_over_v0");
    fault.add_data_vector(theta, "state");
    fault.add_data_vector(slip_um, "slip_um");
    fault.add_data_vector(traction, "shear_traction");
    fault.add_data_vector(mu, "friction_coefficient");
    fault.build_patches();
    fault.set_flags(flags);
    std::ofstream fault_vtu(parameters.run.output_directory + "/fault/fault-" +
                            Utilities::int_to_string(n_snapshots, 5) + ".vtu");
    fault.write_vtu(fault_vtu);
    std::vector<std::pair<double, std::string>> fault_records;
    for (unsigned int i = 0; i < pvd_records.size(); ++i)
      fault_records.emplace_back(pvd_records[i].first,
                                 "fault/fault-" +
                                   Utilities::int_to_string(i, 5) + ".vtu");
    std::ofstream fault_pvd(parameters.run.output_directory + "/fault.pvd");
    DataOutBase::write_pvd_record(fault_pvd, fault_records);
    ++n_snapshots;
  }


  namespace
  {
    std::string
    format_duration(double seconds)
    {
      std::ostringstream s;
      const long         total = static_cast<long>(seconds);
      s << total / 3600 << "h" << std::setw(2) << std::setfill('0')
        << (total / 60) % 60 << "m" << std::setw(2) << total % 60 << "s";
      return s.str();
    }
  } // namespace


  namespace
  {
    volatile std::sig_atomic_t stop_signal = 0;

    extern "C" void
    handle_stop_signal(int signal)
    {
      stop_signal = signal;
    }
  } // namespace


  template <int dim>
  void
  ProblemBase<dim>::write_checkpoint(const std::string &dir,
                                     const RunState    &run_state) const
  {
    // temporary file + rename: the previous checkpoint survives until the
    // new one is complete
    const std::string tmp = dir + "/checkpoint.tmp";
    {
      std::ofstream                   out(tmp, std::ios::binary);
      boost::archive::binary_oarchive archive(out);
      const types::global_dof_index   n_dofs = dof_handler.n_dofs();
      archive << n_dofs << run_state << n_snapshots << pvd_records;
      out.flush();
      if (!out)
        throw std::runtime_error("cannot write the checkpoint " + tmp);
    }
    std::filesystem::rename(tmp, dir + "/checkpoint.bin");
  }


  template <int dim>
  void
  ProblemBase<dim>::read_checkpoint(const std::string &dir, RunState &run_state)
  {
    std::ifstream in(dir + "/checkpoint.bin", std::ios::binary);
    if (!in)
      throw std::invalid_argument("--resume " + dir +
                                  ": no checkpoint.bin in this folder");
    boost::archive::binary_iarchive archive(in);
    types::global_dof_index         n_dofs;
    archive >> n_dofs;
    if (n_dofs != dof_handler.n_dofs())
      throw std::invalid_argument(
        "--resume " + dir +
        ": the checkpoint belongs to a different mesh (parameters changed?)");
    archive >> run_state >> n_snapshots >> pvd_records;
  }


  template <int dim>
  bool
  ProblemBase<dim>::run(const ParameterHandler &prm, const bool resume)
  {
    const std::string dir = parameters.run.output_directory;
    std::filesystem::create_directories(dir + "/solution");
    std::filesystem::create_directories(dir + "/fault");
    if (!resume)
      {
        std::ofstream out(dir + "/parameters.prm");
        prm.print_parameters(out, ParameterHandler::PRM);
      }

    setup();
    const unsigned int n_nodes = contact.nodes.size();
    log << "Scene: " << parameters.run.scene << " (" << dim << "D)\n"
        << "Mesh: " << tria.n_active_cells() << " cells, "
        << tria.n_global_levels() << " levels, " << dof_handler.n_dofs()
        << " unknowns, " << n_nodes << " contact nodes\n";
    {
      double h_min = 1e300, h_max = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          h_min = std::min(h_min, cell->diameter());
          h_max = std::max(h_max, cell->diameter());
        }
      log << "Cell diameters: " << h_min << " m to " << h_max << " m\n";
    }
    log << "Solver: " << parameters.solver.coupling << " coupling, "
        << parameters.solver.linear_correction << " linear correction, "
        << parameters.solver.state_law << " law, " << parameters.solver.dynamics
        << std::endl;

    // Base profile: node order along the base.
    std::vector<unsigned int> order(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      order[k] = k;
    std::sort(order.begin(), order.end(), [&](unsigned int i, unsigned int j) {
      const double si = scene.along_base_coordinate(node_info[i].position);
      const double sj = scene.along_base_coordinate(node_info[j].position);
      if (si != sj)
        return si < sj;
      return (dim == 3) &&
             node_info[i].position[dim - 1] < node_info[j].position[dim - 1];
    });

    const double end_time  = parameters.run.end_time;
    const double v0        = scene.convergence_rate();
    const double threshold = parameters.output.event_threshold * v0;

    std::vector<double> along_base(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      along_base[k] = scene.along_base_coordinate(node_info[k].position);

    // Everything the time loop carries from step to step: what a checkpoint
    // holds (with the output counters and the PVD record, members).
    RunState run_state(output::EventDetector(threshold, v0, along_base));
    run_state.state   = initial;
    run_state.tau     = parameters.time_stepping.initial_step;
    BodyState &state  = run_state.state;
    double    &t      = run_state.t;
    auto      &events = run_state.events;

    std::ofstream series, profile, catalogue;
    if (resume)
      {
        read_checkpoint(dir, run_state);
        // drop what was written after the checkpoint, then append
        std::filesystem::resize_file(dir + "/time-series.csv",
                                     run_state.series_bytes);
        std::filesystem::resize_file(dir + "/base-profile.csv",
                                     run_state.profile_bytes);
        std::filesystem::resize_file(dir + "/events.csv",
                                     run_state.catalogue_bytes);
        series.open(dir + "/time-series.csv", std::ios::app);
        profile.open(dir + "/base-profile.csv", std::ios::app);
        catalogue.open(dir + "/events.csv", std::ios::app);
        log << "Resumed from the checkpoint at t = " << t << " s, step "
            << run_state.step << std::endl;
      }
    else
      {
        series.open(dir + "/time-series.csv");
        series << "time_s,step_size_s,fixed_point_iterations,tnnmg_iterations,"
                  "linear_iterations,spatial_problems,max_slip_rate_m_per_s";
        for (const auto &p : scene.observation_points())
          series << "," << p.first << "_m";
        series << ",all_tnnmg_iterations,all_linear_iterations\n";

        profile.open(dir + "/base-profile.csv");
        profile << "# slip rate [m/s] of the contact nodes; first row: "
                   "position along the base [m]"
                << (dim == 3 ? " (then the z coordinate in the second row)" :
                               "")
                << "\n"
                << "time_s";
        for (const unsigned int k : order)
          profile << "," << along_base[k];
        profile << "\n";
        if (dim == 3)
          {
            profile << "z_m";
            for (const unsigned int k : order)
              profile << "," << node_info[k].position[dim - 1];
            profile << "\n";
          }
        catalogue.open(dir + "/events.csv");
        catalogue << output::EventDetector::csv_header() << "\n";
      }
    series << std::setprecision(10);
    profile << std::setprecision(8);

    time::StepDoubling<BodyState> controller(
      [this](const BodyState &s, const double t0, const double dt) {
        return newmark_step(s, t0, dt);
      },
      [this](const BodyState &s1, const BodyState &s2) {
        return state_distance(s1.alpha, s2.alpha);
      },
      parameters.time_stepping.tolerance,
      run_state.tau,
      parameters.time_stepping.minimum_step,
      parameters.time_stepping.maximum_step,
      parameters.time_stepping.adaptive);

    if (resume && run_state.has_candidate)
      controller.set_candidate(run_state.candidate);

    const auto write_profile = [&](const double               time,
                                   const std::vector<double> &rates) {
      profile << time;
      for (const unsigned int k : order)
        profile << "," << rates[k];
      profile << "\n";
    };
    const auto tangential_displacement = [&](const Vector<double> &u) {
      std::vector<std::array<double, 2>> slip(n_nodes, {{0., 0.}});
      for (unsigned int k = 0; k < n_nodes; ++k)
        for (unsigned int l = 0; l < contact.nodes[k].n_dofs; ++l)
          slip[k][l] = u[contact.nodes[k].dofs[l]];
      return slip;
    };
    if (!resume)
      {
        if (parameters.output.write_vtu)
          output_results(state, t);
        write_profile(t, slip_rates(state.v));
        events.update(0.,
                      slip_rates(state.v),
                      tangential_displacement(state.u));
      }

    const auto checkpoint = [&]() {
      TimerOutput::Scope scope(timer, "Checkpoint");
      series.flush();
      profile.flush();
      catalogue.flush();
      run_state.series_bytes    = series.tellp();
      run_state.profile_bytes   = profile.tellp();
      run_state.catalogue_bytes = catalogue.tellp();
      run_state.tau             = controller.step_size();
      run_state.has_candidate   = controller.candidate().has_value();
      if (run_state.has_candidate)
        run_state.candidate = *controller.candidate();
      write_checkpoint(dir, run_state);
      run_state.candidate = BodyState();
    };

    unsigned int &step            = run_state.step;
    unsigned int &max_fixed_point = run_state.max_fixed_point;
    auto         &total_problems  = run_state.total_problems;
    double       &min_dt = run_state.min_dt, &max_dt = run_state.max_dt;
    double       &last_output   = run_state.last_output;
    double       &last_profile  = run_state.last_profile;
    const auto    wall_start    = std::chrono::steady_clock::now();
    auto          last_progress = wall_start, last_checkpoint = wall_start;
    const double  t_start         = t;
    bool          stop_for_events = false;
    stop_signal                   = 0;
    const auto old_int            = std::signal(SIGINT, handle_stop_signal);
    const auto old_term           = std::signal(SIGTERM, handle_stop_signal);

    log << "*** Time loop to t = " << end_time << " s" << std::endl;
    {
      TimerOutput::Scope scope(timer, "Time stepping");
      // t is a sum of step sizes: stop within round-off of the end time
      while (end_time - t > 1e-10 * end_time)
        {
          try
            {
              controller.advance(state, t, end_time);
            }
          catch (const time::StepSizeUnderflow &e)
            {
              log << "Error: at t = " << t << " s: " << e.what()
                  << "\nLast failed spatial problem: " << last_failure
                  << std::endl;
              checkpoint();
              log << "A checkpoint of the last accepted state (t = " << t
                  << " s) is in " << dir << std::endl;
              std::signal(SIGINT, old_int);
              std::signal(SIGTERM, old_term);
              throw;
            }
          ++step;
          total_problems += controller.n_spatial_problems();
          const double dt = controller.last_step_size();
          min_dt          = std::min(min_dt, dt);
          max_dt          = std::max(max_dt, dt);
          max_fixed_point =
            std::max(max_fixed_point, state.statistics.fixed_point_iterations);

          const std::vector<double> rates = slip_rates(state.v);
          const auto   max_it   = std::max_element(rates.begin(), rates.end());
          const double max_rate = (max_it == rates.end()) ? 0. : *max_it;
          const bool   was_in_event = events.in_event();
          if (events.update(t, rates, tangential_displacement(state.u)))
            {
              const auto &e = events.events().back();
              output::EventDetector::write_csv_row(catalogue,
                                                   events.events().size(),
                                                   e);
              catalogue.flush();
              log << "    event " << events.events().size()
                  << " ended at t = " << t << " s: peak slip rate "
                  << e.peak_slip_rate / v0 << " v0, rupture width "
                  << e.rupture_width() << " m, slip " << e.slip * 1e6 << " um"
                  << std::endl;
              stop_for_events =
                parameters.run.stop_after_events > 0 &&
                events.events().size() >= parameters.run.stop_after_events;
            }
          if (!was_in_event && events.in_event())
            log << "    event " << events.n_started() << " starts at t = " << t
                << " s near s = " << events.current().nucleation_position
                << " m along the base" << std::endl;
          const bool in_event = events.in_event();

          const std::vector<double> uplift = observed_uplift(state.u);
          series << t << "," << dt << ","
                 << state.statistics.fixed_point_iterations << ","
                 << state.statistics.tnnmg_iterations << ","
                 << state.statistics.linear_iterations << ","
                 << controller.n_spatial_problems() << "," << max_rate;
          for (const double z : uplift)
            series << "," << z;
          // the work of every spatial problem solved for this step, the
          // step-doubling comparisons and rejected attempts included
          series << "," << work.tnnmg_iterations << ","
                 << work.linear_iterations << "\n";
          work = StepStatistics();

          // Profiles densely while slip is fast (events and the afterslip
          // around them: max V > 2 v0), else at their interval.
          const double eps  = 1e-12 * std::max(1., t);
          const bool   fast = in_event || max_rate > 2 * v0;
          if (t >= last_profile +
                     (fast ? parameters.output.event_profile_interval :
                             parameters.output.profile_interval) -
                     eps)
            {
              write_profile(t, rates);
              last_profile = t;
            }
          if (parameters.output.write_vtu &&
              t >= last_output +
                     (in_event ? parameters.output.event_output_interval :
                                 parameters.output.output_interval) -
                     eps)
            {
              output_results(state, t);
              last_output = t;
            }

          const auto   now = std::chrono::steady_clock::now();
          const double since =
            std::chrono::duration<double>(now - last_progress).count();
          if (since >= parameters.output.progress_interval || t >= end_time)
            {
              last_progress = now;
              const double elapsed =
                std::chrono::duration<double>(now - wall_start).count();
              const double eta = elapsed / (t - t_start) * (end_time - t);
              log << "*** Step " << step << ": t = " << std::setprecision(6)
                  << t << " s / " << end_time << " s, dt = " << dt
                  << " s, max V = " << max_rate / v0
                  << " v0, events = " << events.n_started() << ", wall "
                  << format_duration(elapsed) << ", ETA "
                  << format_duration(eta) << "\n"
                  << "    solver: " << state.statistics.fixed_point_iterations
                  << " fixed-point, " << state.statistics.tnnmg_iterations
                  << " TNNMG, " << state.statistics.linear_iterations
                  << " linear iterations; " << controller.n_spatial_problems()
                  << " spatial problems this step" << std::endl;
              series.flush();
              profile.flush();
            }

          const bool checkpoint_due =
            (parameters.output.checkpoint_steps > 0 &&
             step % parameters.output.checkpoint_steps == 0) ||
            (parameters.output.checkpoint_minutes > 0 &&
             std::chrono::duration<double>(now - last_checkpoint).count() >=
               60 * parameters.output.checkpoint_minutes);
          if (checkpoint_due || stop_signal != 0)
            {
              checkpoint();
              last_checkpoint = now;
            }
          if (stop_signal != 0)
            {
              log << "Stopped by signal " << stop_signal << " at t = " << t
                  << " s; checkpoint written. Continue with: rsfcycle "
                     "--resume "
                  << dir << std::endl;
              timer.print_summary();
              std::signal(SIGINT, old_int);
              std::signal(SIGTERM, old_term);
              return false;
            }
          if (stop_for_events)
            {
              log << "*** Stop after events = "
                  << parameters.run.stop_after_events
                  << " reached: the run ends at t = " << t << " s" << std::endl;
              break;
            }
        }
    }
    std::signal(SIGINT, old_int);
    std::signal(SIGTERM, old_term);
    checkpoint();
    if (parameters.output.write_vtu && pvd_records.back().first < t)
      output_results(state, t);

    log << "Summary: " << step << " steps, " << total_problems
        << " spatial problems, " << events.n_started() << " events, step size "
        << min_dt << " s to " << max_dt << " s, max fixed-point iterations "
        << max_fixed_point << std::endl;
    {
      std::ostringstream summary;
      events.write_summary(summary,
                           parameters.output.transition_time,
                           parameters.output.transition_events);
      log << summary.str();
      std::ofstream(dir + "/summary.txt")
        << "Steps: " << step << "\nSpatial problems: " << total_problems
        << "\nStep size: " << min_dt << " s to " << max_dt
        << " s\nMax fixed-point iterations per step: " << max_fixed_point
        << "\n"
        << summary.str();
    }
    timer.print_summary();
    return true;
  }

  template class ProblemBase<2>;
  template class ProblemBase<3>;
} // namespace rsfcycle
