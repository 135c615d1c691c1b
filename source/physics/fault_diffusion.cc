// SPDX-License-Identifier: LGPL-2.1-or-later
#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <rsfcycle/physics/fault_diffusion.h>
#include <stdexcept>
#include <string>

namespace rsfcycle
{
  namespace physics
  {
    namespace
    {
      void
      require(const bool holds, const std::string &what)
      {
        if (!holds)
          throw std::invalid_argument("FaultDiffusion: " + what);
      }
    } // namespace


    template <int plane_dim>
    FaultDiffusion<plane_dim>::FaultDiffusion(
      const FaultDiffusionParameters &parameters)
      : parameters(parameters)
      , fe(1)
      , dof_handler(triangulation)
    {
      using Source    = FaultDiffusionParameters::Source;
      const auto &p   = parameters;
      const bool  gs  = p.source == Source::gaussian;
      const bool  pw  = p.source == Source::well;
      const bool  all = p.compressibility > 0 && p.porosity > 0 &&
                       p.permeability > 0 && p.viscosity > 0 &&
                       p.thickness > 0 && p.half_width > 0 && p.cell_size > 0 &&
                       p.time_step > 0;
      require(all,
              "beta, phi, k, eta, L, l, h and the time step must be "
              "positive");
      require(p.snapshot_interval > 0, "the snapshot interval must be > 0");
      require(p.shut_in_time > 0, "t_off must be positive (inf: never)");
      require(std::isfinite(p.injection_rate), "Q0 must be finite");
      require(!gs || p.injection_width > 0, "L_inj must be positive");
      require(!pw || plane_dim == 2, "a Peaceman well needs the plane");
      require(!pw || (p.well_radius > 0 && p.well_storage > 0),
              "the well's radius and storage must be positive");

      if (std::isfinite(p.shut_in_time))
        {
          const double n = std::ceil(p.shut_in_time / p.time_step - 1e-9);
          require(n < 1e8, "t_off / time step is too large");
          dt = p.shut_in_time / std::max(1., n);
        }
      else
        dt = p.time_step;

      make_grid();
      setup_system();
      assemble_system();
      assemble_source();
      factorise();
      snapshots[0] = Vector<double>(n_unknowns);
      window.push_back({0, 0., snapshots[0]});
    }


