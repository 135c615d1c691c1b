// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_implicit_step_h
#define rsfcycle_models_implicit_step_h

#include <deal.II/base/timer.h>
#include <functional>
#include <optional>
#include <rsfcycle/friction/law.h>
#include <rsfcycle/la.h>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/body_state.h>
#include <rsfcycle/physics/contact_quadrature.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/solvers/tnnmg.h>
#include <rsfcycle/time/time_scheme.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace models
  {
    using time::TimeScheme;

    /**
     * One implicit step of the continuum: the time scheme of `Solver/Time
     * scheme` (time/time_scheme.h; the paper's Newmark step (15) for
     * theta = 1/2) with the rate/state coupling (18) of
     * time/rate_state_coupling.h, whose velocity solves are TNNMG:
     * alpha^0 = the old state (or the guess); w^k = the TNNMG solution with
     * alpha^{k-1}; alpha^k from (17) with the slip rate of the scheme's
     * combination of v_n and w^k; stop at d(alpha^k, alpha^{k-1}) <=
     * epsilon. With explicit coupling, the state is updated once from the
     * old slip rate and one spatial problem is solved. A failed step (no
     * convergence, non-finite values) returns nothing and leaves a diagnosis
     * in last_failure().
     */
    template <int dim>
    class ImplicitStep
    {
    public:
      /**
       * `along_base` gives the position along the base [m] that diagnoses
       * name.
       */
      ImplicitStep(
        const SolverParameters                           &solver,
        const TimeScheme                                 &scheme,
        physics::Discretisation<dim>                     &discretisation,
        const physics::ContactQuadrature<dim>            &contact,
        solvers::TNNMG                                   &tnnmg,
        std::function<double(const dealii::Point<dim> &)> along_base);

      /**
       * The step of length tau from state `old` at time t. The fixed-point
       * iteration starts from the friction state and the velocity of
       * `guess` if given (a prediction), else from the old ones.
       */
      std::optional<BodyState>
      operator()(const BodyState &old,
                 double           t,
                 double           tau,
                 const BodyState *guess = nullptr);

      /**
       * Iterations of all spatial problems since the last call, then
       * reset.
       */
      solvers::StepStatistics
      take_work();

      /**
       * At most n iterations of the rate-state fixed point in the steps
       * that follow (0: Solver/Max fixed-point iterations).
       */
      void
      limit_fixed_point_iterations(const unsigned int n)
      {
        fixed_point_cap = n;
      }

      /** Time the state updates in the TimerOutput section "State update". */
      void
      set_timer(dealii::TimerOutput *new_timer)
      {
        timer = new_timer;
      }

      /** Why the last step failed. */
      const std::string &
      last_failure() const
      {
        return failure;
      }

    private:
      /**
       * r = f - K (u_n + d[0] v_n + d[1] a_n) (+ M (m[0] v_n + m[1] a_n),
       * dynamic) with the scheme's d and m; theta = 1/2: f - K (u + tau/2 v)
       * + M (2/tau v + a).
       */
      la::Vector
      right_hand_side(const BodyState &old, double tau) const;

      /**
       * The rate/state coupling for the step: w (in next.v) and the
       * friction state of `next`; false on failure.
       */
      bool
      couple(const BodyState                      &old,
             const std::vector<double>            &alpha_start,
             const solvers::SpatialProblem        &problem,
             std::vector<friction::NodePotential> &potentials,
             double                                t,
             double                                tau,
             BodyState                            &next);

      /**
       * The state update (17) of every node over the step tau from the old
       * friction state, with the velocity (1 - weight_new) v_old +
       * weight_new w.
       */
      void
      update_states(const BodyState     &old,
                    const la::Vector    &w,
                    double               weight_new,
                    double               tau,
                    std::vector<double> &alpha) const;

      /** The diagnosis of a TNNMG solve that failed. */
      std::string
      tnnmg_failure(const solvers::TNNMGStatistics &stats,
                    double                          t,
                    double                          tau,
                    unsigned int                    k,
                    const la::Vector               &v) const;

      /**
       * v, u, a of `next` from w (in next.v), the friction force and the
       * finiteness checks.
       */
      bool
      complete(const BodyState       &old,
               const la::LocalMatrix &A,
               const la::Vector      &rhs,
               double                 t,
               double                 tau,
               BodyState             &next);

      /**
       * v, a and u at the step's end from the unknown w at which friction
       * acts (the scheme's new_velocity, new_acceleration, new_displacement).
       */
      void
      advance(const BodyState  &old,
              const la::Vector &w,
              double            tau,
              BodyState        &next) const;

      /**
       * A split fault's normal coupling: physics::split_normal_stresses() at
       * the displacement of the step's end for w, into the potentials (as
       * forces) and `stresses`; false if a node is not in compression.
       */
      bool
      couple_normal_forces(const BodyState                      &old,
                           const la::Vector                     &w,
                           double                                tau,
                           std::vector<friction::NodePotential> &potentials,
                           std::vector<double> &stresses) const;

      /** Where the first non-finite velocity is (for diagnoses). */
      std::string
      first_non_finite(const la::Vector &v) const;

      const SolverParameters                           &solver;
      const TimeScheme                                 &scheme;
      const bool                                        inertia;
      physics::Discretisation<dim>                     &discretisation;
      const physics::ContactQuadrature<dim>            &contact;
      solvers::TNNMG                                   &tnnmg;
      const friction::Law                              &law;
      std::function<double(const dealii::Point<dim> &)> along_base;
      /** limit_fixed_point_iterations()'s n (0: none). */
      unsigned int fixed_point_cap = 0;

      solvers::StepStatistics work;
      std::string             failure;
      dealii::TimerOutput    *timer = nullptr;
    };
  } // namespace models
} // namespace rsfcycle

#endif
