#ifndef rsfcycle_time_newmark_step_h
#define rsfcycle_time_newmark_step_h

#include <boost/serialization/split_member.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <optional>
#include <rsfcycle/friction/contact_quadrature.h>
#include <rsfcycle/la.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/solvers/tnnmg.h>
#include <rsfcycle/time/model.h>
#include <rsfcycle/time/theta_scheme.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  using dealii::SparseMatrix;
  using dealii::Vector;
  namespace types = dealii::types;

  /**
   * The state of the body at one time: displacement, velocity, acceleration
   * (all dofs) and the friction state alpha = log(theta V* / L) per contact
   * node, with what the step that produced it cost.
   */
  struct BodyState
  {
    la::Vector           u, v, a;
    std::vector<double>  alpha;
    std::vector<double>  shear_traction; // |friction force| / w per node [Pa]
    time::StepStatistics statistics;

    template <class Archive>
    void
    save(Archive &ar, const unsigned int) const
    {
      la::save(ar, u);
      la::save(ar, v);
      la::save(ar, a);
      ar &alpha &shear_traction &statistics;
    }

    template <class Archive>
    void
    load(Archive &ar, const unsigned int)
    {
      la::load(ar, u);
      la::load(ar, v);
      la::load(ar, a);
      ar &alpha &shear_traction &statistics;
    }

    BOOST_SERIALIZATION_SPLIT_MEMBER()
  };

  namespace time
  {
    /**
     * One Newmark step (15) of the continuum (in general the theta scheme
     * of `Solver/Theta`, time/theta_scheme.h) with the rate/state coupling
     * (18) of time/rate_state_coupling.h, whose velocity solves are TNNMG:
     * theta^0 = theta_{n-1}; v^k = TNNMG solution with theta^{k-1};
     * theta^k from (17) with V = |(v_{n-1} + v^k)/2| (the scheme's
     * weights); stop at
     * d(theta^k, theta^{k-1}) <= epsilon. With explicit coupling, the state
     * is updated once from V = |v_{n-1}| and one spatial problem is solved.
     * A failed step (no convergence, non-finite values) returns nothing and
     * leaves a diagnosis in last_failure().
     */
    template <int dim>
    class NewmarkStep
    {
    public:
      /**
       * `along_base` gives the position along the base [m] that diagnoses
       * name.
       */
      NewmarkStep(const SolverParameters                 &solver,
                  physics::Discretisation<dim>           &discretisation,
                  const friction::ContactQuadrature<dim> &contact,
                  solvers::TNNMG                         &tnnmg,
                  std::function<double(const dealii::Point<dim> &)> along_base);

      /**
       * The step of length tau from state `old` at time t. The fixed-point
       * iteration starts from the state and the velocity of `guess` if
       * given (a prediction), else from the old ones.
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
      StepStatistics
      take_work();

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
       * r = f - K (u + (1 - theta) tau v) (+ M (v / (theta tau) + (1 -
       * theta) / theta a), dynamic); theta = 1/2: f - K (u + tau/2 v) + M
       * (2/tau v + a).
       */
      la::Vector
      right_hand_side(const BodyState &old, double tau) const;

      /**
       * The rate/state coupling for the step: v and alpha of `next`; false
       * on failure.
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
       * state, with the velocity (1 - weight_new) v_old + weight_new v_new.
       */
      void
      update_states(const BodyState     &old,
                    const la::Vector    &v_new,
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

      /** u, a, the shear traction and the finiteness checks of `next`. */
      bool
      complete(const BodyState       &old,
               const la::LocalMatrix &A,
               const la::Vector      &rhs,
               double                 t,
               double                 tau,
               BodyState             &next);

      /** Where the first non-finite velocity is (for diagnoses). */
      std::string
      first_non_finite(const la::Vector &v) const;

      const SolverParameters                           &solver;
      physics::Discretisation<dim>                     &discretisation;
      const friction::ContactQuadrature<dim>           &contact;
      solvers::TNNMG                                   &tnnmg;
      const ThetaScheme                                 scheme;
      const friction::Law                              &law;
      std::function<double(const dealii::Point<dim> &)> along_base;

      StepStatistics       work;
      std::string          failure;
      dealii::TimerOutput *timer = nullptr;
    };
  } // namespace time
} // namespace rsfcycle

#endif
