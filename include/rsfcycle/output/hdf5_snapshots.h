// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_hdf5_snapshots_h
#define rsfcycle_output_hdf5_snapshots_h

#include <deal.II/base/data_out_base.h>
#include <rsfcycle/output/snapshots.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /**
     * HDF5 + XDMF snapshots (`Output/Writers = hdf5`): the body's
     * solution/solution-N.h5 and the fault's fault/fault-N.h5, one file per
     * snapshot for any number of ranks (deal.II's parallel HDF5), indexed by
     * solution.xdmf and fault.xdmf, which ParaView and VisIt open (XDMF
     * reader). The same fields and times as the VTU snapshots; the XDMF
     * records are kept in checkpoints, so that a resumed run continues
     * them.
     */
    template <int dim>
    class Hdf5Snapshots : public Snapshots<dim>
    {
    public:
      using Snapshots<dim>::Snapshots;

      std::string
      name() const override
      {
        return "HDF5 snapshots";
      }

    protected:
      void
      store(dealii::DataOutInterface<dim, dim>     &body,
            dealii::DataOutInterface<dim - 1, dim> &fault,
            double                                  t,
            unsigned int                            number) override;

      void
      save_records(boost::archive::binary_oarchive &archive) const override;
      void
      load_records(boost::archive::binary_iarchive &archive) override;

      double
      last_time() const override
      {
        return times.empty() ? -1. : times.back();
      }

    private:
      /**
       * Write one data set to `stem`.h5 and the XDMF file `index` of its
       * records (with the new one appended to `records`).
       */
      template <int patch_dim>
      void
      write_set(dealii::DataOutInterface<patch_dim, dim> &data,
                const std::string                        &stem,
                const std::string                        &index,
                double                                    t,
                std::vector<dealii::XDMFEntry>           &records) const;

      std::vector<double>            times;
      std::vector<dealii::XDMFEntry> records, fault_records;
    };
  } // namespace output
} // namespace rsfcycle

#endif
