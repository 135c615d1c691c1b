#ifndef rsfcycle_physics_green_operator_h
#define rsfcycle_physics_green_operator_h

#include <cstdint>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/solvers/hierarchical_matrix.h>
#include <rsfcycle/solvers/spatial_problem.h>
#include <string>
#include <utility>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    /**
     * The fault's Green's functions of a quasi-static elastic bulk
     * (MODEL.md §8.1). The dofs split into the contact's tangential dofs c
     * (one per contact node: the slip s), the fixed dofs b (the loads'
     * prescribed displacement u_b(t) = t v_b from t = 0, the held normal
     * components, hanging nodes) and the others I. With the bulk in
     * equilibrium, K_II u_I = f_I - K_Ic s - K_Ib u_b(t), the force the
     * body exerts on contact node k (which friction and radiation damping
     * balance) is
     *   F(s, t) = f_c - (K u)_c = g0 + t g1 - S s,
     *   S  = K_cc - K_cI K_II^-1 K_Ic  (the Schur complement),
     *   g0 = f_c - K_cI K_II^-1 f_I,
     *   g1 = -K_cb v_b + K_cI K_II^-1 K_Ib v_b,
     * f the body force and the shear prestress tau_0 w_k of the
     * discretisation; F / w_k is the elastic shear traction. An
     * observation u_p = P u (a surface station) is, the same way,
     *   u_p(s, t) = o0 + t o1 + O s,   O = P_c - P_I K_II^-1 K_Ic.
     * Everything is computed from the assembled stiffness with one sparse
     * Cholesky factor of K_II (CHOLMOD) and one solve per contact node, the
     * right-hand sides `block_size` at a time, one MPI rank. S is kept
     * dense or, after compress(), as an H-matrix (solvers::
     * HierarchicalMatrix).
     */
    struct GreenOperator
    {
      dealii::FullMatrix<double> S;  // n_c x n_c [N/m^(dim-1) per m]
      dealii::Vector<double>     g0; // [N/m^(3-dim)]
      dealii::Vector<double>     g1; // [N/m^(3-dim) per s]
      dealii::FullMatrix<double> O;  // n_obs x n_c [-]
      dealii::Vector<double>     o0; // [m]
      dealii::Vector<double>     o1; // [m/s]
      unsigned int               n_interior = 0;
      unsigned int               n_blocks   = 0; // multi-RHS solves
      /** S as an H-matrix, once compress() has run; apply() then uses it. */
      std::shared_ptr<const solvers::HierarchicalMatrix> compressed;

      unsigned int
      n_contact() const
      {
        return g0.size();
      }

      /**
       * force = S slip: the H-matrix's product if S is compressed, else
       * each row a vectorised dot product (3 - 8 times FullMatrix::vmult,
       * whose one running sum serialises the adds;
       * benchmarks/green-function/README.md).
       */
      void
      apply(const double *slip, double *force) const;

      /**
       * Compress S as an H-matrix of relative tolerance `tolerance`, row k
       * at the point (points[dim k], ...), and return the largest relative
       * error (2-norm) of the compressed product against the dense one for
       * two test slips (uniform, and pseudo-random). S stays until
       * release_dense().
       */
      double
      compress(const std::vector<double> &points,
               unsigned int               dim,
               double                     tolerance);

      /** Free the dense S once it is compressed and written. */
      void
      release_dense();
    };

    /**
     * An observation as a weighted sum of dofs: (local index, weight),
     * hanging dofs replaced by the dofs they depend on.
     */
    using ObservationRow = std::vector<std::pair<unsigned int, double>>;

    /**
     * The rows of the scene's observation points: the physical vertical
     * displacement (antiplane: the out-of-plane one) interpolated in the
     * cell around each point (one rank).
     */
    template <int dim>
    std::vector<ObservationRow>
    observation_rows(const Discretisation<dim> &discretisation,
                     const Scene<dim>          &scene,
                     bool                       antiplane);

    /**
     * The operator of the assembled discretisation for the contact nodes
     * of `contact` (one tangential dof each) and the observation rows.
     * Throws std::invalid_argument on more than one MPI rank or a node
     * with two tangential dofs.
     */
    template <int dim>
    GreenOperator
    compute_green_operator(const Discretisation<dim>         &discretisation,
                           const solvers::ContactSet         &contact,
                           const std::vector<ObservationRow> &observations,
                           unsigned int                       block_size = 64);

    /**
     * A CRC32 of everything the operator depends on: the assembled
     * stiffness, the fixed dofs and their prescribed velocity, the body
     * force and prestress, the contact's dofs and the observation rows.
     * Two runs with the same value have the same operator (the same mesh,
     * material, boundary roles, loads and observation points); the
     * friction, the normal stress and the radiation damping do not enter.
     */
    template <int dim>
    std::uint32_t
    operator_fingerprint(const Discretisation<dim>         &discretisation,
                         const solvers::ContactSet         &contact,
                         const std::vector<ObservationRow> &observations);

    /**
     * The format of the operator file. Increase it whenever its layout
     * changes: a file of another format is refused, never misread.
     */
    constexpr std::uint32_t green_operator_format = 1;

    /**
     * Write `file` (green-operator.bin in a run folder): a header (magic
     * "rsfgreen", format, fingerprint, the sizes n_dofs, n_c, n_o, CRC32 of
     * the payload and of the header) and the payload (S, g0, g1, O, o0, o1
     * as doubles, row by row). Written to file.tmp and renamed: the file is
     * either complete or absent. A failed write is a std::runtime_error
     * naming the file.
     */
    void
    write_green_operator(const std::string   &file,
                         const GreenOperator &op,
                         std::uint32_t        fingerprint,
                         std::uint64_t        n_dofs);

    /**
     * Read `file` and check it against this run: a missing, truncated or
     * damaged (checksum) file, another format, or one written for another
     * mesh, material or load (sizes, fingerprint) is an
     * std::invalid_argument of one line, "what: file: what is wrong".
     */
    GreenOperator
    read_green_operator(const std::string &file,
                        const std::string &what,
                        std::uint32_t      fingerprint,
                        std::uint64_t      n_dofs,
                        unsigned int       n_contact,
                        unsigned int       n_observations);
  } // namespace physics
} // namespace rsfcycle

#endif
