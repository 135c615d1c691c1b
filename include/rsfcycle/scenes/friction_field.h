// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_scenes_friction_field_h
#define rsfcycle_scenes_friction_field_h

#include <array>
#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <memory>
#include <optional>
#include <rsfcycle/friction/law.h>
#include <string>

namespace rsfcycle
{
  namespace scenes
  {
    using namespace dealii;

    /**
     * The rate-and-state parameters, the cohesion and the initial state of
     * a contact as functions of position: the one mechanism through which
     * every continuum scene describes its fault. The wedge builds the
     * functions from its patch (piecewise constant), the mesh-file scene
     * parses them from the .prm (muparser expressions in x, y, z); both
     * hand the solver the same friction::Parameters per node. Optionally
     * also the normal stress and the radiation damping on the contact.
     */
    template <int dim>
    class FrictionField
    {
    public:
      /** One scalar function per quantity. */
      struct Functions
      {
        std::shared_ptr<const Function<dim>> a;         // [-]
        std::shared_ptr<const Function<dim>> b_minus_a; // [-]
        std::shared_ptr<const Function<dim>> L;         // [m]
        std::shared_ptr<const Function<dim>> mu_star;   // [-]
        std::shared_ptr<const Function<dim>> v_star;    // [m/s]
        std::shared_ptr<const Function<dim>> cohesion;  // [Pa]
        /** theta_0 [s]; null: theta_0 = L / V*, i.e. alpha = 0. */
        std::shared_ptr<const Function<dim>> initial_state;
        /** |sigma_n| [Pa]; null: from the gravity equilibrium. */
        std::shared_ptr<const Function<dim>> normal_stress;
        /** tau_0 [Pa] along the load; null: none. */
        std::shared_ptr<const Function<dim>> shear_prestress;
        /** Delta tau [Pa] along the load; null: none. */
        std::shared_ptr<const Function<dim>> shear_perturbation;
        /** g(t) [-] of Delta tau, time-dependent; null without it. */
        std::shared_ptr<Function<dim>> perturbation_history;
        /** eta [Pa s/m]; null: sqrt(G rho) of the material. */
        std::shared_ptr<const Function<dim>> radiation_damping;
        /** p(x, t) [Pa], time-dependent; null: none. */
        std::shared_ptr<Function<dim>> pore_pressure;
        /**
         * q(x, t) [m/s], time-dependent, reported only, one component (2D)
         * or one or two (3D, along the fluid domain's axes); null: none.
         */
        std::shared_ptr<Function<dim>> darcy_velocity;
      };

      explicit FrictionField(Functions functions);

      /**
       * Declare the entries of the expressions (in the current
       * subsection).
       */
      static void
      declare_parameters(ParameterHandler &prm);

      /**
       * Parse the expressions of the current subsection (named `section` in
       * error messages). A malformed expression throws
       * std::invalid_argument naming the entry.
       */
      static FrictionField
      parse(ParameterHandler &prm, const std::string &section);

      /**
       * A muparser expression of the coordinates x, y (z), and with
       * `time_dependent` of the time t (Function::set_time()), checked
       * once; a malformed one throws std::invalid_argument naming `entry`.
       */
      static std::shared_ptr<Function<dim>>
      parse_expression(const std::string &expression,
                       const std::string &entry,
                       bool               time_dependent = false);

      /** Parameters and cohesion at x. */
      friction::Parameters
      parameters(const Point<dim> &x) const;

      /** The initial state alpha = log(theta_0 V* / L) at x. */
      double
      initial_alpha(const Point<dim> &x) const;

      /** The functions (the optional ones are null when not given). */
      const Functions &
      functions() const
      {
        return f;
      }

      /** The prescribed |sigma_n| at x; none: from gravity. */
      std::optional<double>
      normal_stress(const Point<dim> &x) const;

      /** The shear prestress tau_0 at x; none: no prestress. */
      std::optional<double>
      shear_prestress(const Point<dim> &x) const;

      /**
       * The spatial part Delta tau of the shear stress perturbation at x
       * [Pa]; none: no perturbation.
       */
      std::optional<double>
      shear_perturbation(const Point<dim> &x) const;

      /** Its factor g(t) [-] at the time t [s] (0 without it). */
      double
      perturbation_history(double t) const;

      /** The pore pressure p at x and time t [Pa]; none: no pore fluid. */
      std::optional<double>
      pore_pressure(const Point<dim> &x, double t) const;

      /**
       * The Darcy velocity's components at x and time t [m/s] (the second
       * 0 in 2D); none: not given.
       */
      std::optional<std::array<double, 2>>
      darcy_velocity(const Point<dim> &x, double t) const;

      /** The prescribed radiation damping at x; none: the material's. */
      std::optional<double>
      radiation_damping(const Point<dim> &x) const;

      /** b - a at x (> 0: rate weakening). */
      double
      b_minus_a(const Point<dim> &x) const;

      /**
       * Throw std::invalid_argument naming the entry (of `section`) and x
       * unless every value at x lies in its range: a, L, V*, theta_0 > 0,
       * b >= 0, mu* and the cohesion >= 0, all finite.
       */
      void
      check(const Point<dim> &x, const std::string &section) const;

    private:
      static void
      parse_pore_fluid(ParameterHandler  &prm,
                       const std::string &section,
                       Functions         &functions);

      Functions f;
    };
  } // namespace scenes
} // namespace rsfcycle

#endif
