// The ARKODE reference integrator of the spring-slider (see
// make_arkode_reference in spring_slider.h).

#include <algorithm>
#include <arkode/arkode_arkstep.h>
#include <cmath>
#include <deal.II/lac/vector.h>
#include <deal.II/sundials/arkode.h>
#include <rsfcycle/scenes/spring_slider.h>
#include <stdexcept>

namespace rsfcycle
{
  namespace scenes
  {
    /** See make_arkode_reference(). */
    class ArkodeReference : public time::Controller<SpringSlider::State>
    {
    public:
      using State      = SpringSlider::State;
      using VectorType = dealii::Vector<double>;

      explicit ArkodeReference(const SpringSlider &slider);

      void
      advance(State &current, double &t, double end_time) override;

      double
      last_step_size() const override
      {
        return last_step;
      }

      double
      step_size() const override
      {
        return last_step;
      }

      unsigned int
      n_spatial_problems() const override
      {
        return internal_steps;
      }

      time::ControllerMemory<State>
      memory() const override
      {
        return {};
      }

      void
      restore(const time::ControllerMemory<State> &) override
      {}

      bool
      can_checkpoint() const override
      {
        return false;
      }

    private:
      /** y' = f(t, y); 0 if finite, 1 otherwise (ARKODE retries). */
      int
      rhs(double t, const VectorType &y, VectorType &dy) const;

      State
      to_state(const VectorType &y, double t) const;

      const SpringSlider                                   &slider;
      const bool                                            dynamic;
      VectorType                                            y, abs_tol;
      std::unique_ptr<dealii::SUNDIALS::ARKode<VectorType>> ode;
      void        *arkode_memory  = nullptr;
      long int     steps_so_far   = 0;
      unsigned int internal_steps = 0;
      double       last_step      = 0;
    };


    ArkodeReference::ArkodeReference(const SpringSlider &slider)
      : slider(slider)
      , dynamic(slider.mass > 0)
      , y(3)
      , abs_tol(3)
    {
      if (slider.cohesion != 0)
        throw std::invalid_argument(
          "Spring slider: the ARKODE reference requires Cohesion = 0");
      const double end_time = slider.parameters.run.end_time;
      const double rtol     = slider.parameters.time_stepping.tolerance;

      using ARKode = dealii::SUNDIALS::ARKode<VectorType>;
      typename ARKode::AdditionalData data(0.0,
                                           end_time,
                                           1e-6,
                                           end_time,
                                           1e-14,
                                           5,
                                           20,
                                           false,
                                           false,
                                           false,
                                           3,
                                           0.0,
                                           rtol);
      ode                    = std::make_unique<ARKode>(data);
      ode->implicit_function = [this](const double      t,
                                      const VectorType &y,
                                      VectorType &dy) { return rhs(t, y, dy); };
      // Jacobian-vector products by finite differences: only the Newton
      // iteration uses them, not the accuracy of the solution.
      ode->jacobian_times_vector = [this](const VectorType &v,
                                          VectorType       &Jv,
                                          const double      t,
                                          const VectorType &y,
                                          const VectorType &fy) {
        const double norm = v.l2_norm();
        if (norm == 0)
          {
            Jv = 0;
            return 0;
          }
        const double h = 1e-7 * std::max(1., y.l2_norm()) / norm;
        VectorType   yh(y), fh(y.size());
        yh.add(h, v);
        const int err = rhs(t, yh, fh);
        for (unsigned int i = 0; i < Jv.size(); ++i)
          Jv[i] = (fh[i] - fy[i]) / h;
        return err;
      };
      // Absolute tolerances: rtol times the scale of each variable.
      abs_tol[0]                = rtol * slider.friction.L;
      abs_tol[1]                = dynamic ? rtol * slider.v0 : rtol;
      abs_tol[2]                = rtol;
      ode->get_local_tolerances = [this]() -> VectorType & { return abs_tol; };
      ode->custom_setup = [this](void *memory) { arkode_memory = memory; };

      y[0] = 0;
      y[1] = dynamic ? slider.initial_rate : std::log(slider.initial_rate);
      y[2] = slider.initial_alpha;
    }


    int
    ArkodeReference::rhs(const double      t,
                         const VectorType &y,
                         VectorType       &dy) const
    {
      const SpringSlider &s  = slider;
      const double        V  = dynamic ? y[1] : std::exp(y[1]);
      const double        Va = std::abs(V);
      const double        da = s.law.state_rate(s.friction, y[2], Va);
      const double        mu = s.law.friction_coefficient(s.friction, y[2], Va);
      const double        tau =
        s.prestress + s.stiffness * (s.load_point_displacement(t) - y[0]);
      dy[0] = V;
      dy[2] = da;
      if (dynamic)
        dy[1] = (tau - s.normal_stress * std::copysign(mu, V) - s.damping * V) /
                s.mass;
      else
        {
          // d/dt of tau0 + k(u_lp - delta) = N mu(V, alpha) + eta V
          // V dmu/dV and dmu/dalpha
          const auto sens = s.law.sensitivities(s.friction, y[2], Va);
          dy[1]           = (s.stiffness * (s.load_point_velocity(t) - V) -
                   s.normal_stress * sens[1] * da) /
                  (s.normal_stress * sens[0] + s.damping * V);
        }
      return std::isfinite(dy[0]) && std::isfinite(dy[1]) &&
                 std::isfinite(dy[2]) ?
               0 :
               1;
    }


    ArkodeReference::State
    ArkodeReference::to_state(const VectorType &y, const double t) const
    {
      State s;
      s.slip     = y[0];
      s.velocity = dynamic ? y[1] : std::exp(y[1]);
      s.alpha    = y[2];
      VectorType dy(3);
      rhs(t, y, dy);
      s.acceleration = dynamic ? dy[1] : s.velocity * dy[1];
      return s;
    }


    /**
     * Sample the solution (ARKODE interpolates between its own steps) at
     * the output period, and densely enough during events to see the peak:
     * at most (Reference sample spacing) L / V apart.
     */
    void
    ArkodeReference::advance(State &current, double &t, const double end_time)
    {
      const double period  = slider.output_period;
      const double spacing = slider.sample_spacing;
      const double dt =
        std::min({period,
                  spacing > 0 ? spacing * slider.friction.L /
                                  std::max(std::abs(current.velocity), 1e-300) :
                                period,
                  end_time - t});
      const double t_next =
        (end_time - t - dt < 1e-12 * end_time) ? end_time : t + dt;
      ode->solve_ode_incrementally(y, t_next);
      current   = to_state(y, t_next);
      last_step = t_next - t;
      t         = t_next;

      long int steps = steps_so_far;
      if (arkode_memory != nullptr)
        ARKStepGetNumSteps(arkode_memory, &steps);
      internal_steps = steps - steps_so_far;
      steps_so_far   = steps;
    }


    std::unique_ptr<time::Controller<SpringSlider::State>>
    make_arkode_reference(const SpringSlider &slider)
    {
      return std::make_unique<ArkodeReference>(slider);
    }
  } // namespace scenes
} // namespace rsfcycle
