#pragma once
// Strict CSV files, field by field: the format `entourage export` writes and `entourage verify`
// reads back. One record per line (LF, or CRLF), fields separated by commas, a field that holds a
// comma or a double quote written in double quotes with "" for a quote; numbers in the shortest
// text that reads back as the same double (so an export loses nothing). Reading refuses anything
// else: a header that is not exactly the expected columns, a row with another number of fields, a
// field that is not the number or name its column holds. Each refusal is a CsvError whose message
// names file, line, column and the column's name: "DIR/ego.csv:7:8: speed_mps: \"fast\" is not
// a number" (the column is the field's 1-based position, as `entourage check` counts columns).

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace entourage::recording::csv {

class CsvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The columns of one kind of file, in order.
using Columns = std::vector<std::string_view>;

// The fields of a line, unquoted; false (with the 1-based column of the fault in *bad_column and
// what is wrong in *what) if a quote is not closed or not followed by a comma.
bool split_fields(std::string_view line, std::vector<std::string>* fields, std::size_t* bad_column,
                  std::string* what);

// One line being written: fields in column order.
class LineWriter {
 public:
  LineWriter& add(double v);
  LineWriter& add(std::uint64_t v);
  LineWriter& add(std::uint32_t v);
  LineWriter& add(int v);
  LineWriter& add(std::string_view text);  // quoted when it holds a comma, a quote or a line break
  // The line with its LF; the next add() starts a new line.
  const std::string& finish();

 private:
  void separate();
  std::string line_;
  std::size_t fields_ = 0;
  bool finished_ = false;
};

// The header line for `columns`, with its LF.
std::string header_line(const Columns& columns);

// Reads a file row by row; each row's fields are taken in column order.
class Reader {
 public:
  // Opens the file and checks its header; throws CsvError if it cannot be read or the header is
  // not `columns`.
  Reader(std::string path, Columns columns);

  // The next row; false at the end of the file. Throws CsvError for a row with a wrong number of
  // fields or broken quoting.
  bool next();

  // The next field of the row, as a number or a name; throws CsvError if it is not one.
  std::uint64_t u64();
  std::uint32_t u32();
  int integer();
  double number();
  std::string text();
  // A name from `allowed` (the words the writer uses for this column).
  std::string word(const std::vector<std::string_view>& allowed);
  // Refuses the field just taken with `what`.
  [[noreturn]] void fail(const std::string& what) const;

  const std::string& path() const { return path_; }
  std::size_t line() const { return line_; }

 private:
  bool read_line(std::string* line);
  void check_header();
  const std::string& take();
  template <typename T>
  T parse(const char* not_a);  // the next field as T; `not_a` says what it should have been
  [[noreturn]] void fail_at(std::size_t column, const std::string& what) const;

  std::string path_;
  Columns columns_;
  std::ifstream in_;
  std::size_t line_ = 0;
  std::string text_;                 // the current line
  std::vector<std::string> fields_;  // its fields (their strings reused from line to line)
  std::size_t taken_ = 0;
};

}  // namespace entourage::recording::csv
