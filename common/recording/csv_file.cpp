#include "recording/csv_file.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>
#include <utility>

namespace entourage::recording::csv {

namespace {

std::string joined(const Columns& columns) {
  std::string s;
  for (const auto& c : columns) {
    if (!s.empty()) s += ',';
    s += c;
  }
  return s;
}

bool needs_quotes(std::string_view text) { return text.find_first_of(",\"\r\n") != std::string_view::npos; }

// Parses a whole field as T (an integer or a double); false if it is not exactly one.
template <typename T>
bool parse_whole(const std::string& field, T* value, bool* out_of_range) {
  const char* first = field.data();
  const char* last = first + field.size();
  const auto [end, ec] = std::from_chars(first, last, *value);
  *out_of_range = ec == std::errc::result_out_of_range;
  return ec == std::errc() && end == last;
}

}  // namespace

bool split_fields(std::string_view line, std::vector<std::string>* fields, std::size_t* bad_column,
                  std::string* what) {
  std::size_t n = 0;  // fields so far; their strings are reused to keep their capacity
  std::size_t i = 0;
  for (;;) {
    if (n == fields->size()) fields->emplace_back();
    std::string& field = (*fields)[n++];
    field.clear();
    if (i < line.size() && line[i] == '"') {
      for (++i;; ++i) {
        if (i == line.size()) {
          *bad_column = n;
          *what = "a quoted field is not closed on its line";
          return false;
        }
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            ++i;
          } else {
            ++i;
            break;
          }
        } else {
          field += line[i];
        }
      }
      if (i < line.size() && line[i] != ',') {
        *bad_column = n;
        *what = "a quoted field goes on after its closing quote";
        return false;
      }
    } else {
      const std::size_t end = std::min(line.find(',', i), line.size());
      field.assign(line.substr(i, end - i));
      if (field.find('"') != std::string::npos) {
        *bad_column = n;
        *what = "a quote inside a field that does not start with one";
        return false;
      }
      i = end;
    }
    if (i == line.size()) break;
    ++i;  // the comma
  }
  fields->resize(n);
  return true;
}

void LineWriter::separate() {
  if (finished_) {
    line_.clear();
    fields_ = 0;
    finished_ = false;
  }
  if (fields_++ > 0) line_ += ',';
}

LineWriter& LineWriter::add(double v) {
  separate();
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);  // shortest round trip
  line_.append(buffer, ec == std::errc() ? end : buffer);
  return *this;
}

LineWriter& LineWriter::add(std::uint64_t v) {
  separate();
  line_ += std::to_string(v);
  return *this;
}

LineWriter& LineWriter::add(std::uint32_t v) { return add(static_cast<std::uint64_t>(v)); }

LineWriter& LineWriter::add(int v) {
  separate();
  line_ += std::to_string(v);
  return *this;
}

LineWriter& LineWriter::add(std::string_view text) {
  separate();
  if (!needs_quotes(text)) {
    line_ += text;
    return *this;
  }
  line_ += '"';
  for (char c : text) {
    if (c == '"') line_ += '"';
    line_ += c;
  }
  line_ += '"';
  return *this;
}

const std::string& LineWriter::finish() {
  line_ += '\n';
  finished_ = true;
  return line_;
}

std::string header_line(const Columns& columns) { return joined(columns) + "\n"; }

Reader::Reader(std::string path, Columns columns) : path_(std::move(path)), columns_(std::move(columns)) {
  in_.open(path_, std::ios::binary);
  if (!in_) throw CsvError(path_ + ": cannot open: " + std::strerror(errno));
  check_header();
}

bool Reader::read_line(std::string* line) {
  if (!std::getline(in_, *line)) return false;
  ++line_;
  if (!line->empty() && line->back() == '\r') line->pop_back();
  return true;
}

void Reader::check_header() {
  std::string line;
  if (!read_line(&line)) throw CsvError(path_ + ":1: the file is empty; expected the header " + joined(columns_));
  std::vector<std::string> got;
  std::size_t bad = 0;
  std::string what;
  if (!split_fields(line, &got, &bad, &what)) fail_at(bad, what);
  for (std::size_t i = 0; i < std::max(got.size(), columns_.size()); ++i) {
    const std::string at = path_ + ":1:" + std::to_string(i + 1) + ": ";
    if (i >= got.size()) {
      throw CsvError(at + std::string(columns_[i]) + ": missing (the header ends after column " + std::to_string(i) + ")");
    }
    if (i >= columns_.size()) {
      throw CsvError(at + "unexpected column \"" + got[i] + "\" after the last one, " + std::string(columns_.back()));
    }
    if (got[i] != columns_[i]) {
      throw CsvError(at + std::string(columns_[i]) + ": expected here, found \"" + got[i] + "\" (the header must be " +
                     joined(columns_) + ")");
    }
  }
}

bool Reader::next() {
  if (!read_line(&text_)) return false;
  taken_ = 0;
  std::size_t bad = 0;
  std::string what;
  if (!split_fields(text_, &fields_, &bad, &what)) fail_at(bad, what);
  if (fields_.size() != columns_.size()) {
    const std::string count = "the row has " + std::to_string(fields_.size()) +
                              (fields_.size() == 1 ? " field" : " fields") + ", the header " +
                              std::to_string(columns_.size());
    if (fields_.size() < columns_.size()) fail_at(fields_.size() + 1, "missing: " + count);
    fail_at(columns_.size() + 1, count);
  }
  return true;
}

const std::string& Reader::take() {
  if (taken_ >= fields_.size()) throw std::logic_error(path_ + ": more fields taken than the row has");
  return fields_[taken_++];
}

template <typename T>
T Reader::parse(const char* not_a) {
  const std::string& f = take();
  T v{};
  bool out_of_range = false;
  if (!parse_whole(f, &v, &out_of_range)) {
    fail("\"" + f + (out_of_range ? "\" is out of range" : "\" is not " + std::string(not_a)));
  }
  return v;
}

std::uint64_t Reader::u64() { return parse<std::uint64_t>("a whole number of 0 or more"); }
std::uint32_t Reader::u32() { return parse<std::uint32_t>("a whole number of 0 or more"); }
int Reader::integer() { return parse<int>("a whole number"); }
double Reader::number() { return parse<double>("a number"); }

std::string Reader::text() { return take(); }

std::string Reader::word(const std::vector<std::string_view>& allowed) {
  const std::string& f = take();
  for (const auto& a : allowed) {
    if (f == a) return f;
  }
  fail("\"" + f + "\" is not one of " + joined(allowed));
}

void Reader::fail(const std::string& what) const { fail_at(std::max<std::size_t>(taken_, 1), what); }

void Reader::fail_at(std::size_t column, const std::string& what) const {
  std::string at = path_ + ":" + std::to_string(line_) + ":" + std::to_string(column) + ": ";
  if (column >= 1 && column <= columns_.size()) at += std::string(columns_[column - 1]) + ": ";
  throw CsvError(at + what);
}

}  // namespace entourage::recording::csv
