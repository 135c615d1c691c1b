// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_explicit_step_h
#define rsfcycle_models_explicit_step_h

#include <deal.II/base/point.h>
#include <functional>
#include <optional>
#include <rsfcycle/friction/law.h>
#include <rsfcycle/la.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    /**
     * One explicit step of the elastic continuum with inertia (`Time
     * stepping/Integrator = explicit`): Newmark's explicit member (beta =
     * 0, gamma = 1/2, central differences) with the lumped mass M_L (the
     * row sums of M) and the diagonal damping C (the absorbing faces'
     * lumped dashpots),
     *   u_{n+1} = u_n + tau v_n + tau^2/2 a_n,   v* = v_n + tau/2 a_n,
     *   (2/tau M_L + C) v_{n+1} = (2/tau M_L + C) v* + f - K u_{n+1} - C v*
     *                             - the friction force,
     *   a_{n+1} = 2 (v_{n+1} - v*) / tau,
     * every dof on its own: K is applied as a product, and on a contact
     * node the slip rate solves the node-local problem of the implicit
     * path's Gauss-Seidel sweep (friction::solve_local_problem) with the
     * node's friction potential at the state of t_{n+1}. The state takes
     * the law's closed-form update with the mean slip rate of the step, in
     * two passes (the state from the old slip rate, the slip rate, the
     * state from the mean, the slip rate again). The state (u, v, a,
     * alpha) is the implicit step's, so that a run may take either.
     *
     * Stable for tau <= stable_step() = 2/omega_max: omega_max^2, the
     * largest eigenvalue of M_L^-1 K, is bounded from above by the largest
     * of every cell's K_e x = lambda M_L,e x (the element eigenvalue
     * theorem; sharp on a uniform mesh).
     */
    template <int dim>
    class ExplicitStep
    {
    public:
      /**
       * `along_base` gives the position along the base [m] that diagnoses
       * name.
       */
      ExplicitStep(
        const physics::Discretisation<dim>               &discretisation,
        const physics::ContactQuadrature<dim>            &contact,
        const friction::Law                              &law,
        std::function<double(const dealii::Point<dim> &)> along_base);

      /** 2/omega_max [s] (collective at construction). */
      double
      stable_step() const
      {
        return stable;
      }

      /** The smallest diameter of the cells [m]. */
      double
      smallest_cell() const
      {
        return h_min;
      }

      /**
       * Why the discretisation has no explicit step (a damping matrix C
       * that is not diagonal: Kelvin-Voigt viscosity, or absorbing faces
       * not aligned with the axes; a split fault); empty: it has one.
       */
      const std::string &
      refusal() const
      {
        return refused;
      }

      /** The step of length tau from `old` at time t; none if it failed. */
      std::optional<BodyState>
      operator()(const BodyState &old, double t, double tau);

      /** Why the last step failed. */
      const std::string &
      last_failure() const
      {
        return failure;
      }

    private:
      /**
       * The slip rate of every contact node of this rank into v (and the
       * friction force per unit area into `traction`) for the states
       * alpha, from r (the force without friction) and v*.
       */
      void
      solve_contact(const la::Vector          &r,
                    const la::Vector          &v_star,
                    const std::vector<double> &alpha,
                    double                     tau,
                    la::Vector                &v,
                    std::vector<double>       *traction);

      /**
       * The states of t + tau from the old ones with the mean slip rate of
       * v_old and v.
       */
      void
      update_states(const BodyState     &old,
                    const la::Vector    &v,
                    double               tau,
                    std::vector<double> &alpha) const;

      const physics::Discretisation<dim>               &discretisation;
      const physics::ContactQuadrature<dim>            &contact;
      const friction::Law                              &law;
      std::function<double(const dealii::Point<dim> &)> along_base;
      std::vector<friction::NodePotential>              potentials;
      /** f: the body force and the prestress (constant). */
      la::Vector load;
      /** Per owned dof: the lumped mass and the diagonal of C. */
      std::vector<double> mass, damping;
      /** Per owned dof: whether it is a contact node's tangential dof. */
      std::vector<bool> on_contact;
      double            stable = 0, h_min = 0;
      std::string       refused, failure;
    };
  } // namespace models
} // namespace rsfcycle

#endif
