#include "behaviour/mobil.hpp"

namespace entourage {

bool mobil_safe(const MobilParams& p, double self_after_mps2, double new_follower_after_mps2) {
  return new_follower_after_mps2 >= -p.safe_decel_mps2 && self_after_mps2 >= -p.safe_decel_mps2;
}

MobilDecision mobil_decide(const MobilParams& p, const MobilSituation& s) {
  MobilDecision d;
  d.safe = mobil_safe(p, s.self_after_mps2, s.new_follower_after_mps2);
  const double own_gain = s.self_after_mps2 - s.self_now_mps2;
  const double others_gain = (s.new_follower_after_mps2 - s.new_follower_now_mps2) +
                             (s.old_follower_after_mps2 - s.old_follower_now_mps2);
  const double bias = s.to_right ? -p.right_bias_mps2 : p.right_bias_mps2;
  d.advantage_mps2 = own_gain + p.politeness * others_gain - p.change_threshold_mps2 - bias;
  d.change = d.safe && d.advantage_mps2 > 0.0;
  return d;
}

}  // namespace entourage
