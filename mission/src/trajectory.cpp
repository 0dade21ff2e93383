#include "ceilplan/mission/trajectory.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ceilplan::mission {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr double kSamePoint_m = 1e-6;       // consecutive waypoints closer than this are one station
constexpr double kHeadingChange_deg = 0.1;  // smaller heading changes are not turns
constexpr int kBisections = 60;

void requirePositive(double value, const std::string& what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InputError(what + " must be positive and finite, got " + formatNumber(value));
}

// Signed smallest rotation from `from_deg` to `to_deg`, in (-180, 180].
double headingDifference_deg(double from_deg, double to_deg) {
  double d = std::remainder(to_deg - from_deg, 360.0);
  return d <= -180.0 ? d + 360.0 : d;
}

// Smoothstep in [0, 1] and its derivative, for u in [0, 1]: peak slope 1.5.
double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }
double smoothstepSlope(double u) { return 6.0 * u * (1.0 - u); }

// --- One-dimensional motion made of pieces of constant jerk -----------------------------------

// Duration of a jerk-limited speed change of `delta` (>= 0) under acceleration `a` and jerk `j`:
// jerk up, constant acceleration (if the change is large enough), jerk down.
struct SpeedChange {
  double ramp_s = 0.0;  // each jerk phase
  double hold_s = 0.0;  // constant acceleration phase
  double peak_m_s2 = 0.0;
  double duration_s() const { return 2.0 * ramp_s + hold_s; }
};

SpeedChange speedChange(double delta, double a, double j) {
  SpeedChange c;
  if (!(delta > 0.0)) return c;
  if (delta * j >= a * a) {
    c.ramp_s = a / j;
    c.hold_s = delta / a - a / j;
    c.peak_m_s2 = a;
  } else {
    c.ramp_s = std::sqrt(delta / j);
    c.peak_m_s2 = j * c.ramp_s;
  }
  return c;
}

// Distance of a speed change from v0 to v1: by symmetry, the mean speed times the duration.
double changeDistance(double v0, double v1, double a, double j) {
  return 0.5 * (v0 + v1) * speedChange(std::abs(v1 - v0), a, j).duration_s();
}

// Distance covered in the first half (in time) of a speed-up from rest to v.
double firstHalfDistance(double v, double a, double j) {
  const SpeedChange c = speedChange(v, a, j);
  const double jerk = c.peak_m_s2 / std::max(c.ramp_s, 1e-300);
  const double ramp_distance = jerk * c.ramp_s * c.ramp_s * c.ramp_s / 6.0;
  const double ramp_speed = 0.5 * c.peak_m_s2 * c.ramp_s;
  const double half_hold = 0.5 * c.hold_s;
  return ramp_distance + ramp_speed * half_hold + 0.5 * c.peak_m_s2 * half_hold * half_hold;
}

struct State1D {
  double s = 0.0, v = 0.0, a = 0.0;
};

class Motion1D {
 public:
  void add(double duration_s, double jerk) {
    if (duration_s > 0.0) pieces_.push_back({duration_s, jerk});
  }
  // Jerk-limited change from v0 to v1.
  void changeSpeed(double v0, double v1, double a, double j) {
    const SpeedChange c = speedChange(std::abs(v1 - v0), a, j);
    if (c.duration_s() <= 0.0) return;
    const double sign = v1 > v0 ? 1.0 : -1.0;
    const double jerk = c.peak_m_s2 / c.ramp_s;
    add(c.ramp_s, sign * jerk);
    add(c.hold_s, 0.0);
    add(c.ramp_s, -sign * jerk);
  }
  // Stretches time by k: speeds / k, accelerations / k^2, jerks / k^3.
  void stretch(double k) {
    for (Piece& p : pieces_) {
      p.duration_s *= k;
      p.jerk /= k * k * k;
    }
  }
  // Integrates the pieces; `length_m` is where the motion ends (at rest).
  void finish(double length_m) {
    length_m_ = length_m;
    starts_.clear();
    states_.clear();
    double t = 0.0;
    State1D x;
    for (const Piece& p : pieces_) {
      starts_.push_back(t);
      states_.push_back(x);
      x = advance(x, p.jerk, p.duration_s);
      t += p.duration_s;
    }
    duration_s_ = t;
  }
  double duration_s() const { return duration_s_; }

