// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_physics_green_operator_h
#define rsfcycle_physics_green_operator_h

#include <cstdint>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <rsfcycle/physics/discretisation.h>
#include <rsfcycle/physics/global_system.h>
#include <rsfcycle/physics/scene.h>
#include <rsfcycle/solvers/hierarchical_matrix.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace physics
  {
    /**
     * The fault's Green's functions of a quasi-static elastic bulk
     * (doc/model.md §8.1). The dofs split into the contact's tangential dofs c
     * (one per contact node in 2D, two in 3D: the slip s), the fixed dofs b
     * (the loads' prescribed displacement u_b(t) = t v_b from t = 0, the held
     * normal components, hanging nodes) and the others I. With the bulk in
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
     * The contact nodes are numbered rank by rank (GlobalSystem::
     * contact_dofs); a rank holds the rows of S, g0, g1 of its own nodes,
     * first_row ... first_row + n_rows() - 1 (S is symmetric: it computes
     * them as the columns K_II^-1 K_Ic of its nodes, with a CHOLMOD factor
     * of the whole K_II on every rank, `block_size` right-hand sides at a
     * time), and all of O, o0, o1. The rows are kept dense or, after
     * compress(), as H-matrices (solvers::HierarchicalMatrix) of the ranks'
     * parts of S's lower triangle.
     */
    struct GreenOperator
    {
      dealii::FullMatrix<double> S;  // n_rows x n_c [N/m^(dim-1) per m]
      dealii::Vector<double>     g0; // n_rows [N/m^(3-dim)]
      dealii::Vector<double>     g1; // n_rows [N/m^(3-dim) per s]
      dealii::FullMatrix<double> O;  // n_obs x n_c [-]
      dealii::Vector<double>     o0; // [m]
      dealii::Vector<double>     o1; // [m/s]
      /**
       * A split fault's normal coupling (GlobalSystem::normal_rows), this
       * rank's rows: the compressive normal force of each contact dof's
       * node, n0 + t n1 + N s (BP3's slip-induced normal stress change
       * times the node's weight), as the observations'; empty without.
       */
      dealii::FullMatrix<double> N;  // n_rows x n_c [N/m^(dim-1) per m]
      dealii::Vector<double>     n0; // n_rows [N/m^(3-dim)]
      dealii::Vector<double>     n1; // n_rows [N/m^(3-dim) per s]
      bool                       normal_coupling = false;
      /**
       * compress() found this rank's N rounding noise, at most 1e-10 of S
       * in the Frobenius norm (a vertical fault: the dip slip of an
       * antisymmetric problem leaves the normal stress unchanged), and
       * dropped it: compressed to a relative tolerance, noise keeps every
       * block at full rank (40 MB and a product 100 times slower than S's
       * for BP3 at 90 degrees). apply_normal() then gives n0 + t n1.
       */
      bool         normal_negligible = false;
      unsigned int first_row         = 0;
      unsigned int n_nodes           = 0; // n_c, all ranks
      unsigned int n_interior        = 0;
      unsigned int n_blocks          = 0; // multi-RHS solves
      /** The Cholesky factor's size (one per node), for the log. */
      double factor_megabytes = 0;
      /**
       * S as H-matrices, once compress() has run, split among the ranks as
       * its lower triangle: this rank's product rows P = product_begin ...
       * product_end - 1 (not its own rows: chosen so that every rank's
       * share of the triangle is the same), `compressed` the diagonal block
       * S(P, P) (symmetric, its lower triangle stored) and
       * `compressed_left` the block left of it, S(P, 0 ... product_begin -
       * 1) (none on the first rank), applied as stored and transposed (S
       * symmetric: the transposed block is the rows above P right of the
       * diagonal). On one rank P is all rows: the lower triangle of S.
       * `compressed_normal`: this rank's own rows of N.
       */
      std::shared_ptr<const solvers::HierarchicalMatrix> compressed,
        compressed_left, compressed_normal;
      unsigned int product_begin = 0, product_end = 0;
      /** Every rank's number of own rows (the products' reduce-scatter). */
      std::vector<int> row_counts;
      MPI_Comm         communicator = MPI_COMM_SELF;
      /** The product's sum over all rows before the reduce-scatter. */
      mutable std::vector<double> product_work;

      unsigned int
      n_contact() const
      {
        return n_nodes;
      }

      unsigned int
      n_rows() const
      {
        return g0.size();
      }

      /**
       * force = this rank's rows of S times slip (all n_c nodes). If S is
       * compressed, collective: each rank applies its part of the triangle
       * (the diagonal block, the left block and its transpose) and the
       * ranks' sums are reduced onto the own rows (MPI_Reduce_scatter);
       * else each own row a vectorised dot product (3 - 8 times
       * FullMatrix::vmult, whose one running sum serialises the adds;
       * benchmarks/green-function/README.md).
       */
      void
      apply(const double *slip, double *force) const;

      /** Whether compress() has run (S's products are then collective). */
      bool
      is_compressed() const
      {
        return !row_counts.empty();
      }

      /** Numbers and blocks this rank's H-matrices of S hold. */
      std::size_t
      stored_entries() const;
      /** Bytes of those numbers. */
      std::size_t
      memory_consumption() const;
      std::size_t
      n_low_rank_blocks() const;
      std::size_t
      n_dense_blocks() const;

      /**
       * With the normal coupling: force = n0 + t n1 + N slip for this
       * rank's rows (the H-matrix's product if N is compressed).
       */
      void
      apply_normal(const double *slip, double t, double *force) const;

      /**
       * Collectively, compress S's lower triangle as H-matrices of relative
       * tolerance `tolerance`, stored in `precision`, split among the
       * ranks of `communicator`
       * (above; the rows of S a rank's product rows need from other ranks
       * are sent to it), node k at the point (points[dim k], ...) for all
       * n_c nodes, and return the largest relative error (2-norm) of the
       * compressed product against the dense one for two test slips
       * (uniform, and pseudo-random), over this rank's rows; this rank's
       * rows of N too (not symmetric), the error the larger of the two,
       * unless N is negligible (normal_negligible). S and N stay until
       * release_dense().
       */
      double
      compress(const std::vector<double>             &points,
               unsigned int                           dim,
               double                                 tolerance,
               MPI_Comm                               communicator,
               solvers::HierarchicalMatrix::Precision precision =
                 solvers::HierarchicalMatrix::Precision::double_precision);

      /** Free the dense S and N once they are compressed and written. */
      void
      release_dense();
    };

    /**
     * This rank's part of the operator of the gathered system (the same
     * on every rank but for the rows).
     */
    GreenOperator
    compute_green_operator(const GlobalSystem &system,
                           MPI_Comm            communicator,
                           unsigned int        block_size = 64);

    /**
     * A CRC32 of everything the operator depends on: the assembled
     * stiffness, the fixed dofs and their prescribed velocity, the body
     * force and prestress, the contact's dofs (and their split among the
     * ranks) and the observation rows. Two runs with the same value have
     * the same operator (the same mesh, material, boundary roles, loads,
     * observation points and number of ranks: the dof numbering depends on
     * it); the friction, the normal stress and the radiation damping do
     * not enter.
     */
    std::uint32_t
    operator_fingerprint(const GlobalSystem &system);

    /**
     * The format of the operator file. Increase it whenever its layout
     * changes: a file of another format is refused, never misread.
     */
    constexpr std::uint32_t green_operator_format = 3;

    /**
     * Write `file` (green-operator.bin in a run folder), collectively: a
     * header (magic "rsfgreen", format, fingerprint, the sizes n_dofs, n_c,
     * n_o, the number of ranks, CRC32 of the payload and of the header)
     * and the payload (g0, g1, O, o0, o1, then the rows of S, as doubles,
     * the nodes rank by rank), each rank writing its rows in turn; with the
     * normal coupling (a flag in the header) then, rank by rank, the rows
     * of n0, n1 and N, each as (n0, n1, row of N). Written
     * to file.tmp and renamed: the file is either complete or absent. A
     * failed write is a std::runtime_error naming the file on every rank.
     */
    void
    write_green_operator(const std::string   &file,
                         const GreenOperator &op,
                         std::uint32_t        fingerprint,
                         std::uint64_t        n_dofs,
                         MPI_Comm             communicator);

    /**
     * Read this rank's part of `file` and check the whole file against this
     * run: a missing, truncated or damaged (checksum) file, another format,
     * or one written for another mesh, material, load or number of ranks
     * (sizes, fingerprint) is an std::invalid_argument of one line, "what:
     * file: what is wrong", on every rank. `first_row` and `n_rows`: this
     * rank's contact nodes.
     */
    GreenOperator
    read_green_operator(const std::string &file,
                        const std::string &what,
                        std::uint32_t      fingerprint,
                        std::uint64_t      n_dofs,
                        unsigned int       n_contact,
                        unsigned int       n_observations,
                        unsigned int       first_row,
                        unsigned int       n_rows,
                        MPI_Comm           communicator);
  } // namespace physics
} // namespace rsfcycle

#endif
