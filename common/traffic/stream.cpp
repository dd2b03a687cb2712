#include "traffic/stream.hpp"

#include <algorithm>
#include <cmath>

namespace entourage {

namespace {
constexpr int kBinsPerClass = 400;
constexpr double kMinSpeed_mps = 0.5;  // desired speeds are never below this (avoids 1/v blow-up)

double normal_pdf(double x, double mean, double sd) {
  const double z = (x - mean) / sd;
  return std::exp(-0.5 * z * z);
}
}  // namespace

StreamModel::StreamModel(double flow_veh_per_s, const std::vector<SpeedClass>& classes) : flow_(flow_veh_per_s) {
  double total_share = 0.0;
  for (const auto& c : classes) total_share += c.share;
  for (const auto& c : classes) {
    if (c.share <= 0.0 || total_share <= 0.0) continue;
    const NormalDist& d = c.desired_speed_mps;
    const double lo = std::max(kMinSpeed_mps, d.min);
    const double hi = std::max(lo, d.max);
    const double share = c.share / total_share;
    if (d.sd <= 0.0 || hi - lo <= 0.0) {
      const double v = std::clamp(d.mean, lo, hi);
      bins_.push_back({c.type_index, v, v, v, share});
      continue;
    }
    const double width = (hi - lo) / kBinsPerClass;
    std::vector<double> w(kBinsPerClass);
    double sum = 0.0;
    for (int i = 0; i < kBinsPerClass; ++i) {
      w[static_cast<std::size_t>(i)] = normal_pdf(lo + (i + 0.5) * width, d.mean, d.sd);
      sum += w[static_cast<std::size_t>(i)];
    }
    for (int i = 0; i < kBinsPerClass; ++i) {
      const double a = lo + i * width;
      bins_.push_back({c.type_index, a, a + width, a + 0.5 * width, share * w[static_cast<std::size_t>(i)] / sum});
    }
  }
}

double StreamModel::expect(const std::function<double(double)>& h) const {
  double e = 0.0;
  for (const auto& b : bins_) e += b.probability * h(b.mid_mps);
  return e;
}

double StreamModel::density_per_m() const {
  return flow_ * expect([](double v) { return 1.0 / v; });
}

double StreamModel::rate_rear_per_s(double u) const {
  return flow_ * expect([u](double v) { return std::max(0.0, 1.0 - u / v); });
}

double StreamModel::rate_front_per_s(double u) const {
  return flow_ * expect([u](double v) { return std::max(0.0, u / v - 1.0); });
}

double StreamModel::rate_oncoming_per_s(double u) const {
  return flow_ * expect([u](double v) { return 1.0 + u / v; });
}

double StreamModel::mean_time_speed_mps() const {
  return expect([](double v) { return v; });
}

double StreamModel::mean_space_speed_mps() const {
  const double inv = expect([](double v) { return 1.0 / v; });
  return inv > 0.0 ? 1.0 / inv : 0.0;
}

SpeedDraw StreamModel::draw_weighted(Random& rng, const std::function<double(double)>& h) const {
  double total = 0.0;
  for (const auto& b : bins_) total += b.probability * h(b.mid_mps);
  if (bins_.empty()) return {};
  const Bin* chosen = &bins_.back();
  if (total > 0.0) {
    double target = rng.uniform() * total;
    for (const auto& b : bins_) {
      target -= b.probability * h(b.mid_mps);
      if (target < 0.0) {
        chosen = &b;
        break;
      }
    }
  }
  return SpeedDraw{chosen->type_index, rng.uniform(chosen->lo_mps, chosen->hi_mps)};
}

SpeedDraw StreamModel::draw_time_mean(Random& rng) const {
  return draw_weighted(rng, [](double) { return 1.0; });
}

SpeedDraw StreamModel::draw_space_mean(Random& rng) const {
  return draw_weighted(rng, [](double v) { return 1.0 / v; });
}

SpeedDraw StreamModel::draw_rear(Random& rng, double u) const {
  return draw_weighted(rng, [u](double v) { return std::max(0.0, 1.0 - u / v); });
}

SpeedDraw StreamModel::draw_front(Random& rng, double u) const {
  return draw_weighted(rng, [u](double v) { return std::max(0.0, u / v - 1.0); });
}

SpeedDraw StreamModel::draw_oncoming(Random& rng, double u) const {
  return draw_weighted(rng, [u](double v) { return 1.0 + u / v; });
}

StreamModel make_stream(const ScenarioConfig& sc, Direction dir) {
  const FlowConfig& flow = sc.flow(dir);
  std::vector<SpeedClass> classes;
  for (std::size_t i = 0; i < sc.vehicle_types.size() && i < flow.type_shares.size(); ++i) {
    classes.push_back({static_cast<std::uint8_t>(i), flow.type_shares[i], sc.vehicle_types[i].driver.desired_speed_mps});
  }
  return StreamModel(flow.flow_veh_per_s, classes);
}

}  // namespace entourage
