#include "scenario/loader.hpp"

#include <fstream>
#include <sstream>

#include <google/protobuf/io/tokenizer.h>
#include <google/protobuf/text_format.h>

#include "scenario/resolve.hpp"
#include "scenario/scenario.pb.h"
#include "scenario/validate.hpp"

namespace entourage::scenario {

namespace {

class Collector : public google::protobuf::io::ErrorCollector {
 public:
  Collector(std::string path, std::vector<Problem>* problems) : path_(std::move(path)), problems_(problems) {}
  void AddError(int line, google::protobuf::io::ColumnNumber column, const std::string& message) override {
    problems_->push_back({path_, line + 1, column + 1, "", message});
  }
  void AddWarning(int line, google::protobuf::io::ColumnNumber column, const std::string& message) override {
    problems_->push_back({path_, line + 1, column + 1, "", "warning: " + message});
  }

 private:
  std::string path_;
  std::vector<Problem>* problems_;
};

}  // namespace

std::string Problem::to_string() const {
  std::ostringstream os;
  os << file;
  if (line > 0) os << ':' << line << ':' << column;
  os << ": ";
  if (!field.empty()) os << field << ": ";
  os << message;
  return os.str();
}

Loaded load_text(const std::string& text, const std::string& path) {
  Loaded out;
  out.path = path;
  out.text = text;
  auto proto = std::make_shared<Scenario>();
  google::protobuf::TextFormat::Parser parser;
  Collector collector(path, &out.problems);
  parser.RecordErrorsTo(&collector);
  google::protobuf::TextFormat::ParseInfoTree tree;
  parser.WriteLocationsTo(&tree);
  if (!parser.ParseFromString(text, proto.get())) {
    if (out.problems.empty()) out.problems.push_back({path, 0, 0, "", "cannot parse the scenario"});
    return out;  // a half-filled message is discarded
  }
  out.proto = proto;
  validate(*proto, tree, path, &out.problems);
  if (out.problems.empty()) out.config = resolve(*proto);
  return out;
}

Loaded load_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Loaded out;
    out.path = path;
    out.problems.push_back({path, 0, 0, "", "cannot open the file"});
    return out;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return load_text(buffer.str(), path);
}

}  // namespace entourage::scenario
