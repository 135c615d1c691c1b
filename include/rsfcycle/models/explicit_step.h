// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_models_explicit_step_h
#define rsfcycle_models_explicit_step_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>
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
     * stepping/Integrator = explicit`) with the lumped mass M_L (the row
     * sums of M) and the damping C of the absorbing faces' dashpots,
     * lumped at the vertices (a dim x dim block per vertex on a face not
     * aligned with the axes, solved as such; couplings outside a vertex or
     * a split fault's pair, as at a fault's end on an absorbing face, act
     * at v*, on the right-hand side). Its stage from (u, v, a) over tau,
     * given a base velocity v* and a coefficient kappa:
     *   u_{n+1} = u_n + tau v_n + tau^2/2 a_n,
     *   (kappa M_L + C) v_{n+1} = (kappa M_L + C) v* + f - K u_{n+1} - C v*
     *                             - the friction force,
     *   a_{n+1} = kappa (v_{n+1} - v*),
     * every dof (or vertex) on its own: K is applied as a product, and on a
     * contact node the slip rate solves the node-local problem of the implicit
     * path's Gauss-Seidel sweep (friction::solve_local_problem) with the
     * node's friction potential at the state of t_{n+1}. The state takes
     * the law's closed-form update with the mean slip rate of the stage, in
     * two passes (the state from the old slip rate, the slip rate, the
     * state from the mean, the slip rate again). The state (u, v, a,
     * alpha) is the implicit step's, so that a run may take either.
     *
     * Central differences (Newmark's beta = 0, gamma = 1/2) are one stage
     * with v* = v_n + tau/2 a_n and kappa = 2/tau. Noh and Bathe's scheme
     * (2013, p = 0.54; `Explicit scheme = noh-bathe`) takes two: central
     * differences over p tau, then over (1 - p) tau from that stage's
     * state with v** = v_p + (1 - p) tau (q0 a_n + (1/2 + q1) a_p) and
     * kappa = 1/((1 - p) tau q2), q1 = (1 - 2p)/(2p(1 - p)), q2 = 1/2 - p
     * q1, q0 = 1/2 - q1 - q2: second order, with a numerical damping that
     * grows as (omega tau)^3 per period and takes the shortest waves.
     *
     * A split fault (physics/split_fault.h: the slip s and the mean m of
     * each tangential pair, one shared normal w): the tie makes the lumped
     * mass a 2x2 block per pair, A = kappa M~ + C~ on (s, m), so the pair
     * is solved together, as split-node codes do: the slip from the
     * node-local problem with a_s - a_sm^2/a_m in place of the diagonal
     * and rho_s - a_sm rho_m/a_m as its right-hand side, then the mean
     * from its own row, m = (rho_m - a_ms s)/a_m. The friction's normal
     * stress is the + side's elastic reaction at u_{n+1}
     * (physics::split_normal_stresses, the implicit step's); a node that
     * loses its compression fails the step.
     *
     * Stable for tau <= stable_step() = Omega/omega_max, Omega = 2 for
     * central differences and 3.745029 for Noh and Bathe's p = 0.54:
     * omega_max^2, the largest eigenvalue of M_L^-1 K, is bounded from
     * above by the largest of every cell's K_e x = lambda M_L,e x (the
     * element eigenvalue theorem; sharp on a uniform mesh).
     */
    template <int dim>
    class ExplicitStep
    {
    public:
      /**
       * `along_base` gives the position along the base [m] that diagnoses
       * name.
       */
      ExplicitStep(const physics::Discretisation<dim>    &discretisation,
                   const physics::ContactQuadrature<dim> &contact,
                   const friction::Law                   &law,
                   std::function<double(const dealii::Point<dim> &)> along_base,
                   bool two_stages);

      /** Omega/omega_max [s] (collective at construction). */
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
       * that is not diagonal outside a split fault's pairs: Kelvin-Voigt
       * viscosity, or absorbing faces not aligned with the axes); empty:
       * it has one.
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
       * A stage of length tau from `old` at time t with the base velocity
       * v_star and the mass's coefficient kappa (class comment); `slot`:
       * which of the step's stages (the blocks' inverses kept per stage).
       */
      std::optional<BodyState>
      stage(const BodyState  &old,
            const la::Vector &v_star,
            double            t,
            double            tau,
            double            kappa,
            unsigned int      slot);

      /**
       * The slip rate of every contact node of this rank into v (and the
       * friction force per unit area into `traction`) for the states
       * alpha, from r (the force without friction) and v*.
       */
      void
      solve_contact(const la::Vector          &r,
                    const la::Vector          &v_star,
                    const std::vector<double> &alpha,
                    double                     kappa,
                    la::Vector                &v,
                    std::vector<double>       *traction);

      /**
       * The states of t + tau from the old ones with the mean slip rate of
       * v_old and v.
       */
      /**
       * Whether the step's displacement, velocity and states are finite on
       * every rank (collective); else the failure's text.
       */
      bool
      finite(const BodyState &next, double t, double tau);

      /**
       * The blocks of C (find_blocks): the free dofs off the contact and
       * the pairs that a vertex's dashpot couples, and single[i] for those
       * that nothing couples; refused if C couples dofs of different nodes.
       */
      void
      find_blocks();

      /** v += (kappa M_L + C)^-1 r on every block. */
      void
      solve_blocks(const la::Vector &r,
                   double            kappa,
                   unsigned int      slot,
                   la::Vector       &v);

      /**
       * rho = r + A v* of a split fault's paired dofs (A = kappa M + C with
       * the pair's coupling), ghosts updated; v of the paired dofs that are
       * neither on the contact nor prescribed, after the contact's.
       */
      void
      pair_right_hand_sides(const la::Vector &r,
                            const la::Vector &v_star,
                            double            kappa);
      void
      solve_pairs(double kappa, la::Vector &v) const;

      /** The pair's a_sm^2 / a_m and a_sm rho_m / a_m of paired dof i. */
      std::pair<double, double>
      condensed(unsigned int i, double kappa) const;

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
      /**
       * A split fault: per owned dof the local index of its partner
       * (invalid: none) and the coupling M~, C~ to it; the diagonals of M~
       * and C~ with the partners' as ghosts; rho of the paired dofs.
       */
      std::vector<unsigned int> partner;
      std::vector<double>       mass_coupling, damping_coupling;
      /** A vertex's dofs that C couples, and C among them. */
      struct Block
      {
        std::vector<unsigned int>  dofs;
        dealii::FullMatrix<double> damping;
        /** (kappa M_L + C)^-1 on the block per stage, kappa = blocks_kappa */
        std::array<dealii::FullMatrix<double>, 2> inverse;
      };
      std::vector<Block>    blocks;
      std::array<double, 2> blocks_kappa{};
      /** A split fault's free slips and means off the contact. */
      std::vector<unsigned int> free_slips, free_means;
      /** Per owned dof: free, off the contact and the pairs, in no block. */
      std::vector<bool> single;
      /** C v* of a stage. */
      la::Vector damping_force;
      /**
       * Whether C has an entry other than zero on some rank: an elastic
       * body (no viscosity, no sponge) skips the product C v*, a sparse
       * product the size of K u in each stage.
       */
      bool       damped = false;
      la::Vector mass_diagonal, damping_diagonal, rho_pairs;
      double     stable = 0, h_min = 0;
      /** Noh and Bathe's p (0: central differences). */
      const double p;
      std::string  refused, failure;
    };
  } // namespace models
} // namespace rsfcycle

#endif