    /**
     * [-l, l]^plane_dim in 2 l / h cells per direction; a source at the
     * origin needs an even number, so that the origin is a node.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::make_grid()
    {
      const double l     = parameters.half_width;
      const double ratio = 2 * l / parameters.cell_size;
      require(ratio < 1e6, "2 l / h is too large");
      n_cells = static_cast<unsigned int>(std::lround(ratio));
      require(n_cells >= 1 && std::abs(ratio - n_cells) <= 1e-9 * ratio,
              "2 l / h = " + std::to_string(ratio) + " is not an integer");
      require(parameters.source == FaultDiffusionParameters::Source::gaussian ||
                n_cells % 2 == 0,
              "2 l / h must be even for a source at the origin's node");
      GridGenerator::subdivided_hyper_cube(triangulation, n_cells, -l, l);
    }


    /**
     * The dofs, their lexicographic order (for the point evaluation), the
     * fixed rows and the sparsity of the system, whose last unknown is the
     * well's.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::setup_system()
    {
      dof_handler.distribute_dofs(fe);
      const unsigned int n_dofs = dof_handler.n_dofs();
      const double       h      = 2 * parameters.half_width / n_cells;
      node_dof.assign(n_dofs, numbers::invalid_dof_index);
      fixed.assign(n_dofs, false);
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          {
            unsigned int index = 0, stride = 1;
            bool         on_boundary = false;
            for (unsigned int d = 0; d < plane_dim; ++d)
              {
                const unsigned int i = static_cast<unsigned int>(std::lround(
                  (cell->vertex(v)[d] + parameters.half_width) / h));
                on_boundary          = on_boundary || i == 0 || i == n_cells;
                index += i * stride;
                stride *= n_cells + 1;
              }
            const auto dof  = cell->vertex_dof_index(v, 0);
            node_dof[index] = dof;
            fixed[dof]      = on_boundary &&
                         parameters.boundary ==
                           FaultDiffusionParameters::Boundary::fixed_pressure;
          }
      unsigned int centre = 0, stride = 1;
      for (unsigned int d = 0; d < plane_dim; ++d, stride *= n_cells + 1)
        centre += (n_cells / 2) * stride;
      origin_dof = node_dof[centre];

      const bool well =
        parameters.source == FaultDiffusionParameters::Source::well;
      n_unknowns = n_dofs + (well ? 1 : 0);
      fixed.resize(n_unknowns, false);
      DynamicSparsityPattern               dsp(n_unknowns);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            for (const auto j : dofs)
              dsp.add(i, j);
        }
      if (well)
        for (const auto i : {origin_dof, types::global_dof_index(n_dofs)})
          for (const auto j : {origin_dof, types::global_dof_index(n_dofs)})
            dsp.add(i, j);
      sparsity.copy_from(dsp);

      DynamicSparsityPattern gradient_dsp(n_dofs);
      DoFTools::make_sparsity_pattern(dof_handler, gradient_dsp);
      gradient_sparsity.copy_from(gradient_dsp);
    }


    /**
     * K = (k L / eta) (grad phi_j, grad phi_i) (2-point Gauss, exact on the
     * squares), the lumped mass m_i = int phi_i (the vertex quadrature), the
     * gradient's lumped projection (phi_i, d phi_j / dx_d) / m_i, the well's
     * coupling WI [1 -1; -1 1] between the origin's node and p_w.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::assemble_system()
    {
      const auto  &p              = parameters;
      const double transmissivity = p.permeability * p.thickness / p.viscosity;
      const unsigned int n_dofs   = dof_handler.n_dofs();
      stiffness.reinit(sparsity);
      for (auto &g : gradient)
        g.reinit(gradient_sparsity);
      lumped_mass.reinit(n_dofs);

      const QGauss<plane_dim>        gauss(2);
      const QGaussLobatto<plane_dim> lobatto(2);
      FEValues<plane_dim>            fe_values(
        fe, gauss, update_values | update_gradients | update_JxW_values);
      FEValues<plane_dim>                  fe_lumped(fe,
                                    lobatto,
                                    update_values | update_JxW_values);
      const unsigned int                   n = fe.n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_lumped.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n; ++i)
            {
              for (const unsigned int q : fe_lumped.quadrature_point_indices())
                lumped_mass(dofs[i]) +=
                  fe_lumped.shape_value(i, q) * fe_lumped.JxW(q);
              for (unsigned int j = 0; j < n; ++j)
                for (const unsigned int q :
                     fe_values.quadrature_point_indices())
                  {
                    const auto dx = fe_values.JxW(q);
                    stiffness.add(dofs[i],
                                  dofs[j],
                                  transmissivity *
                                    (fe_values.shape_grad(i, q) *
                                     fe_values.shape_grad(j, q)) *
                                    dx);
                    for (unsigned int d = 0; d < plane_dim; ++d)
                      gradient[d].add(dofs[i],
                                      dofs[j],
                                      fe_values.shape_value(i, q) *
                                        fe_values.shape_grad(j, q)[d] * dx);
                  }
            }
        }
      for (auto &g : gradient)
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (auto entry = g.begin(i); entry != g.end(i); ++entry)
            entry->value() /= lumped_mass(i);

      storage.reinit(n_unknowns);
      for (unsigned int i = 0; i < n_dofs; ++i)
        storage(i) =
          p.compressibility * p.porosity * p.thickness * lumped_mass(i);
      if (p.source == FaultDiffusionParameters::Source::well)
        {
          const double r_e = peaceman_factor * 2 * p.half_width / n_cells;
          require(r_e > p.well_radius,
                  "the cell size must exceed r_w / " +
                    std::to_string(peaceman_factor));
          index_of_well =
            2 * numbers::PI * transmissivity / std::log(r_e / p.well_radius);
          const types::global_dof_index w = n_dofs;
          stiffness.add(origin_dof, origin_dof, index_of_well);
          stiffness.add(w, w, index_of_well);
          stiffness.add(origin_dof, w, -index_of_well);
          stiffness.add(w, origin_dof, -index_of_well);
          storage(w) = p.well_storage;
        }
    }


    /**
     * f with sum_i f_i = 1: the Gaussian's (w, phi_i) (4-point Gauss),
     * scaled so that the plane takes exactly Q (the Gaussian's tail beyond
     * the domain and the quadrature's error, both small, go into the
     * scale); the origin's node; the well's unknown.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::assemble_source()
    {
      source_shape.reinit(n_unknowns);
      switch (parameters.source)
        {
          case FaultDiffusionParameters::Source::point:
            source_shape(origin_dof) = 1;
            break;
          case FaultDiffusionParameters::Source::well:
            source_shape(n_unknowns - 1) = 1;
            break;
            case FaultDiffusionParameters::Source::gaussian: {
              const double            s = parameters.injection_width;
              const QGauss<plane_dim> gauss(4);
              FEValues<plane_dim>     fe_values(fe,
                                            gauss,
                                            update_values |
                                              update_quadrature_points |
                                              update_JxW_values);
              std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
              for (const auto &cell : dof_handler.active_cell_iterators())
                {
                  fe_values.reinit(cell);
                  cell->get_dof_indices(dofs);
                  for (const unsigned int q :
                       fe_values.quadrature_point_indices())
                    {
                      const double r2 =
                        fe_values.quadrature_point(q).norm_square();
                      const double w =
                        std::exp(-r2 / (2 * s * s)) * fe_values.JxW(q);
                      for (unsigned int i = 0; i < dofs.size(); ++i)
                        source_shape(dofs[i]) +=
                          w * fe_values.shape_value(i, q);
                    }
                }
              double sum = 0;
              for (const double f : source_shape)
                sum += f;
              source_shape /= sum;
              break;
            }
        }
      for (unsigned int i = 0; i < n_unknowns; ++i)
        if (fixed[i])
          source_shape(i) = 0;
    }


    /**
     * The step matrices M + d dt K and M - d dt K, d = 1 - 1/sqrt(2), with
     * the rows of fixed pressures 1 and 0, and the first one's factor.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::factorise()
    {
      implicit_matrix.reinit(sparsity);
      explicit_matrix.reinit(sparsity);
      const double d = 1 - 1 / std::sqrt(2.);
      implicit_matrix.add(d * dt, stiffness);
      explicit_matrix.add(-d * dt, stiffness);
      for (unsigned int i = 0; i < n_unknowns; ++i)
        {
          if (fixed[i])
            {
              for (auto *matrix : {&implicit_matrix, &explicit_matrix})
                for (auto entry = matrix->begin(i); entry != matrix->end(i);
                     ++entry)
                  entry->value() = 0;
              implicit_matrix.set(i, i, 1.);
              storage(i) = 0;
              continue;
            }
          implicit_matrix.add(i, i, storage(i));
          explicit_matrix.add(i, i, storage(i));
        }
      solver.initialize(implicit_matrix);
    }


    /**
     * One step n -> n + 1 from the window's last state y with the source's
     * rate Q over the step, by TR-BDF2 with gamma = 2 - sqrt(2) and
     * d = 1 - 1/sqrt(2) (so that both stages have the matrix M + d dt K):
     * the trapezoidal rule to t_n + gamma dt,
     *   (M + d dt K) y_g = (M - d dt K) y + 2 d dt Q f,
     * then BDF2 through y, y_g and y',
     *   (M + d dt K) y' = M ((1 + sqrt 2)/2 y_g - (sqrt 2 - 1)/2 y) + d dt Q f.
     * Fixed rows stay zero (their rows of both matrices, of M and of f
     * are). The snapshot at every M-th step; the window keeps the states
     * from the last-but-one snapshot on.
     */
    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::advance() const
    {
      const unsigned int n = window.back().step;
      const double       q = parameters.rate((n + 0.5) * dt);
      const double       d = 1 - 1 / std::sqrt(2.);
      Vector<double>     rhs(n_unknowns), stage(n_unknowns), y(n_unknowns);
      explicit_matrix.vmult(rhs, window.back().y);
      rhs.add(2 * d * dt * q, source_shape);
      solver.vmult(stage, rhs);
      rhs = stage;
      rhs.sadd((1 + std::sqrt(2.)) / 2,
               -(std::sqrt(2.) - 1) / 2,
               window.back().y);
      rhs.scale(storage);
      rhs.add(d * dt * q, source_shape);
      solver.vmult(y, rhs);
      ++steps_computed;
      window.push_back({n + 1, (n + 1) * dt, y});

      const unsigned int m = parameters.snapshot_interval;
      if ((n + 1) % m == 0)
        {
          snapshots[n + 1] = y;
          while (window.front().step + m < n + 1)
            window.pop_front();
        }
    }


