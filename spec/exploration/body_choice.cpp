// A scenario's body in JSON, and the checks of the intocps body's parameters.
#include <charconv>
#include <cmath>
#include <string>

#include "spec/exploration/scenario.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::json_io {

using exploration::BodyChoice;
using exploration::BodyKind;
using exploration::IntocpsBodyParameter;

Json JsonCodec<BodyChoice>::write(const BodyChoice& b) {
  const std::string kind = enum_to_string(b.kind);
  const exploration::IntocpsBodyParams defaults = exploration::scenario_intocps_params();
  if (b.kind != BodyKind::intocps || b.intocps == defaults) return kind;
  Json parameters = Json::object();
  for (const IntocpsBodyParameter& d : exploration::intocps_body_parameters()) {
    const double v = exploration::intocps_parameter_value(b.intocps, d);
    if (v != exploration::intocps_parameter_value(defaults, d)) parameters[std::string(d.name)] = v;
  }
  Json o = Json::object();
  o["kind"] = kind;
  o["parameters"] = parameters;
  return o;
}

void JsonCodec<BodyChoice>::read(const Json& j, const std::string& path, BodyChoice& out) {
  BodyChoice b;
  if (j.is_string()) {
    b.kind = enum_from_string<BodyKind>(j.get<std::string>(), path);
    out = b;
    return;
  }
  if (!j.is_object())
    throw InputError(path, "expected " + enum_choices<BodyKind>() + " or {\"kind\": ..., \"parameters\": {...}}, got " +
                               type_name(j));
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "kind" && it.key() != "parameters")
      throw InputError(join_key(path, it.key()), "unknown key (expected one of: kind, parameters)");
  if (!j.contains("kind")) throw InputError(join_key(path, "kind"), "missing (" + enum_choices<BodyKind>() + ")");
  from_json(j.at("kind"), join_key(path, "kind"), b.kind);
  if (j.contains("parameters")) {
    const std::string at = join_key(path, "parameters");
    const Json& ps = j.at("parameters");
    if (!ps.is_object()) throw InputError(at, "expected an object of the Body_Block's parameters, got " + type_name(ps));
    if (b.kind != BodyKind::intocps && !ps.empty())
      throw InputError(at, "the " + enum_to_string(b.kind) + " body has no parameters (the intocps body has)");
    for (auto it = ps.begin(); it != ps.end(); ++it) {
      const std::string key = join_key(at, it.key());
      const IntocpsBodyParameter* d = exploration::find_intocps_body_parameter(it.key());
      if (d == nullptr)
        throw InputError(key, "unknown parameter of the intocps body (its names are the Body_Block FMU's: "
                              "battery_initial_energy, axle_offset, mu, servo_left.resistance.r, ...; "
                              "`swarmcheck run --help` lists them all)");
      if (d->initial_position_index == 0 || d->initial_position_index == 1)
        throw InputError(key, "a robot's position is its entry in robots; only initial_position[2] (the heading) "
                              "is a body parameter");
      from_json(it.value(), key, exploration::intocps_parameter_ref(b.intocps, *d));
    }
  }
  out = b;
}

}  // namespace swarmcheck::json_io

namespace swarmcheck::exploration {
namespace {

std::string parameter_path(std::string_view name) { return "body.parameters." + std::string(name); }

void require_parameter(bool ok, std::string_view name, const std::string& expected, double got) {
  if (ok) return;
  char buf[32];   // std::to_chars's shortest text, as every scenario message prints numbers
  const auto end = std::to_chars(buf, buf + sizeof buf, got).ptr;
  throw InputError(parameter_path(name), "expected " + expected + ", got " + std::string(buf, end));
}

// The fastest of the modes thesis-body.md section 7 names: RK4 at h = 1 ms is stable (on the real
// axis) for time constants above h / 2.785; below half a step the body's states blow up.
constexpr double kFastestMode_s = 0.5e-3;

}  // namespace

void validate_intocps_params(const IntocpsBodyParams& p) {
  for (const IntocpsBodyParameter& d : intocps_body_parameters()) {
    const double v = intocps_parameter_value(p, d);
    require_parameter(std::isfinite(v), d.name, "a finite number", v);
  }
  require_parameter(p.battery_initial_energy >= 0, "battery_initial_energy", "a number >= 0 (J)", p.battery_initial_energy);
  require_parameter(p.axle_half_width > 0, "axle_half_width", "a number > 0 (m)", p.axle_half_width);
  require_parameter(p.wheel_radius > 0, "wheel_radius", "a number > 0 (m)", p.wheel_radius);
  require_parameter(p.blade_position > 0, "body.R.bladePosition", "a number > 0 (m)", p.blade_position);
  require_parameter(p.robot_mass_without_battery + p.battery_mass > 0, "robot_mass_without_battery",
                    "a mass that with battery_mass is > 0 (kg)", p.robot_mass_without_battery);
  require_parameter(p.encoder_left_lsb > 0, "encoder_left.Quantisize.lsb", "a number > 0", p.encoder_left_lsb);
  require_parameter(p.encoder_right_lsb > 0, "encoder_right.Quantisize.lsb", "a number > 0", p.encoder_right_lsb);
  require_parameter(p.mu >= 0, "mu", "a number >= 0", p.mu);
  require_parameter(p.wheel_left_lateral_damping >= 0, "wheel_left.R.r", "a number >= 0 (N s/m)",
                    p.wheel_left_lateral_damping);
  require_parameter(p.wheel_right_lateral_damping >= 0, "wheel_right.R2.r", "a number >= 0 (N s/m)",
                    p.wheel_right_lateral_damping);
  const IntocpsBodyModel m = intocps_body_model(p);
  require_parameter(m.inertia > 0, "robot_inertia_without_battery", "an inertia that with the battery's is > 0",
                    p.robot_inertia_without_battery);
  const double mass = 1.0 / m.inv_mass;
  require_parameter(m.ground_friction == 0 || mass / m.ground_friction >= kFastestMode_s, "mu",
                    "a ground friction whose time constant mass / c is at least 0.5 ms (RK4 at 1 ms)", p.mu);
  const double damping = std::fmax(p.wheel_left_lateral_damping, p.wheel_right_lateral_damping);
  require_parameter(damping == 0 || mass / (2 * damping) >= kFastestMode_s, "wheel_left.R.r",
                    "a lateral damping d with mass / (2 d) at least 0.5 ms (RK4 at 1 ms)", damping);
  for (int side = 0; side < 2; ++side) {
    const IntocpsServoParams& s = side == 0 ? p.servo_left : p.servo_right;
    const std::string servo = side == 0 ? "servo_left." : "servo_right.";
    require_parameter(s.inductance_i > 0, servo + "inductance.i", "a number > 0 (H)", s.inductance_i);
    require_parameter(s.tau_i > 0, servo + "internal_controller.tauI", "a number > 0 (s)", s.tau_i);
    require_parameter(s.resistance_r >= 0 && (s.resistance_r == 0 || s.inductance_i / s.resistance_r >= kFastestMode_s),
                      servo + "resistance.r", "a resistance >= 0 with inductance / resistance at least 0.5 ms",
                      s.resistance_r);
    require_parameter(s.voltage_minimum <= s.voltage_maximum, servo + "voltage_limit.minimum",
                      "at most voltage_limit.maximum", s.voltage_minimum);
  }
}

}  // namespace swarmcheck::exploration
