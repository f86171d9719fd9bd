#include <archdam/base/data_files.h>
#include <archdam/loads/ground_motion.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace archdam::loads
{
  namespace
  {
    /// Whether @p filename ends in .at2 in any letter case.
    bool
    has_at2_extension(const std::string &filename)
    {
      std::string extension =
        std::filesystem::path(filename).extension().string();
      for (char &c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return extension == ".at2";
    }

    /// The record of a component with Source = file.
    AccelerationRecord
    read_component(const GroundMotionParameters::Component &c,
                   const std::string                       &filename,
                   const std::string                       &context)
    {
      RecordFormat format = c.format;
      if (format == RecordFormat::automatic)
        format = has_at2_extension(filename) ? RecordFormat::at2 : RecordFormat::two_column;

      switch (format)
        {
          case RecordFormat::at2:
            // Say so rather than ignore a unit the user believes applies.
            if (c.units != RecordUnits::g)
              throw InputError(context + "Units = " +
                               selection_name(c.units, record_units_names()) +
                               ", but AT2 files are always in g.");
            return read_at2(filename, c.scale);
          case RecordFormat::single_column:
            if (!(c.time_step > 0))
              throw InputError(context +
                               "Format = single-column needs the sample "
                               "spacing: set Time step to a positive value.");
            return read_single_column(filename,
                                      c.time_step,
                                      unit_in_si(c.units),
                                      c.scale);
          case RecordFormat::automatic: // resolved above
          case RecordFormat::two_column:
            break;
        }
      return read_two_column(filename, unit_in_si(c.units), c.scale);
    }
  } // namespace



  RecordFormat
  record_format(const std::string &name, const std::string &context)
  {
    if (const auto format = selection_value(name, record_format_names()))
      return *format;
    throw InputError(context + "format '" + name + "' not recognized (use " +
                     selection_choices(record_format_names()) + ").");
  }



  std::string
  record_file_context(const unsigned int d, const std::string &filename)
  {
    return "Ground motion, Component " + std::string(1, "xyz"[d]) + ", file '" +
           filename + "': ";
  }



  void
  GroundMotionParameters::add_parameters(dealii::ParameterHandler &prm)
  {
    const std::array<std::string, 3> axis      = {{"x", "y", "z"}};
    const std::array<std::string, 3> direction = {
      {"stream (x)", "cross-stream (y)", "vertical (z)"}};
    for (unsigned int d = 0; d < 3; ++d)
      {
        Component &c = components[d];
        prm.enter_subsection("Component " + axis[d]);
        add_selection(
          prm,
          "Source",
          c.source,
          motion_source_names(),
          "Where the " + direction[d] +
            " ground acceleration comes from: file (the record named by "
            "File) or generated (an artificial motion matching the target "
            "spectrum of the subsection Generated motion; File is then "
            "ignored).");
        prm.add_parameter(
          "File",
          c.file,
          "Acceleration record in the " + direction[d] +
            " direction; empty means no ground motion in this direction. A "
            "relative path is looked for in the folder of this parameter "
            "file, then in the data folder (ARCHDAM_DATA_DIR, else data/ of "
            "the source tree), which holds the shipped records as "
            "ground_motions/NAME.AT2 (doc/user-guide.md).",
          dealii::Patterns::FileName(dealii::Patterns::FileName::input));
        add_selection(
          prm,
          "Format",
          c.format,
          record_format_names(),
          "File format: AT2 (PEER, in g), two-column (time and acceleration "
          "on each line), single-column (one acceleration per line, spaced "
          "by Time step) or auto (AT2 if the name ends in .AT2, else "
          "two-column).");
        add_selection(
          prm,
          "Units",
          c.units,
          record_units_names(),
          "Unit of the accelerations in a text file; AT2 files are "
          "always in g.");
        prm.add_parameter(
          "Time step",
          c.time_step,
          "Spacing of the samples of a single-column file, s (other "
          "formats give their own times).",
          dealii::Patterns::Double(0));
        prm.add_parameter(
          "Scale factor",
          c.scale,
          "Factor applied to the record (dimensionless), from -1000 to 1000; "
          "a negative value reverses its direction.",
          dealii::Patterns::Double(-1e3, 1e3));
        prm.enter_subsection("Processing");
        c.processing.add_parameters(prm);
        prm.leave_subsection();
        prm.leave_subsection();
      }
    prm.enter_subsection("Generated motion");
    generated.add_parameters(prm);
    prm.leave_subsection();
    prm.add_parameter("Largest plausible PGA", largest_pga,
                      "The largest peak ground acceleration of a component [g], as read, "
                      "scaled and processed: a larger one is refused as a units error (a "
                      "record in cm/s^2 read as g is 981 times too strong). 0 = no limit.",
                      dealii::Patterns::Double(0.));
  }



  GroundMotion::GroundMotion(const GroundMotionParameters &p,
                             const std::string            &base_directory)
  {
    for (unsigned int d = 0; d < 3; ++d)
      {
        const GroundMotionParameters::Component &c    = p.components[d];
        const std::string                        axis = std::string(1, "xyz"[d]);
        std::string                              context;

        if (c.source == MotionSource::generated)
          {
            context = "Ground motion, Component " + axis + " (generated): ";
            const GenerationSettings settings =
              p.generated.settings(d, "Ground motion, Generated motion: ");
            try
              {
                records[d] = generate_artificial_motion(settings, &reports[d]);
              }
            catch (const InputError &e)
              {
                throw InputError(context + e.what());
              }
            generated[d] = true;
            for (double &a : records[d].values)
              a *= c.scale;
          }
        else
          {
            if (c.file.empty())
              continue;
            const std::string filename = find_input_file(
              c.file, base_directory, "Ground motion/Component " + axis + "/File");
            context    = record_file_context(d, filename);
            records[d] = read_component(c, filename, context);
          }

        processing_applied[d] = c.processing.description();
        if (c.processing.any())
          {
            const std::string source = records[d].source;
            records[d] = process(records[d], c.processing, context + "processing: ");
            records[d].source = source;
          }

        const double pga = records[d].peak() / standard_gravity;
        if (p.largest_pga > 0 && pga > p.largest_pga)
          {
            std::ostringstream text;
            text << context << "its peak ground acceleration, as read, scaled and processed, is "
                 << std::setprecision(4) << pga << " g, above Ground motion/Largest plausible PGA = "
                 << p.largest_pga << " g: check the record's Units (a record in cm/s^2 read as g "
                 << "is 981 times too strong), its Scale factor and its Processing; set the "
                 << "limit higher (or 0) if the motion is meant.";
            throw InputError(text.str());
          }
      }
  }



  dealii::Tensor<1, 3>
  GroundMotion::acceleration(const double t) const
  {
    dealii::Tensor<1, 3> a;
    for (unsigned int d = 0; d < 3; ++d)
      if (has_component(d))
        a[d] = records[d].value(t);
    return a;
  }



  bool
  GroundMotion::has_component(const unsigned int d) const
  {
    AssertIndexRange(d, 3);
    return !records[d].times.empty();
  }



  bool
  GroundMotion::empty() const
  {
    return !has_component(0) && !has_component(1) && !has_component(2);
  }



  double
  GroundMotion::duration() const
  {
    double duration = 0.;
    for (unsigned int d = 0; d < 3; ++d)
      if (has_component(d))
        duration = std::max(duration, records[d].duration());
    return duration;
  }



  const AccelerationRecord &
  GroundMotion::record(const unsigned int d) const
  {
    Assert(has_component(d),
           dealii::ExcMessage("This ground-motion component has no record."));
    return records[d];
  }



  const std::string &
  GroundMotion::processing(const unsigned int d) const
  {
    AssertIndexRange(d, 3);
    return processing_applied[d];
  }

  const GenerationReport *
  GroundMotion::generation_report(const unsigned int d) const
  {
    AssertIndexRange(d, 3);
    return generated[d] ? &reports[d] : nullptr;
  }
} // namespace archdam::loads
