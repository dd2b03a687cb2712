#pragma once
// Unit conversions. Everything inside Entourage is SI; scenarios may state speeds in km/h and
// flows in vehicles per hour, converted once when the scenario is loaded.

namespace entourage {

inline constexpr double kKphPerMps = 3.6;
inline constexpr double kSecondsPerHour = 3600.0;

constexpr double kph_to_mps(double kph) { return kph / kKphPerMps; }
constexpr double mps_to_kph(double mps) { return mps * kKphPerMps; }
constexpr double per_hour_to_per_second(double per_hour) { return per_hour / kSecondsPerHour; }
constexpr double per_second_to_per_hour(double per_s) { return per_s * kSecondsPerHour; }

}  // namespace entourage
