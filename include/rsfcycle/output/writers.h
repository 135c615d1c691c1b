// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_writers_h
#define rsfcycle_output_writers_h

#include <any>
#include <memory>
#include <rsfcycle/output/sample.h>
#include <rsfcycle/output/writer.h>
#include <rsfcycle/parameters.h>
#include <string>
#include <vector>

namespace rsfcycle
{
  namespace output
  {
    /** What a writer reads of a run, and what a model offers. */
    enum class Field
    {
      /** slip rates and slips of the contact nodes, observations (Sample) */
      contact,
      /** friction stress, normal stress and state of every node (Sample) */
      stresses,
      /** the body on its mesh (Offer::body: a BodySource of snapshots.h) */
      body
    };

    /**
     * What a model offers the writers: its name in messages, its fields
     * and, with Field::body, the body's source (a BodySource<dim>).
     */
    struct Offer
    {
      std::string        model = "this model";
      std::vector<Field> fields{Field::contact, Field::stresses};
      std::any           body;
    };

    /**
     * The outputs by name (`Output/Writers`, like ASPECT's list of
     * postprocessors): "time series", "base profile", "events", "seas",
     * "vtu", "hdf5". A new output is a Writer in output/ (its file pair)
     * and one line in the list of source/output/writers.cc: its name, the
     * fields it needs and how it is made.
     */
    std::string
    writer_names();

    /**
     * Every writer's own entries, each declared once in subsection Output
     * (each writer type names its declaring function in the list).
     */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * Refuse, in one line naming the entry, a writer the list does not know,
     * a writer that needs a field the model does not offer, `seas` without
     * `Output/SEAS/Benchmark` (or `Problem`) and those without `seas`.
     * Throws std::invalid_argument; writes nothing.
     */
    void
    check_writers(const Parameters         &parameters,
                  const std::vector<Field> &offered,
                  const std::string        &model);

    /**
     * The writers of `Output/Writers` (check_writers() first). Bad SEAS
     * positions throw std::invalid_argument (one line naming the entry) on
     * every rank before a file is written.
     */
    std::vector<std::unique_ptr<Writer>>
    make_writers(const Parameters &parameters,
                 const Layout     &layout,
                 const Offer      &offer = {});
  } // namespace output
} // namespace rsfcycle

#endif