  // State at time t from the motion's start: at rest at 0 before it, at rest at the end after.
  State1D at(double t) const {
    if (t <= 0.0 || pieces_.empty()) return {};
    if (t >= duration_s_) return {length_m_, 0.0, 0.0};
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(starts_.begin(), starts_.end(), t) - starts_.begin()) - 1;
    return advance(states_[k], pieces_[k].jerk, t - starts_[k]);
  }

 private:
  struct Piece {
    double duration_s;
    double jerk;
  };
  static State1D advance(const State1D& x, double jerk, double dt) {
    return {x.s + dt * (x.v + dt * (0.5 * x.a + dt * jerk / 6.0)), x.v + dt * (x.a + 0.5 * dt * jerk), x.a + dt * jerk};
  }

  std::vector<Piece> pieces_;
  std::vector<double> starts_;
  std::vector<State1D> states_;
  double duration_s_ = 0.0;
  double length_m_ = 0.0;
};

// --- The route as stations (distinct consecutive positions) and segments between them -----------

struct Station {
  Eigen::Vector3d position_m;
  double hold_s = 0.0;
  double leave_speed_m_s = 0.0;   // route speed towards the next station
  std::optional<double> yaw_deg;  // last heading given here
  std::optional<double> gimbal_pitch_deg;
  bool take_photo = false;
  std::optional<double> trigger_distance_m;
  // Corner handling (interior stations).
  double turn_rad = 0.0;
  bool rest = true;
  double speed_m_s = 0.0;   // speed through the corner; 0 at a rest
  double pair_accel = 0.0;  // limits of each segment's own motion during the blend
  double pair_jerk = 0.0;
  double pause_s = 0.0;  // turn in place on arrival, before the hold
  // Timeline.
  double arrive_s = 0.0;  // comes to rest here, or passes mid-blend
  double depart_s = 0.0;  // leaves after pause and hold (= arrive_s when blended)
};

struct Segment {
  Eigen::Vector3d from_m;
  Eigen::Vector3d direction;
  double length_m = 0.0;
  double speed_limit_m_s = 0.0;
  Motion1D motion;
  double start_s = 0.0;
  double pair_in_s = 0.0;  // duration of the blend at the start (scaled)
};

class Scaler {
 public:
  Scaler(const SortieRoute& route, const TrajectoryLimits& limits, const TrajectoryOptions& options)
      : limits_(limits), options_(options), dt_(1.0 / options.rate_hz) {
    buildStations(route);
    buildSegments();
    markCorners();
  }

  Trajectory run(int sortie) {
    // Blends whose positions fail the re-check become stops; stops only ever grow.
    while (true) {
      chooseCornerSpeeds();
      buildTimeline();
      if (!rejectUnsafeBlends()) break;
    }
    addTurnPauses();
    buildTimeline();
    return sample(sortie);
  }

 private:
  void buildStations(const SortieRoute& route) {
    Station home;
    home.position_m = route.home_m;
    home.leave_speed_m_s = route.cruise_speed_m_s;
    stations_.push_back(home);
    for (const RouteWaypoint& w : route.waypoints) {
      if ((w.position_m - stations_.back().position_m).norm() > kSamePoint_m) {
        Station next;
        next.position_m = w.position_m;
        stations_.push_back(next);
      }
      Station& s = stations_.back();
      s.hold_s += w.hold_s;
      s.leave_speed_m_s = w.speed_m_s.value_or(route.cruise_speed_m_s);
      if (w.yaw_deg) s.yaw_deg = *w.yaw_deg;
      if (w.gimbal_pitch_deg) s.gimbal_pitch_deg = *w.gimbal_pitch_deg;
      s.take_photo = s.take_photo || w.take_photo;
      if (w.trigger_distance_m) s.trigger_distance_m = *w.trigger_distance_m;
    }
    initial_heading_deg_ = initialHeading_deg(route);
  }

  void buildSegments() {
    for (std::size_t k = 0; k + 1 < stations_.size(); ++k) {
      Segment s;
      s.from_m = stations_[k].position_m;
      const Eigen::Vector3d d = stations_[k + 1].position_m - s.from_m;
      s.length_m = d.norm();
      s.direction = d / s.length_m;
      double speed = stations_[k].leave_speed_m_s;
      if (s.direction.z() > 0.0) speed = std::min(speed, limits_.climb_m_s / s.direction.z());
      if (s.direction.z() < 0.0) speed = std::min(speed, limits_.descent_m_s / -s.direction.z());
      s.speed_limit_m_s = speed;
      segments_.push_back(std::move(s));
    }
  }

