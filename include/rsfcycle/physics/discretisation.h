// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_discretisation_h
#define rsfcycle_physics_discretisation_h

#include <array>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <map>
#include <memory>
#include <rsfcycle/ids.h>
#include <rsfcycle/la.h>
#include <rsfcycle/local_matrix.h>
#include <rsfcycle/parameters.h>
#include <rsfcycle/physics/scene.h>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    using namespace dealii;

    /**
     * An observation (or a force) as a weighted sum of dofs: (global dof
     * index, weight), hanging dofs replaced by the dofs they depend on.
     */
    using ObservationRow =
      std::vector<std::pair<dealii::types::global_dof_index, double>>;

    /**
     * The pairs of a split fault's two sides (physics/split_fault.h) in the
     * global dof numbering: per dof its physics::TieKind and its partner on
     * the other side, and for every + tangential dof its node's + normal dof
     * and the sign of the + side's outward normal along y. Empty without a
     * split fault.
     */
    struct FaultTie
    {
      std::vector<unsigned char>                              kind;
      std::vector<unsigned int>                               partner;
      std::map<unsigned int, std::pair<unsigned int, double>> normal_of;

      bool
      empty() const
      {
        return kind.empty();
      }
    };

    /**
     * The discretisation of the Kelvin-Voigt body (doc/model.md §1-2): the
     * scene's coarse mesh refined toward the seismogenic patch,
     * FE_Q(1)^dim (antiplane: FE_Q(1), the out-of-plane component) with
     * its multigrid level dofs and hanging-node
     * constraints, the mass, viscosity and stiffness matrices M, C, K and
     * the gravity load (assembled once; cell_matrices() gives the same cell
     * integrals on the multigrid levels), the Dirichlet dofs, and the step
     * matrices 2/tau M + C + tau/2 K of the Newmark scheme (15).
     *
     * The deal.II objects are public members for reading: the contact
     * quadrature, the implicit step, the linear corrections and the writers
     * all work on them.
     */
    template <int dim>
    class Discretisation
    {
    public:
      /** What is modelled beyond the mesh. */
      struct Options
      {
        /**
         * One displacement component, out of the plane of a 2D mesh
         * (scalar elasticity), instead of dim.
         */
        bool antiplane = false;
        /**
         * Add the dashpot eta V of the quasi-dynamic approximation
         * (Scene::radiation_damping()) on the contact to C.
         */
        bool radiation_damping = false;
        /**
         * The mass lumped: every cell's mass matrix replaced by the
         * diagonal of its row sums (the explicit step's mass, taken by the
         * implicit step too where a run changes between them).
         */
        bool lumped_mass = false;
      };

      Discretisation(const MeshParameters      &mesh,
                     const physics::Scene<dim> &scene,
                     const Options             &options = Options());
      ~Discretisation();

      /**
       * The coarse mesh of the scene, refined globally and then locally
       * toward the patch; material ids from the cell centres.
       */
      void
      make_grid();

      /** Dofs (active and level), constraints, sparsity, empty matrices. */
      void
      setup_system();

      /**
       * The fixed dofs: backstop (all components), base (the normal
       * component y), lateral walls (z), hanging nodes.
       */
      void
      setup_boundary_conditions();

      /**
       * M, C, K and the load (gravity, the scene's shear prestress on the
       * contact), with hanging nodes condensed; C holds the radiation
       * damping on the contact if it is on, and the sponge (add_sponge).
       */
      void
      assemble_matrices();

      /**
       * The sponge's alpha M, lumped after the hanging nodes' condensation,
       * added to C's diagonal (assemble_matrices' work arrays passed on).
       */
      void
      add_sponge(FEValues<dim>                        &fe_values,
                 std::array<FullMatrix<double>, 3>    &cell,
                 std::vector<types::global_dof_index> &dof_indices);

      /**
       * M, C, K and the gravity load of one cell, active or on a multigrid
       * level (the material is found from the cell centre).
       */
      template <class Iterator>
      void
      cell_matrices(const Iterator                    &cell,
                    FEValues<dim>                     &fe_values,
                    std::array<FullMatrix<double>, 3> &matrices,
                    Vector<double>                    &cell_force) const;

      /**
       * With a split fault (Scene::split_fault()): rewrite M, C, K, the
       * loads, the fixed dofs and the backstop in the tied unknowns
       * u = T u~ of physics/split_fault.h (the slip in the + tangential
       * dof, the mean in the - one, one normal displacement), the radiation
       * damping on the slip; fill fault_tie and fault_normal_rows (the
       * rank's contact dofs). On N ranks the rows of the paired dofs are
       * gathered on every rank, and the partitioner is rebuilt: its ghosts
       * gain the columns of the tied rows and the partners of the relevant
       * dofs (vectors made before must be made again).
       */
      void
      tie_fault_sides();

      /**
       * The static equilibrium under gravity with the fixed dofs held at
       * zero (a frictionless base): the displacement and the reaction
       * K u - f (whose base normal components are the normal forces).
       * Throws if the matrices or the load are not finite.
       */
      std::pair<la::Vector, la::Vector>
      gravity_equilibrium();

      /** v as a zero vector on the dofs' partitioner (owned, ghosts). */
      void
      reinit(la::Vector &v) const;

      /** Prescribed values of the fixed dofs at time t (backstop). */
      void
      set_fixed_values(la::Vector &v, double t) const;

      /**
       * The step matrix A = c_M M + c_C C + c_K K in the rank's rows, with
       * the factors of time::ThetaScheme::step_coefficients() (the
       * trapezoidal step: 2/tau M + C + tau/2 K, quasi-static without M),
       * kept for the last few step sizes.
       */
      const la::LocalMatrix &
      step_matrix(const std::array<double, 3> &coefficients);

      /**
       * The same step matrix assembled as a Trilinos matrix (for algebraic
       * multigrid), built at the first request.
       */
      const TrilinosWrappers::SparseMatrix &
      assembled_step_matrix(const std::array<double, 3> &coefficients);

      /**
       * Free the Trilinos M, C, K (kept only for assembled_step_matrix(),
       * i.e. algebraic multigrid): a third of the memory of a run.
       */
      void
      release_assembled_matrices();

      /**
       * The component normal to the base (y), fixed on the contact;
       * numbers::invalid_unsigned_int in the antiplane model (its only
       * component is tangential everywhere).
       */
      unsigned int
      normal_component() const
      {
        return fe.n_components() > 1 ? 1 : numbers::invalid_unsigned_int;
      }

      /**
       * The component held at zero on the contact: the normal one, or
       * numbers::invalid_unsigned_int where the scene's contact normal is
       * free, the fault is split (its sides are tied instead) or there is
       * no normal component.
       */
      unsigned int
      held_contact_component() const
      {
        return scene.contact_normal_free() || scene.split_fault() ?
                 numbers::invalid_unsigned_int :
                 normal_component();
      }

      /**
       * The component fixed on free-slip (lateral) walls: z in 3D,
       * numbers::invalid_unsigned_int in 2D.
       */
      unsigned int
      lateral_component() const
      {
        return fe.n_components() == 3 ? 2 : numbers::invalid_unsigned_int;
      }

      /**
       * Whether component c of a vertex on boundary `id` moves with the
       * load (backstop, its opposite, the tangential components of creep):
       * prescribed, not an unknown.
       */
      bool
      loaded(const types::boundary_id id, const unsigned int c) const
      {
        return id == boundary_id::backstop ||
               id == boundary_id::backstop_opposite ||
               (id == boundary_id::creep && c != normal_component());
      }

      /**
       * Whether component c of a vertex on boundary `id` is prescribed: it
       * moves with the load (loaded()), or it is held at zero (the lateral
       * component on free-slip walls, the normal one on parallel walls,
       * held_contact_component() on the contact and on creep).
       */
      bool
      prescribed(const types::boundary_id id, const unsigned int c) const
      {
        return loaded(id, c) ||
               (id == boundary_id::lateral && c == lateral_component()) ||
               (id == boundary_id::parallel && c == normal_component()) ||
               ((id == boundary_id::contact || id == boundary_id::creep) &&
                c == held_contact_component());
      }

      /**
       * The prescribed components of every boundary that has any (as
       * prescribed() gives them), homogeneous in a correction: what the
       * geometric multigrid's level matrices hold fixed.
       */
      std::vector<std::pair<types::boundary_id, ComponentMask>>
      prescribed_components() const;

      /** For every locally owned dof, its vector component. */
      std::vector<unsigned int>
      dof_components() const;

      /** Local index (owned, then ghosts) of a global dof index. */
      unsigned int
      local_index(const types::global_dof_index i) const
      {
        return partitioner->global_to_local(i);
      }

      /** Whether a global dof index is owned or a ghost on this rank. */
      bool
      is_local(const types::global_dof_index i) const
      {
        return partitioner->in_local_range(i) || partitioner->is_ghost_entry(i);
      }

      parallel::distributed::Triangulation<dim> triangulation;
      FESystem<dim>                             fe;
      DoFHandler<dim>                           dof_handler;
      FE_Q<dim>                                 scalar_fe;
      DoFHandler<dim>                           scalar_dof_handler;
      AffineConstraints<double>                 hanging_constraints;
      AffineConstraints<double>                 scalar_constraints;

      /** M, C and K with the rows of this rank (Trilinos). */
      TrilinosWrappers::SparseMatrix mass_matrix, viscosity_matrix,
        stiffness_matrix;
      /** The same in the rank's rows for the kernels (LocalMatrix). */
      la::LocalMatrix mass_local, viscosity_local, stiffness_local;
      la::Vector      body_force;
      /**
       * The scene's shear prestress on the contact as nodal forces (zero
       * without one); a load of every time step, not of the gravity
       * equilibrium.
       */
      la::Vector prestress_force;
      /** The split fault's tie (empty without one). */
      FaultTie fault_tie;
      /**
       * With a split fault in plane strain: per + tangential dof (the
       * contact dof) of this rank, by local index, the compressive normal
       * force on its node as a row of the tied unknowns (local indices:
       * owned, then ghosts) [N/m^(3-dim)] (GlobalSystem::normal_rows).
       */
      std::map<unsigned int, ObservationRow> fault_normal_rows;
      /**
       * The same for the + side's inertia: per contact dof, -n (M a)_c of
       * the untied mass's row c as a row of the tied accelerations
       * [kg/m^(3-dim)] (split_normal_stresses()).
       */
      std::map<unsigned int, ObservationRow> fault_normal_inertia_rows;
      /** CG iterations of the last gravity equilibrium. */
      unsigned int gravity_iterations = 0;
      /**
       * Locally owned dofs of this rank and as ghosts the locally relevant
       * dofs and every column of the owned rows of the matrices.
       */
      std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;
      /** Locally owned and locally relevant dofs of the scalar field. */
      std::shared_ptr<const Utilities::MPI::Partitioner> scalar_partitioner;

      /**
       * By local index (owned, then ghosts): whether the value is
       * prescribed (Dirichlet, hanging nodes).
       */
      std::vector<bool> fixed;
      /** An owned dof of a load boundary (inhomogeneous Dirichlet). */
      struct BackstopDof
      {
        /** Local index. */
        unsigned int index;
        unsigned int component;
        /** +1 on load and creep faces, -1 on load-opposite faces. */
        double sign;
      };
      std::vector<BackstopDof> backstop_dofs;

    private:
      /** Whether the refinement law selects this cell in a local cycle. */
      bool
      near_patch(
        const typename Triangulation<dim>::active_cell_iterator &cell) const;

      const MeshParameters      &mesh;
      const physics::Scene<dim> &scene;
      const Options              options;

      /** M, C, K of a cell in the antiplane model (scalar elasticity). */
      void
      antiplane_cell_matrices(
        const FEValues<dim>               &fe_values,
        const physics::Material           &material,
        std::array<FullMatrix<double>, 3> &matrices) const;

      /** The scene's shear prestress on the contact (empty: none). */
      const std::function<Tensor<1, dim>(const Point<dim> &)> prestress;

      /**
       * The terms of a cell's contact faces: the radiation damping eta w_i
       * on the diagonal of every tangential component, w_i the
       * vertex-quadrature weights of the friction (ContactQuadrature), so
       * that it is the quadratic term eta |v_i|^2 w_i / 2 of the node's
       * dissipation (if `cell_viscosity` is given); the shear prestress
       * tau_0 w_i in the force (if `cell_force` is given).
       */
      template <class Iterator>
      void
      add_contact_terms(const Iterator          &cell,
                        const physics::Material *material,
                        FullMatrix<double>      *cell_viscosity,
                        Vector<double>          *cell_force) const;

      /**
       * Calls function(fe_face) for each face of the cell on the boundary
       * `id`, fe_face reinitialised on it with vertex quadrature (the
       * lumped boundary terms) and `flags`.
       */
      template <class Iterator, class FaceFunction>
      void
      for_each_boundary_face(const Iterator     &cell,
                             types::boundary_id  id,
                             UpdateFlags         flags,
                             const FaceFunction &function) const;

      /**
       * The dashpots of a cell's absorbing faces (boundary_id::absorbing)
       * in the viscosity matrix: rho (c_p n n^T + c_s (I - n n^T)) w_i at
       * every face vertex (antiplane: rho c_s w_i), w_i the vertex
       * quadrature weights, with the cell's material.
       */
      template <class Iterator>
      void
      add_absorbing_terms(const Iterator          &cell,
                          const physics::Material &material,
                          FullMatrix<double>      &cell_viscosity) const;

      struct StepMatrix
      {
        std::array<double, 3>                           coefficients;
        std::unique_ptr<la::LocalMatrix>                local;
        std::unique_ptr<TrilinosWrappers::SparseMatrix> assembled;
      };
      StepMatrix &
      cached_step_matrix(const std::array<double, 3> &coefficients);
      std::vector<StepMatrix> step_matrices;
    };
  } // namespace physics
} // namespace rsfcycle

#endif
