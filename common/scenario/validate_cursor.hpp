#pragma once
// Internal to scenario validation: a cursor over the parsed message tree that knows where each
// field was written (file, line, column) and reports problems there, and checks shared by the
// validation files. Not part of the library's interface.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <google/protobuf/text_format.h>

#include "scenario/loader.hpp"
#include "scenario/scenario.pb.h"

namespace entourage::scenario::detail {

using google::protobuf::Message;
using google::protobuf::TextFormat;

struct Location {
  int line = 0;
  int column = 0;
};

inline std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// A position in the message tree: the message, where its fields were written, and its path.
class Cursor {
 public:
  Cursor(const Message& msg, const TextFormat::ParseInfoTree* tree, std::string path, Location where,
         const std::string& file, std::vector<Problem>* problems)
      : msg_(msg), tree_(tree), path_(std::move(path)), where_(where), file_(file), problems_(problems) {}

  Location loc(const std::string& field, int index = -1) const {
    const auto* fd = msg_.GetDescriptor()->FindFieldByName(field);
    if (tree_ != nullptr && fd != nullptr) {
      const auto l = tree_->GetLocation(fd, fd->is_repeated() ? std::max(index, 0) : -1);
      if (l.line >= 0) return {l.line + 1, l.column + 1};
    }
    return where_;
  }

  std::string path_of(const std::string& field, int index = -1) const {
    std::string p = path_.empty() ? field : path_ + "." + field;
    if (index >= 0) p += "[" + std::to_string(index) + "]";
    return p;
  }

  Cursor child(const Message& sub, const std::string& field, int index = -1) const {
    const auto* fd = msg_.GetDescriptor()->FindFieldByName(field);
    const TextFormat::ParseInfoTree* t = nullptr;
    if (tree_ != nullptr && fd != nullptr) t = tree_->GetTreeForNested(fd, fd->is_repeated() ? index : -1);
    return Cursor(sub, t, path_of(field, index), loc(field, index), file_, problems_);
  }

  void fail(const std::string& field, const std::string& message, int index = -1) const {
    const Location l = loc(field, index);
    problems_->push_back({file_, l.line, l.column, path_of(field, index), message});
  }
  void fail_here(const std::string& message) const {
    problems_->push_back({file_, where_.line, where_.column, path_, message});
  }

  bool has(const std::string& field) const {
    const auto* fd = msg_.GetDescriptor()->FindFieldByName(field);
    return fd != nullptr && msg_.GetReflection()->HasField(msg_, fd);
  }

  bool require(const std::string& field) const {
    if (has(field)) return true;
    fail(field, "is required");
    return false;
  }

  // value in [lo, hi]; `lo_open` makes the lower bound exclusive.
  void range(const std::string& field, double value, double lo, double hi, bool lo_open = false) const {
    if (!std::isfinite(value) || value < lo || (lo_open && value == lo) || value > hi) {
      fail(field, "must be in " + std::string(lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "] (got " +
                      fmt(value) + ")");
    }
  }

 private:
  const Message& msg_;
  const TextFormat::ParseInfoTree* tree_;
  std::string path_;
  Location where_;
  const std::string& file_;
  std::vector<Problem>* problems_;
};

// A Normal: mean present, sd >= 0, min <= mean <= max, and every value it can draw in [lo, hi].
inline void check_normal(const Cursor& c, const Normal& n, double lo, double hi, bool lo_open) {
  if (!c.require("mean")) return;
  c.range("mean", n.mean(), lo, hi, lo_open);
  c.range("sd", n.sd(), 0.0, hi);
  const double mn = n.has_min() ? n.min() : n.mean() - 3.0 * n.sd();
  const double mx = n.has_max() ? n.max() : n.mean() + 3.0 * n.sd();
  if (n.has_min()) c.range("min", mn, lo, hi, lo_open);
  if (n.has_max()) c.range("max", mx, lo, hi, lo_open);
  if (mn > mx) c.fail("min", "must not exceed max (" + fmt(mn) + " > " + fmt(mx) + ")");
  if (n.has_min() && n.mean() < mn) c.fail("mean", "is below min");
  if (n.has_max() && n.mean() > mx) c.fail("mean", "is above max");
  if (!n.has_min() && n.sd() > 0.0 && (mn < lo || (lo_open && mn <= lo))) {
    c.fail("sd", "mean - 3 sd = " + fmt(mn) + " leaves the valid range; set min");
  }
}

inline void check_optional_normal(const Cursor& c, const std::string& field, const Normal& n, double lo, double hi,
                           bool lo_open) {
  if (c.has(field)) check_normal(c.child(n, field), n, lo, hi, lo_open);
}

}  // namespace entourage::scenario::detail