  // Which stations are rests, and each corner's turn and blend limits.
  void markCorners() {
    const bool blending = options_.path_is_safe && options_.corner_tolerance_m > 0.0;
    double heading = initial_heading_deg_;
    for (std::size_t k = 0; k < stations_.size(); ++k) {
      Station& s = stations_[k];
      bool turns_yaw = false;
      if (s.yaw_deg) {
        turns_yaw = std::abs(headingDifference_deg(heading, *s.yaw_deg)) > kHeadingChange_deg;
        heading = *s.yaw_deg;
      }
      const bool interior = k > 0 && k + 1 < stations_.size();
      if (interior) {
        const double c = std::clamp(segments_[k - 1].direction.dot(segments_[k].direction), -1.0, 1.0);
        s.turn_rad = std::acos(c);
        const double share = std::max(2.0 * std::sin(0.5 * s.turn_rad), 1e-3);
        s.pair_accel = limits_.max_acceleration_m_s2 / share;
        s.pair_jerk = limits_.max_jerk_m_s3 / share;
      }
      s.rest = !interior || !blending || s.hold_s > 0.0 || turns_yaw || s.turn_rad > options_.stop_turn_deg * kDegree;
    }
  }

  // How far a blend at speed v through station s strays from the polyline (docs/flying.md).
  double deviation_m(const Station& s, double v) const {
    return std::sin(s.turn_rad) * firstHalfDistance(v, s.pair_accel, s.pair_jerk);
  }

  double pairDistance(const Station& s) const {
    if (s.rest || s.speed_m_s <= 0.0) return 0.0;
    return 0.5 * s.speed_m_s * speedChange(s.speed_m_s, s.pair_accel, s.pair_jerk).duration_s();
  }

  // Shortest distance segment k needs between its corners' speeds vin and vout, through `peak`.
  double neededDistance(std::size_t k, double vin, double vout, double peak) const {
    Station in = stations_[k], out = stations_[k + 1];
    in.speed_m_s = vin;
    out.speed_m_s = vout;
    const double a = limits_.max_acceleration_m_s2, j = limits_.max_jerk_m_s3;
    return pairDistance(in) + pairDistance(out) + changeDistance(vin, peak, a, j) + changeDistance(peak, vout, a, j);
  }

  bool fits(std::size_t k, double vin, double vout) const {
    return neededDistance(k, vin, vout, std::max(vin, vout)) <= segments_[k].length_m * (1.0 + 1e-12);
  }

