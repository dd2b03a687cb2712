#include "cli/args.hpp"

#include <iostream>
#include <sstream>

namespace entourage::cli {

namespace {
template <typename T, typename Conv>
std::function<bool(const std::string&)> setter(T* target, Conv conv) {
  return [target, conv](const std::string& v) {
    try {
      std::size_t used = 0;
      const T value = conv(v, &used);
      if (used != v.size()) return false;
      *target = value;
      return true;
    } catch (...) {
      return false;
    }
  };
}
}  // namespace

Args::Args(std::string program, std::string summary) : program_(std::move(program)), summary_(std::move(summary)) {}

void Args::flag(const std::string& name, const std::string& help, bool* target) {
  specs_.push_back({name, "", help, [target](const std::string&) { *target = true; return true; }, true, false, false});
}

void Args::option(const std::string& name, const std::string& value_name, const std::string& help,
                  std::string* target) {
  specs_.push_back({name, value_name, help, [target](const std::string& v) { *target = v; return true; }, false,
                    false, false});
}

void Args::option(const std::string& name, const std::string& value_name, const std::string& help, double* target) {
  specs_.push_back({name, value_name, help,
                    setter(target, [](const std::string& v, std::size_t* used) { return std::stod(v, used); }), false,
                    false, false});
}

void Args::option(const std::string& name, const std::string& value_name, const std::string& help, int* target) {
  specs_.push_back({name, value_name, help,
                    setter(target, [](const std::string& v, std::size_t* used) { return std::stoi(v, used); }), false,
                    false, false});
}

void Args::option(const std::string& name, const std::string& value_name, const std::string& help,
                  std::uint64_t* target) {
  specs_.push_back({name, value_name, help, setter(target, [](const std::string& v, std::size_t* used) {
                      if (!v.empty() && v[0] == '-') throw std::invalid_argument("negative");
                      return static_cast<std::uint64_t>(std::stoull(v, used));
                    }),
                    false, false, false});
}

void Args::positional(const std::string& name, const std::string& help, std::string* target) {
  specs_.push_back({name, "", help, [target](const std::string& v) { *target = v; return true; }, false, true,
                    false});
}

Args::Spec* Args::find(const std::string& name) {
  for (auto& s : specs_) {
    if (!s.positional && s.name == name) return &s;
  }
  return nullptr;
}

bool Args::was_set(const std::string& name) const {
  for (const auto& s : specs_) {
    if (s.name == name) return s.seen;
  }
  return false;
}

bool Args::parse(int argc, char** argv, int first) {
  std::vector<std::string> args;
  for (int i = first; i < argc; ++i) args.emplace_back(argv[i]);
  return parse(args);
}

std::optional<int> Args::parse_or_exit(int argc, char** argv, int first) {
  if (!parse(argc, argv, first)) {
    std::cerr << program_ << ": " << error_ << "\n\n" << usage();
    return 2;
  }
  if (help_) {
    std::cout << usage();
    return 0;
  }
  return std::nullopt;
}

bool Args::parse(const std::vector<std::string>& args) {
  std::size_t next_positional = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      help_ = true;
      return true;
    }
    if (a.rfind("--", 0) == 0) {
      const auto eq = a.find('=');
      const std::string name = a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
      Spec* s = find(name);
      if (s == nullptr) {
        error_ = "unknown option --" + name;
        return false;
      }
      std::string value;
      if (!s->is_flag) {
        if (eq != std::string::npos) {
          value = a.substr(eq + 1);
        } else if (i + 1 < args.size()) {
          value = args[++i];
        } else {
          error_ = "--" + name + " needs a value (" + s->value_name + ")";
          return false;
        }
      } else if (eq != std::string::npos) {
        error_ = "--" + name + " takes no value";
        return false;
      }
      if (!s->set(value)) {
        error_ = "bad value \"" + value + "\" for --" + name + " (expected " + s->value_name + ")";
        return false;
      }
      s->seen = true;
      continue;
    }
    Spec* p = nullptr;
    std::size_t seen = 0;
    for (auto& s : specs_) {
      if (s.positional && seen++ == next_positional) p = &s;
    }
    if (p == nullptr) {
      error_ = "unexpected argument \"" + a + "\"";
      return false;
    }
    p->set(a);
    p->seen = true;
    ++next_positional;
  }
  for (const auto& s : specs_) {
    if (s.positional && !s.seen) {
      error_ = "missing " + s.name;
      return false;
    }
  }
  return true;
}

std::string Args::usage() const {
  std::ostringstream os;
  os << "usage: " << program_;
  for (const auto& s : specs_) {
    if (s.positional) os << ' ' << s.name;
  }
  os << " [options]\n\n" << summary_ << "\n\n";
  for (const auto& s : specs_) {
    std::string left = s.positional ? "  " + s.name : "  --" + s.name + (s.value_name.empty() ? "" : " " + s.value_name);
    os << left;
    os << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << s.help << '\n';
  }
  os << "  --help" << std::string(22, ' ') << "show this help\n";
  return os.str();
}

}  // namespace entourage::cli
