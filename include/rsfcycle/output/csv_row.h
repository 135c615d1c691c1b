// SPDX-License-Identifier: LGPL-2.1-or-later
#ifndef rsfcycle_output_csv_row_h
#define rsfcycle_output_csv_row_h

#include <charconv>
#include <ostream>
#include <string>

namespace rsfcycle
{
  namespace output
  {
    /**
     * One row of a CSV file, formatted with std::to_chars into a buffer that
     * is reused from row to row. Numbers come out as printf's "%.<p>g" (the
     * same characters as an ostream with setprecision(p)), at a fraction of
     * the cost: the spring-slider writes a row per step, and formatting
     * through the ostream was a third of its time loop
     * (benchmarks/time-stepping/README.md).
     */
    class CsvRow
    {
    public:
      /**
       * Start a row whose real numbers have `precision` significant digits,
       * separated by `separator` (a comma; a space in the SEAS files).
       */
      explicit CsvRow(const int precision, const char separator = ',')
        : precision(precision)
        , separator(separator)
      {}

      /** Forget the last row. */
      void
      clear()
      {
        buffer.clear();
      }

      /** Append a real number (a separator first unless the row is empty). */
      CsvRow &
      operator<<(const double value)
      {
        return append(value, precision);
      }

      /**
       * Append a real number with the 17 significant digits that give a
       * double back exactly: times, whose steps (milliseconds in events)
       * are far below `precision` digits of t ~ 1e10 s.
       */
      CsvRow &
      precise(const double value)
      {
        return append(value, 17);
      }

      /** Append a count. */
      CsvRow &
      operator<<(const unsigned long long value)
      {
        separate();
        char       digits[24];
        const auto end =
          std::to_chars(digits, digits + sizeof(digits), value).ptr;
        buffer.append(digits, end - digits);
        return *this;
      }

      CsvRow &
      operator<<(const unsigned int value)
      {
        return *this << static_cast<unsigned long long>(value);
      }

      /** Write the row and a newline to `out`, and start the next one. */
      void
      write_line(std::ostream &out)
      {
        buffer.push_back('\n');
        out.write(buffer.data(), buffer.size());
        buffer.clear();
      }

    private:
      CsvRow &
      append(const double value, const int digits)
      {
        separate();
        char       text[64];
        const auto end = std::to_chars(text,
                                       text + sizeof(text),
                                       value,
                                       std::chars_format::general,
                                       digits)
                           .ptr;
        buffer.append(text, end - text);
        return *this;
      }

      void
      separate()
      {
        if (!buffer.empty())
          buffer.push_back(separator);
      }

      const int   precision;
      const char  separator;
      std::string buffer;
    };
  } // namespace output
} // namespace rsfcycle

#endif