    template <int plane_dim>
    void
    FaultDiffusion<plane_dim>::restart_window(const unsigned int step) const
    {
      const auto snapshot = std::prev(snapshots.upper_bound(step));
      window.clear();
      window.push_back(
        {snapshot->first, snapshot->first * dt, snapshot->second});
    }


    /**
     * The state at t: the window made to reach t (restarted from the last
     * snapshot at or before t if t lies before the window or a later
     * snapshot is nearer), then linear interpolation between the two
     * stored states around t. Cached for the next question at the same t.
     */
    template <int plane_dim>
    const Vector<double> &
    FaultDiffusion<plane_dim>::state_at(const double t) const
    {
      if (!(t >= 0) || !std::isfinite(t))
        throw std::domain_error("FaultDiffusion: the time " +
                                std::to_string(t) + " is not in [0, inf)");
      if (t == cached_time)
        return cached_state;
      if (t / dt > 4e9)
        throw std::domain_error("FaultDiffusion: the time " +
                                std::to_string(t) + " is too late");
      const auto step = static_cast<unsigned int>(std::floor(t / dt));
      const auto last = std::prev(snapshots.upper_bound(step))->first;
      if (t < window.front().t || last > window.back().step)
        restart_window(step);
      while (window.back().t < t)
        advance();

      const auto after =
        std::lower_bound(window.begin(),
                         window.end(),
                         t,
                         [](const Node &node, const double time) {
                           return node.t < time;
                         });
      cached_state = after->y;
      if (after->t != t)
        {
          const auto   before = std::prev(after);
          const double theta  = (t - before->t) / (after->t - before->t);
          cached_state.sadd(theta, 1 - theta, before->y);
        }
      cached_time           = t;
      cached_gradient_valid = false;
      return cached_state;
    }


    template <int plane_dim>
    std::size_t
    FaultDiffusion<plane_dim>::memory_consumption() const
    {
      std::size_t bytes =
        triangulation.memory_consumption() + dof_handler.memory_consumption() +
        stiffness.memory_consumption() + implicit_matrix.memory_consumption() +
        explicit_matrix.memory_consumption() + sparsity.memory_consumption() +
        gradient_sparsity.memory_consumption();
      for (const auto &g : gradient)
        bytes += g.memory_consumption();
      for (const auto &snapshot : snapshots)
        bytes += snapshot.second.memory_consumption();
      for (const auto &node : window)
        bytes += node.y.memory_consumption();
      return bytes;
    }


    template class FaultDiffusion<1>;
    template class FaultDiffusion<2>;
  } // namespace physics
} // namespace rsfcycle