  // Largest value in [low, high] for which `ok` holds, given ok(low).
  template <typename Ok>
  static double largest(double low, double high, Ok&& ok) {
    if (ok(high)) return high;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (low + high);
      (ok(mid) ? low : high) = mid;
    }
    return low;
  }

  void chooseCornerSpeeds() {
    for (std::size_t k = 1; k + 1 < stations_.size(); ++k) {
      Station& s = stations_[k];
      s.speed_m_s = 0.0;
      if (s.rest) continue;
      const double limit = std::min(segments_[k - 1].speed_limit_m_s, segments_[k].speed_limit_m_s);
      s.speed_m_s = largest(0.0, limit, [&](double v) { return deviation_m(s, v) <= options_.corner_tolerance_m; });
    }
    // Each segment must hold its corners' blends and the speed change between them: lower the
    // faster end until it does. Lowering one end can tighten the neighbour, so repeat; a segment
    // still too short after many rounds makes its corners stops (always feasible).
    for (int round = 0;; ++round) {
      bool changed = false;
      for (std::size_t k = 0; k < segments_.size(); ++k) {
        double& vin = stations_[k].speed_m_s;
        double& vout = stations_[k + 1].speed_m_s;
        if (fits(k, vin, vout)) continue;
        changed = true;
        if (round >= 100) {
          for (Station* s : {&stations_[k], &stations_[k + 1]}) {
            s->rest = true;
            s->speed_m_s = 0.0;
          }
          continue;
        }
        if (vin > vout) {
          vin = fits(k, vout, vout) ? largest(vout, vin, [&](double v) { return fits(k, v, vout); }) : vout;
        } else {
          vout = fits(k, vin, vin) ? largest(vin, vout, [&](double v) { return fits(k, vin, v); }) : vin;
        }
        if (!fits(k, vin, vout)) {
          const double common = largest(0.0, vin, [&](double v) { return fits(k, v, v); });
          vin = vout = common;
        }
      }
      if (!changed) break;
    }
    for (Station& s : stations_)
      if (!s.rest && s.speed_m_s <= 0.0) s.rest = true;
  }

  // Each segment's motion, each run between rests stretched to whole samples, and the times of
  // every station.
  void buildTimeline() {
    const double a = limits_.max_acceleration_m_s2, j = limits_.max_jerk_m_s3;
    long cursor = samplesFor(stations_[0].pause_s) + samplesFor(stations_[0].hold_s);
    stations_[0].arrive_s = 0.0;
    stations_[0].depart_s = cursor * dt_;
    std::size_t k = 0;
    while (k < segments_.size()) {
      // The run from rest station k to the next rest.
      std::size_t end = k + 1;
      while (!stations_[end].rest) ++end;
      std::vector<double> offsets;
      double t = 0.0;
      for (std::size_t i = k; i < end; ++i) {
        Segment& seg = segments_[i];
        const Station &in = stations_[i], &out = stations_[i + 1];
        const double vin = in.speed_m_s, vout = out.speed_m_s;
        const double peak = largest(std::max(vin, vout), seg.speed_limit_m_s,
                                    [&](double v) { return neededDistance(i, vin, vout, v) <= seg.length_m; });
        seg.motion = Motion1D();
        seg.motion.changeSpeed(0.0, vin, in.pair_accel, in.pair_jerk);
        seg.motion.changeSpeed(vin, peak, a, j);
        seg.motion.add((seg.length_m - neededDistance(i, vin, vout, peak)) / peak, 0.0);
        seg.motion.changeSpeed(peak, vout, a, j);
        seg.motion.changeSpeed(vout, 0.0, out.pair_accel, out.pair_jerk);
        seg.motion.finish(seg.length_m);
        const double pair_in = vin > 0.0 ? speedChange(vin, in.pair_accel, in.pair_jerk).duration_s() : 0.0;
        t -= pair_in;  // overlaps the previous segment's slow-down
        offsets.push_back(t);
        seg.pair_in_s = pair_in;
        t += seg.motion.duration_s();
      }
      const double run_s = t;
      const long samples = std::max(1L, static_cast<long>(std::ceil(run_s / dt_ - 1e-9)));
      const double stretch = samples * dt_ / run_s;
      const double run_start = cursor * dt_;
      for (std::size_t i = k; i < end; ++i) {
        Segment& seg = segments_[i];
        seg.motion.stretch(stretch);
        seg.motion.finish(seg.length_m);
        seg.start_s = run_start + offsets[i - k] * stretch;
        seg.pair_in_s *= stretch;
        if (i > k) stations_[i].arrive_s = stations_[i].depart_s = seg.start_s + 0.5 * seg.pair_in_s;
      }
      cursor += samples;
      Station& rest = stations_[end];
      rest.arrive_s = cursor * dt_;
      cursor += samplesFor(rest.pause_s) + samplesFor(rest.hold_s);
      rest.depart_s = cursor * dt_;
      k = end;
    }
    end_sample_ = cursor;
  }

  long samplesFor(double duration_s) const {
    return duration_s > 0.0 ? static_cast<long>(std::ceil(duration_s / dt_ - 1e-9)) : 0L;
  }

  struct Kinematics {
    Eigen::Vector3d position, velocity, acceleration;
  };

  // Position, velocity and acceleration at time t: at most two segments move at once.
  Kinematics at(double t) const {
    std::size_t k =
        static_cast<std::size_t>(std::upper_bound(segments_.begin(), segments_.end(), t,
                                                  [](double time, const Segment& s) { return time < s.start_s; }) -
                                 segments_.begin());
    if (k == 0) return {stations_[0].position_m, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    --k;  // the last segment started
    Kinematics x{stations_[k].position_m, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    const auto add = [&](std::size_t i) {
      const State1D s = segments_[i].motion.at(t - segments_[i].start_s);
      x.position += segments_[i].direction * s.s;
      x.velocity += segments_[i].direction * s.v;
      x.acceleration += segments_[i].direction * s.a;
    };
    if (k > 0 && t < segments_[k - 1].start_s + segments_[k - 1].motion.duration_s()) {
      x.position = stations_[k - 1].position_m;
      add(k - 1);
    }
    add(k);
    return x;
  }

  // Checks every blend's positions (finely, and as the samples will fly them); returns whether
  // one was turned into a stop.
  bool rejectUnsafeBlends() {
    bool rejected = false;
    for (std::size_t k = 1; k + 1 < stations_.size(); ++k) {
      Station& s = stations_[k];
      if (s.rest) continue;
      const double begin = segments_[k].start_s, end = begin + segments_[k].pair_in_s;
      std::vector<double> times;
      for (double t = std::floor(begin / dt_) * dt_; t <= end + dt_; t += dt_) times.push_back(t);
      const int fine = 32;
      for (int i = 0; i <= fine; ++i) times.push_back(begin + (end - begin) * i / fine);
      std::sort(times.begin(), times.end());
      std::vector<Eigen::Vector3d> positions;
      for (double t : times) positions.push_back(at(t).position);
      if (!options_.path_is_safe(positions)) {
        s.rest = true;
        rejected = true;
      }
    }
    return rejected;
  }

  // Where the yaw rate limit cannot turn to a station's heading on the way there, the vehicle
  // turns in place on arrival. The turn towards a heading spans the last run before it.
  void addTurnPauses() {
    double heading = initial_heading_deg_;
    double last_rest_departure = 0.0;
    for (Station& s : stations_) {
      if (s.yaw_deg) {
        const double change = std::abs(headingDifference_deg(heading, *s.yaw_deg));
        const double needed = 1.5 * change / limits_.max_yaw_rate_deg_s;
        s.pause_s = std::max(0.0, needed - (s.arrive_s - last_rest_departure));
        heading = *s.yaw_deg;
      }
      if (s.rest) last_rest_departure = s.depart_s;
    }
  }

  // A channel (yaw or gimbal pitch) moving smoothly between keyframes.
  struct Ramp {
    double begin_s, end_s, from, to;
  };

  std::vector<Ramp> yawRamps() const {
    std::vector<Ramp> ramps;
    double heading = initial_heading_deg_;
    double last_rest_departure = 0.0;
    for (const Station& s : stations_) {
      if (s.yaw_deg) {
        const double change = headingDifference_deg(heading, *s.yaw_deg);
        if (change != 0.0) ramps.push_back({last_rest_departure, s.arrive_s + s.pause_s, heading, heading + change});
        heading = *s.yaw_deg;
      }
      if (s.rest) last_rest_departure = s.depart_s;
    }
    return ramps;
  }

  std::vector<Ramp> pitchRamps() const {
    std::vector<Ramp> ramps;
    double pitch = 0.0;
    for (std::size_t k = 0; k < stations_.size(); ++k) {
      const Station& s = stations_[k];
      if (s.gimbal_pitch_deg && *s.gimbal_pitch_deg != pitch) {
        const double begin = k > 0 ? stations_[k - 1].depart_s : 0.0;
        ramps.push_back({begin, s.arrive_s + s.pause_s, pitch, *s.gimbal_pitch_deg});
      }
      if (s.gimbal_pitch_deg) pitch = *s.gimbal_pitch_deg;
    }
    return ramps;
  }

  // Value and rate of a channel at time t; `ramps` in time order, cursor advanced monotonically.
  static std::pair<double, double> channelAt(const std::vector<Ramp>& ramps, std::size_t& cursor, double initial,
                                             double t) {
    while (cursor < ramps.size() && t >= ramps[cursor].end_s) ++cursor;
    const double before = cursor > 0 ? ramps[cursor - 1].to : initial;
    if (cursor == ramps.size() || t <= ramps[cursor].begin_s) return {before, 0.0};
    const Ramp& r = ramps[cursor];
    const double span = r.end_s - r.begin_s;
    const double u = (t - r.begin_s) / span;
    return {r.from + (r.to - r.from) * smoothstep(u), (r.to - r.from) * smoothstepSlope(u) / span};
  }

  Trajectory sample(int sortie) {
    Trajectory out;
    out.sortie = sortie;
    out.rate_hz = options_.rate_hz;
    out.limits = limits_;
    for (const Segment& s : segments_) out.length_m += s.length_m;
    for (std::size_t k = 1; k < stations_.size(); ++k) {
      const Station& s = stations_[k];
      if (s.rest) {
        ++out.stops;
      } else {
        ++out.blended_corners;
        out.max_corner_deviation_m = std::max(out.max_corner_deviation_m, deviation_m(s, s.speed_m_s));
      }
    }
    const std::vector<Ramp> yaw = yawRamps(), pitch = pitchRamps();
    std::size_t yaw_cursor = 0, pitch_cursor = 0;
    out.setpoints.reserve(static_cast<std::size_t>(end_sample_) + 1);
    for (long n = 0; n <= end_sample_; ++n) {
      TrajectorySetpoint p;
      p.t_s = n * dt_;
      const Kinematics x = at(p.t_s);
      p.position_m = x.position;
      p.velocity_m_s = x.velocity;
      p.acceleration_m_s2 = x.acceleration;
      const auto [heading_deg, heading_rate] = channelAt(yaw, yaw_cursor, initial_heading_deg_, p.t_s);
      p.yaw_rad = enuYawFromHeading_rad(heading_deg);
      p.yaw_rate_rad_s = -heading_rate * kDegree;
      p.gimbal_pitch_deg = channelAt(pitch, pitch_cursor, 0.0, p.t_s).first;
      out.setpoints.push_back(p);
    }
    markTriggers(out);
    return out;
  }

  long nearestSample(double t) const { return std::clamp(static_cast<long>(std::lround(t / dt_)), 0L, end_sample_); }

  void markTriggers(Trajectory& out) const {
    for (const Station& s : stations_)
      if (s.take_photo) out.setpoints[static_cast<std::size_t>(nearestSample(s.depart_s))].trigger = true;
    // Distance triggers: a photo where one starts, then every `spacing` metres flown.
    std::vector<std::pair<long, double>> switches;  // sample, spacing (0 stops)
    for (const Station& s : stations_)
      if (s.trigger_distance_m) switches.push_back({nearestSample(s.depart_s), *s.trigger_distance_m});
    std::size_t next = 0;
    double spacing = 0.0, flown = 0.0;
    for (std::size_t n = 0; n < out.setpoints.size(); ++n) {
      if (n > 0) flown += (out.setpoints[n].position_m - out.setpoints[n - 1].position_m).norm();
      while (next < switches.size() && switches[next].first == static_cast<long>(n)) {
        spacing = switches[next++].second;
        flown = 0.0;
        if (spacing > 0.0) out.setpoints[n].trigger = true;
      }
      if (spacing > 0.0 && flown >= spacing) {
        out.setpoints[n].trigger = true;
        flown -= spacing;
      }
    }
    for (const TrajectorySetpoint& p : out.setpoints) out.photos += p.trigger ? 1 : 0;
  }

  TrajectoryLimits limits_;
  const TrajectoryOptions& options_;
  double dt_;
  double initial_heading_deg_ = 0.0;
  std::vector<Station> stations_;
  std::vector<Segment> segments_;
  long end_sample_ = 0;
};

}  // namespace

