#pragma once
// The highest of a value over a sliding window of time: the ego's usual speed, against which the
// director tells a driver who has slowed down for a while (play_transport.cpp, an actor judged hopeless).
// A monotonic queue: each sample is added once and dropped once, so a step costs O(1) amortised.

#include <deque>
#include <utility>

namespace entourage::director {

class RecentTop {
 public:
  explicit RecentTop(double window_s) : window_s_(window_s) {}

  // The value at `time_s` (times never decrease).
  void observe(double time_s, double value) {
    while (!samples_.empty() && samples_.back().second <= value) samples_.pop_back();
    samples_.emplace_back(time_s, value);
    while (samples_.front().first < time_s - window_s_) samples_.pop_front();
  }

  // The highest value observed over the window that ends at the latest time; 0 before any.
  double top() const { return samples_.empty() ? 0.0 : samples_.front().second; }

 private:
  double window_s_;
  std::deque<std::pair<double, double>> samples_;  // (time, value), values decreasing
};

}  // namespace entourage::director
