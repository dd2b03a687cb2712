#pragma once
// A small command-line parser: --name value, --name=value, boolean --flags and positionals,
// with a generated usage text. Errors name the offending argument.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace entourage::cli {

class Args {
 public:
  Args(std::string program, std::string summary);

  void flag(const std::string& name, const std::string& help, bool* target);
  void option(const std::string& name, const std::string& value_name, const std::string& help, std::string* target);
  void option(const std::string& name, const std::string& value_name, const std::string& help, double* target);
  void option(const std::string& name, const std::string& value_name, const std::string& help, int* target);
  void option(const std::string& name, const std::string& value_name, const std::string& help,
              std::uint64_t* target);
  void positional(const std::string& name, const std::string& help, std::string* target);

  // Parses argv[first..]. Returns false on an error (see error()); --help sets help_requested().
  bool parse(int argc, char** argv, int first = 1);
  bool parse(const std::vector<std::string>& args);
  // parse() as a program's first step: on an error prints "PROGRAM: error" and the usage to stderr
  // and gives 2, on --help prints the usage to stdout and gives 0 (the exit code to stop with);
  // nullopt to go on.
  std::optional<int> parse_or_exit(int argc, char** argv, int first = 1);
  bool help_requested() const { return help_; }
  bool was_set(const std::string& name) const;
  const std::string& error() const { return error_; }
  std::string usage() const;

 private:
  struct Spec {
    std::string name;
    std::string value_name;  // empty for flags and positionals
    std::string help;
    std::function<bool(const std::string&)> set;  // false: bad value
    bool is_flag = false;
    bool positional = false;
    bool seen = false;
  };
  Spec* find(const std::string& name);

  std::string program_;
  std::string summary_;
  std::vector<Spec> specs_;
  std::string error_;
  bool help_ = false;
};

}  // namespace entourage::cli