void TrajectoryLimits::validate() const {
  requirePositive(climb_m_s, "trajectory limits: climb_m_s");
  requirePositive(descent_m_s, "trajectory limits: descent_m_s");
  requirePositive(max_acceleration_m_s2, "trajectory limits: max_acceleration_m_s2");
  requirePositive(max_jerk_m_s3, "trajectory limits: max_jerk_m_s3");
  requirePositive(max_yaw_rate_deg_s, "trajectory limits: max_yaw_rate_deg_s");
}

void TrajectoryOptions::validate() const {
  requirePositive(rate_hz, "trajectory: rate_hz");
  if (!(corner_tolerance_m >= 0.0) || !std::isfinite(corner_tolerance_m))
    throw InputError("trajectory: corner_tolerance_m must be finite and non-negative, got " +
                     formatNumber(corner_tolerance_m));
  if (!(stop_turn_deg >= 0.0 && stop_turn_deg <= 90.0))
    throw InputError("trajectory: stop_turn_deg must lie in [0, 90], got " + formatNumber(stop_turn_deg));
}

Trajectory timeScale(const SortieRoute& route, const TrajectoryLimits& limits, const TrajectoryOptions& options) {
  route.validate();
  limits.validate();
  options.validate();
  return Scaler(route, limits, options).run(route.sortie);
}

}  // namespace ceilplan::mission
