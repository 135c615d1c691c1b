// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_parameters_h
#define rsfcycle_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <rsfcycle/friction/laws.h>
#include <rsfcycle/seas_parameters.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  using dealii::ParameterHandler;

  /**
   * The names of a choice (a Patterns::Selection) in the order of its enum's
   * values: every choice is parsed into its enum once, in
   * parse_parameters(), and the rest of the program compares enums; the
   * names serve the pattern, the parsing and the log.
   */
  template <typename Enum>
  struct Choice
  {
    /** The names, in the order of the enum's values (defined per enum). */
    static const std::vector<std::string> names;

    /** "a|b|c", the pattern of the Selection. */
    static std::string
    pattern();

    /** The value of a name the pattern allowed. */
    static Enum
    parse(const std::string &name);

    /** The name of a value. */
    static const std::string &
    name(Enum value);
  };

  /** The name of an enum value of a choice, for the log. */
  template <typename Enum>
  const std::string &
  name_of(const Enum value)
  {
    return Choice<Enum>::name(value);
  }

  /** Top level: which scene, in which dimension, for how long, where to. */
  struct RunParameters
  {
    unsigned int dimension = 2;
    bool         antiplane = false; // Displacement = antiplane
    /** The scene's name; scenes/scenes.h makes the scene of a name. */
    std::string  scene             = "wedge";
    double       end_time          = 1000;
    unsigned int stop_after_events = 0;
    std::string  output_directory  = "output";
    bool         overwrite_output  = false;

    /** `Scene` is declared with the names of scenes/scenes.h. */
    static void
    declare_parameters(ParameterHandler &prm, const std::string &scene_names);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Mesh": refinement toward the seismogenic patch. */
  struct MeshParameters
  {
    /** How the cells to refine toward the patch are chosen. */
    enum class RefinementLaw
    {
      /** centre closer than `refinement_distance` x diameter */
      centre_distance,
      /** box within `refinement_band` + layers x shortest edge */
      band
    };

    unsigned int  global_refinements     = 3;
    unsigned int  local_refinements      = 4;
    RefinementLaw refinement_law         = RefinementLaw::centre_distance;
    double        refinement_distance    = 1.5;
    double        refinement_band        = 0;
    double        refinement_band_layers = 1;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Time stepping": integrator and step-size control. */
  struct TimeSteppingParameters
  {
    /** The step-size control of the implicit step (doc/model.md §4.3). */
    enum class Controller
    {
      step_doubling,
      local_extrapolation
    };
    /** The norm of the error estimate. */
    enum class ErrorNorm
    {
      /** the state distance (14) */
      l2,
      /** the largest difference at a contact node */
      max
    };

    /** How the model is advanced; time/integrators.h makes it. */
    enum class Integrator
    {
      /** the model's implicit step, its sizes chosen by the Controller */
      implicit,
      /** SUNDIALS ARKODE on the model's ODE */
      arkode,
      /** ARKODE's explicit Dormand-Prince 5(4) on the model's ODE */
      runge_kutta,
      /** the model's explicit step, Courant number x its stable step */
      explicit_steps,
      /** implicit steps, explicit ones where they are shorter */
      implicit_explicit
    };

    Integrator integrator         = Integrator::implicit;
    bool       adaptive           = true;
    Controller controller         = Controller::local_extrapolation;
    bool       extrapolated_start = true;
    /** Step sizes = ladder (true) or free (false). */
    bool      ladder             = true;
    double    doubling_threshold = 1;
    ErrorNorm error_norm         = ErrorNorm::l2;
    double    tolerance          = 1e-5;
    double    initial_step       = 1e-2;
    double    minimum_step       = 1e-9;
    double    maximum_step       = 100;
    /** The explicit step as a fraction of the stable step [-]. */
    double courant_number = 0.5;
    /** R of the implicit-explicit switch (Explicit steps per implicit
     * step). */
    double implicit_ratio = 16;
    /** The explicit step's scheme (models::ExplicitStep). */
    enum class ExplicitScheme
    {
      /** Noh and Bathe's two sub-steps, p = 0.54: damps the shortest waves */
      noh_bathe,
      /** Newmark's explicit member: no numerical damping */
      central_differences
    };
    ExplicitScheme explicit_scheme = ExplicitScheme::noh_bathe;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Solver": rate/state coupling, TNNMG, linear correction. */
  struct SolverParameters
  {
    /** Rate/state coupling within one time step (doc/model.md §4.1). */
    enum class Coupling
    {
      fixed_point,
      explicit_decoupling
    };
    /** Inertia and radiation damping. */
    enum class Dynamics
    {
      dynamic,
      quasi_static,
      quasi_dynamic
    };
    /** The linear correction of TNNMG (doc/model.md §4.2 step 3). */
    enum class LinearCorrection
    {
      multigrid,
      direct,
      amg
    };
    /**
     * How the bulk enters a run: the volume mesh at every step, or its
     * Green's functions on the fault (doc/model.md §8.1).
     */
    enum class Bulk
    {
      volume,
      green_function
    };
    /** How the Green's-function operator S is stored and applied. */
    enum class GreenStorage
    {
      automatic,
      dense,
      h_matrix
    };

    /** The friction law of `State law` (friction/laws.h). */
    std::shared_ptr<const friction::Law> law = friction::make_law("ageing");
    Coupling                             coupling = Coupling::fixed_point;
    Dynamics                             dynamics = Dynamics::dynamic;
    /** Mass matrix = lumped (true) or consistent (false). */
    bool lumped_mass = false;
    Bulk bulk        = Bulk::volume;
    /**
     * `Green operator file`: the operator of an earlier green-function run
     * to reuse (absolute after parsing), or empty to compute it.
     */
    std::string  green_operator_file;
    GreenStorage green_storage = GreenStorage::automatic;
    /** Relative tolerance of the H-matrix compression (ACA+). */
    double green_compression_tolerance = 1e-6;
    /** Whether the H-matrix stores floats (`Green compression precision`). */
    bool green_single_precision = false;
    /** The time scheme's name; time/schemes.h makes it. */
    std::string time_scheme = "theta";
    double      theta       = 0.5;
    /** rho_inf of the generalized-alpha scheme. */
    double           spectral_radius            = 0.8;
    double           fixed_point_tolerance      = 1e-5;
    unsigned int     max_fixed_point_iterations = 20;
    LinearCorrection linear_correction          = LinearCorrection::multigrid;
    bool             direct_fallback            = false;
    bool             direct_factor_reuse        = false;
    unsigned int     smoothing_steps            = 3;
    unsigned int     coarse_reuse_size          = 10000;
    unsigned int     correction_cycles          = 1;
    double           correction_tolerance       = 1e-2;
    double           tnnmg_tolerance            = 1e-10;
    double           inner_tolerance_factor     = 0.3;
    unsigned int     max_tnnmg_iterations       = 100;
    double           truncation_ratio           = 1e10;

    /** `Time scheme` is declared with the names of time/schemes.h. */
    static void
    declare_parameters(ParameterHandler &prm, const std::string &schemes);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Subsection "Output": snapshots, profiles, events, progress. */
  struct OutputParameters
  {
    double output_interval        = 10;
    double event_output_interval  = 0.1;
    double profile_interval       = 1;
    double event_profile_interval = 0.005;
    double event_threshold        = 10;
    double event_merge_time       = 0;
    double progress_interval      = 10;
    /** The outputs of a run by name (output/writers.h). */
    std::vector<std::string> writers            = {"time series",
                                                   "base profile",
                                                   "events",
                                                   "vtu"};
    double                   transition_time    = 0;
    unsigned int             transition_events  = 2;
    unsigned int             checkpoint_steps   = 5000;
    double                   checkpoint_minutes = 10;
    /** The subsection Output/SEAS. */
    SeasParameters seas;

    /** `Writers` is declared with the names of output/writers.h. */
    static void
    declare_parameters(ParameterHandler &prm, const std::string &writers);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** All parameters of a run but the scene's own subsection. */
  struct Parameters
  {
    RunParameters          run;
    MeshParameters         mesh;
    TimeSteppingParameters time_stepping;
    SolverParameters       solver;
    OutputParameters       output;

    /**
     * Declare every entry but the scenes' subsections (declared by
     * app::declare_parameters(), which calls this function with the
     * names of its scenes).
     */
    static void
    declare_parameters(ParameterHandler  &prm,
                       const std::string &scene_names,
                       const std::string &scheme_names,
                       const std::string &writer_names);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Checks across entries that the patterns cannot express; throws
     * std::invalid_argument with one line naming the entry, its value and
     * what is allowed.
     */
    void
    validate() const;
  };
} // namespace rsfcycle

#endif
