#pragma once
// The FMI variables of one FMU instance, bound to the storage of its port structs (ports.hpp):
// the value reference of a variable is its position here. Built by walking the structs' Hana
// declarations, so the model description and fmi2Get/Set can never disagree with the code.
#include <boost/hana.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "fmi/fmu/ports.hpp"

namespace swarmcheck::fmi {

enum class BaseType : uint8_t { real, integer };
enum class Causality : uint8_t { parameter, input, output, local };
enum class Variability { constant, fixed, discrete, continuous };
enum class Initial { none, exact, calculated };

const char* to_string(BaseType t);
const char* to_string(Causality c);
const char* to_string(Variability v);
const char* to_string(Initial i);

struct Variable {
  std::string name;
  uint32_t value_reference = 0;
  BaseType type = BaseType::real;
  Causality causality = Causality::local;
  Variability variability = Variability::continuous;
  Initial initial = Initial::none;
  double* real = nullptr;       // the storage, by type
  int32_t* integer = nullptr;
};

// The role of a group of variables; what FMI 2.0 attributes it gets (section 2.2.7's table):
//   parameter -> causality parameter, variability fixed, initial exact (a start value)
//   constant  -> causality local, variability constant, initial exact
//   input     -> causality input, variability continuous (Real) or discrete (Integer), a start value
//   output    -> causality output, continuous/discrete, initial calculated (listed as InitialUnknown)
//   local     -> causality local, continuous/discrete, initial calculated
enum class Role { parameter, constant, input, output, local };

class VariableTable {
 public:
  // The FMU kind whose descriptions the variables bound next get ("environment", ...).
  explicit VariableTable(std::string_view kind = "") : kind_(kind) {}

  // Binds every member of `group` (k: robot or obstacle number, 1-based, for repeated groups).
  template <class Group>
  void bind(Group& group, Role role, std::optional<int32_t> k = std::nullopt) {
    boost::hana::for_each(boost::hana::accessors<Group>(), [&](auto pair) {
      const std::string member = boost::hana::to<const char*>(boost::hana::first(pair));
      auto& value = boost::hana::second(pair)(group);
      using T = std::remove_reference_t<decltype(value)>;
      static_assert(std::is_same_v<T, double> || std::is_same_v<T, int32_t>, "FMU ports are double or int32_t");
      Variable v;
      v.name = k ? index_name(member, *k) : member;
      v.value_reference = static_cast<uint32_t>(vars_.size());
      if constexpr (std::is_same_v<T, double>) {
        v.type = BaseType::real;
        v.real = &value;
      } else {
        v.type = BaseType::integer;
        v.integer = &value;
      }
      attributes(v, role);
      description_.push_back(describe(kind_, member, k));
      slots_.push_back(Slot{v.real ? static_cast<void*>(v.real) : static_cast<void*>(v.integer), v.type, v.causality});
      vars_.push_back(std::move(v));
    });
  }

  // Binds one Real variable whose name is no C++ identifier (the Body_Block's
  // `servo_left.friction.r`, `initial_position[0]`), with its description.
  void bind_named(double& value, std::string name, Role role, std::string description);

  const std::vector<Variable>& variables() const { return vars_; }
  // What fmi2Get/Set need of a variable, compact (the hot path of every communication step).
  struct Slot {
    void* storage;   // double* (Real) or int32_t* (Integer)
    BaseType type;
    Causality causality;
    double& real() const { return *static_cast<double*>(storage); }
    int32_t& integer() const { return *static_cast<int32_t*>(storage); }
  };
  const std::vector<Slot>& slots() const { return slots_; }   // by value reference
  const std::string& description(uint32_t vr) const { return description_[vr]; }
  const Variable* find(uint32_t vr) const { return vr < vars_.size() ? &vars_[vr] : nullptr; }
  const Variable* find(const std::string& name) const;

 private:
  static void attributes(Variable& v, Role role);
  std::vector<Variable> vars_;
  std::vector<Slot> slots_;
  std::vector<std::string> description_;
  std::string_view kind_;   // whose descriptions (ports.hpp's describe)
};

}  // namespace swarmcheck::fmi
