#include "recording/tables.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/ids.hpp"

namespace entourage::recording {

const char* const kVehiclesHeader =
    "step,time_s,id,owner,region,direction,lane,s_m,d_m,x_m,y_m,heading_rad,speed_mps,accel_mps2,length_m,width_m,"
    "type";
const char* const kEgoHeader = "step,time_s,s_m,d_m,x_m,y_m,heading_rad,speed_mps,accel_mps2,lane";

namespace {

constexpr const char* kHandoffsHeader = "step,time_s,vehicle_id,sequence,from,to_role,to_region,reason,lane,s_m,speed_mps";
constexpr const char* kPlaysHeader = "step,time_s,play_id,name,phase,ego_s_m,estimated_start_time_s,detail";

const char* role_name(std::uint8_t role) {
  switch (static_cast<Role>(role)) {
    case Role::kNone: return "none";
    case Role::kMicro: return "micro";
    case Role::kMeso: return "meso";
    case Role::kDirector: return "director";
    default: return "other";
  }
}

const char* reason_name(std::uint8_t reason) {
  switch (reason) {
    case 1: return "birth";
    case 2: return "initial_fill";
    case 3: return "border";
    case 4: return "left_window";
    case 5: return "director";
    default: return "unknown";
  }
}

struct FileCloser {
  void operator()(std::FILE* f) const {
    if (f != nullptr) std::fclose(f);
  }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File open_for_writing(const std::string& path, std::string* error) {
  File f(std::fopen(path.c_str(), "w"));
  if (!f) *error = "cannot write " + path;
  return f;
}

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

Tables tables_from(const Recording& r, const std::vector<std::string>& type_names) {
  Tables t;
  t.vehicles.reserve(r.vehicles.size());
  for (const auto& m : r.vehicles) {
    VehicleRow row;
    row.step = m.step();
    row.time_s = m.time_s();
    row.id = m.id();
    row.owner = to_string(ServiceId::from_code(m.owner()));
    row.region = to_string(static_cast<Region>(m.region()));
    row.direction = m.direction();
    row.lane = m.lane();
    row.target_lane = m.target_lane();
    row.s_m = m.s_m();
    row.d_m = m.d_m();
    row.x_m = m.x_m();
    row.y_m = m.y_m();
    row.heading_rad = m.heading_rad();
    row.speed_mps = m.speed_mps();
    row.accel_mps2 = m.accel_mps2();
    row.length_m = m.length_m();
    row.width_m = m.width_m();
    row.type = m.type_index() < type_names.size() ? type_names[m.type_index()] : "type" + std::to_string(m.type_index());
    t.vehicles.push_back(std::move(row));
  }
  std::stable_sort(t.vehicles.begin(), t.vehicles.end(),
                   [](const VehicleRow& a, const VehicleRow& b) { return a.step != b.step ? a.step < b.step : a.id < b.id; });
  for (const auto& m : r.egos) {
    t.ego.push_back({m.step(), m.time_s(), m.s_m(), m.d_m(), m.x_m(), m.y_m(), m.heading_rad(), m.speed_mps(),
                     m.accel_mps2(), m.lane(), m.length_m(), m.width_m()});
  }
  std::stable_sort(t.ego.begin(), t.ego.end(), [](const EgoRow& a, const EgoRow& b) { return a.step < b.step; });
  return t;
}

bool write_csv(const Recording& r, const Tables& t, const std::string& dir, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    *error = "cannot create " + dir + ": " + ec.message();
    return false;
  }
  File v = open_for_writing(dir + "/vehicles.csv", error);
  File e = open_for_writing(dir + "/ego.csv", error);
  File h = open_for_writing(dir + "/handoffs.csv", error);
  File p = open_for_writing(dir + "/plays.csv", error);
  if (!v || !e || !h || !p) return false;
  std::fprintf(v.get(), "%s\n", kVehiclesHeader);
  for (const auto& x : t.vehicles) {
    std::fprintf(v.get(), "%" PRIu64 ",%.3f,%u,%s,%s,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.3f,%.3f,%s\n", x.step,
                 x.time_s, x.id, x.owner.c_str(), x.region.c_str(), x.direction, x.lane, x.s_m, x.d_m, x.x_m, x.y_m,
                 x.heading_rad, x.speed_mps, x.accel_mps2, x.length_m, x.width_m, csv_quote(x.type).c_str());
  }
  std::fprintf(e.get(), "%s\n", kEgoHeader);
  for (const auto& x : t.ego) {
    std::fprintf(e.get(), "%" PRIu64 ",%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%d\n", x.step, x.time_s, x.s_m, x.d_m,
                 x.x_m, x.y_m, x.heading_rad, x.speed_mps, x.accel_mps2, x.lane);
  }
  std::fprintf(h.get(), "%s\n", kHandoffsHeader);
  for (const auto& x : r.handoffs) {
    std::fprintf(h.get(), "%" PRIu64 ",%.3f,%u,%u,%s,%s,%s,%s,%d,%.6f,%.6f\n", static_cast<std::uint64_t>(x.step()),
                 x.time_s(), x.vehicle_id(), x.handoff_sequence(),
                 to_string(ServiceId::from_code(x.from_service())).c_str(), role_name(x.to_role()),
                 to_string(static_cast<Region>(x.to_region())), reason_name(x.reason()), x.lane(), x.s_m(),
                 x.speed_mps());
  }
  std::fprintf(p.get(), "%s\n", kPlaysHeader);
  for (const auto& x : r.plays) {
    std::fprintf(p.get(), "%" PRIu64 ",%.3f,%u,%s,%u,%.6f,%.6f,%s\n", static_cast<std::uint64_t>(x.step()), x.time_s(),
                 x.play_id(), csv_quote(x.name().to_string()).c_str(), x.phase(), x.ego_s_m(), x.estimated_start_time_s(),
                 csv_quote(x.detail().to_string()).c_str());
  }
  return true;
}

std::optional<Tables> read_csv(const std::string& dir, std::string* error) {
  Tables t;
  std::ifstream v(dir + "/vehicles.csv");
  std::ifstream e(dir + "/ego.csv");
  if (!v || !e) {
    *error = "cannot read " + dir + "/vehicles.csv and " + dir + "/ego.csv";
    return std::nullopt;
  }
  std::string line;
  std::getline(v, line);
  if (line != kVehiclesHeader) {
    *error = dir + "/vehicles.csv: unexpected header";
    return std::nullopt;
  }
  std::size_t n = 1;
  while (std::getline(v, line)) {
    ++n;
    const auto f = split(line);
    if (f.size() != 17) {
      *error = dir + "/vehicles.csv:" + std::to_string(n) + ": expected 17 fields";
      return std::nullopt;
    }
    VehicleRow r;
    r.step = std::stoull(f[0]);
    r.time_s = std::stod(f[1]);
    r.id = static_cast<std::uint32_t>(std::stoul(f[2]));
    r.owner = f[3];
    r.region = f[4];
    r.direction = std::stoi(f[5]);
    r.lane = std::stoi(f[6]);
    r.target_lane = r.lane;
    r.s_m = std::stod(f[7]);
    r.d_m = std::stod(f[8]);
    r.x_m = std::stod(f[9]);
    r.y_m = std::stod(f[10]);
    r.heading_rad = std::stod(f[11]);
    r.speed_mps = std::stod(f[12]);
    r.accel_mps2 = std::stod(f[13]);
    r.length_m = std::stod(f[14]);
    r.width_m = std::stod(f[15]);
    r.type = f[16];
    t.vehicles.push_back(std::move(r));
  }
  std::getline(e, line);
  if (line != kEgoHeader) {
    *error = dir + "/ego.csv: unexpected header";
    return std::nullopt;
  }
  n = 1;
  while (std::getline(e, line)) {
    ++n;
    const auto f = split(line);
    if (f.size() != 10) {
      *error = dir + "/ego.csv:" + std::to_string(n) + ": expected 10 fields";
      return std::nullopt;
    }
    EgoRow r;
    r.step = std::stoull(f[0]);
    r.time_s = std::stod(f[1]);
    r.s_m = std::stod(f[2]);
    r.d_m = std::stod(f[3]);
    r.x_m = std::stod(f[4]);
    r.y_m = std::stod(f[5]);
    r.heading_rad = std::stod(f[6]);
    r.speed_mps = std::stod(f[7]);
    r.accel_mps2 = std::stod(f[8]);
    r.lane = std::stoi(f[9]);
    t.ego.push_back(r);
  }
  return t;
}

}  // namespace entourage::recording
