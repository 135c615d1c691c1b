// SPDX-License-Identifier: LGPL-2.1-or-later
#include <boost/serialization/vector.hpp>
#include <deal.II/base/utilities.h>
#include <rsfcycle/output/hdf5_snapshots.h>

namespace rsfcycle
{
  namespace output
  {
    using namespace dealii;

    template <int dim>
    template <int patch_dim>
    void
    Hdf5Snapshots<dim>::write_set(DataOutInterface<patch_dim, dim> &data,
                                  const std::string                &stem,
                                  const std::string                &index,
                                  const double                      t,
                                  std::vector<XDMFEntry> &records) const
    {
      // every vertex of every patch kept (no merging), as the VTU files
      DataOutBase::DataOutFilter filter(
        DataOutBase::DataOutFilterFlags(false, true));
      data.write_filtered_data(filter);
      const std::string h5 = stem + ".h5";
      data.write_hdf5_parallel(filter,
                               this->in_folder(h5),
                               this->communicator());
      // the XDMF file names the .h5 files relative to the run folder
      records.push_back(
        data.create_xdmf_entry(filter, h5, t, this->communicator()));
      data.write_xdmf_file(records,
                           this->dir + "/" + index,
                           this->communicator());
    }


    template <int dim>
    void
    Hdf5Snapshots<dim>::store(DataOutInterface<dim, dim>     &body,
                              DataOutInterface<dim - 1, dim> &fault,
                              const double                    t,
                              const unsigned int              number)
    {
      const std::string n = Utilities::int_to_string(number, 5);
      write_set(body, "solution/solution-" + n, "solution.xdmf", t, records);
      write_set(fault, "fault/fault-" + n, "fault.xdmf", t, fault_records);
      times.push_back(t);
    }


    template <int dim>
    void
    Hdf5Snapshots<dim>::save_records(
      boost::archive::binary_oarchive &archive) const
    {
      archive << times << records << fault_records;
    }


    template <int dim>
    void
    Hdf5Snapshots<dim>::load_records(boost::archive::binary_iarchive &archive)
    {
      archive >> times >> records >> fault_records;
    }


    template class Hdf5Snapshots<2>;
    template class Hdf5Snapshots<3>;
  } // namespace output
} // namespace rsfcycle
