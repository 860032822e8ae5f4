#include "hotlap/brake/brake_hydraulics.h"

#include <algorithm>

namespace hotlap::brake {

template <Scalar T>
T CalcPressureRate(const BrakeHydraulicsParams<T>& p, const T& pressure, const T& target) {
  // The system cannot deliver less than nothing or more than its maximum.
  T goal = target;
  if (ValueOf(goal) < 0.0) goal = T(0.0);
  if (ValueOf(goal) > ValueOf(p.max_pressure)) goal = p.max_pressure;
  const T rate = (goal - pressure) / p.time_constant;
  if (ValueOf(rate) > ValueOf(p.max_rise_rate)) return p.max_rise_rate;
  if (ValueOf(rate) < -ValueOf(p.max_fall_rate)) return -p.max_fall_rate;
  return rate;
}

template <Scalar T>
T CalcBrakeTorqueCapacity(const BrakeHydraulicsParams<T>& p, const T& pressure) {
  return ValueOf(pressure) > 0.0 ? p.torque_gain * pressure : T(0.0);
}

PressureDelayLine::PressureDelayLine(int delay_ticks, double initial)
    : buffer_(static_cast<size_t>(std::max(delay_ticks, 0)), initial) {}

double PressureDelayLine::Push(double command) {
  if (buffer_.empty()) return command;
  const double out = buffer_[next_];
  buffer_[next_] = command;
  next_ = (next_ + 1) % buffer_.size();
  return out;
}

#define HOTLAP_INSTANTIATE_BRAKE_HYDRAULICS(T)                                         \
  template T CalcPressureRate<T>(const BrakeHydraulicsParams<T>&, const T&, const T&); \
  template T CalcBrakeTorqueCapacity<T>(const BrakeHydraulicsParams<T>&, const T&);
HOTLAP_FOR_EACH_SCALAR(HOTLAP_INSTANTIATE_BRAKE_HYDRAULICS)

}  // namespace hotlap::brake
