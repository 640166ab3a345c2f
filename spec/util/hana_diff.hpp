#pragma once
// The first differing field of two values of a BOOST_HANA_DEFINE_STRUCT type, derived from the
// one declaration. Doubles are compared by their bits (the conformance contract: a difference
// is never a tolerance), so -0.0 differs from 0.0 and NaN equals a NaN of the same payload.
// Paths read like the JSON they would be written as: "robots[2].cell".
#include <array>
#include <bit>
#include <boost/hana.hpp>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::json_io {

struct FieldDiff {
  std::string path;
  std::string a;   // the first value as text
  std::string b;   // the second
};

template <class T>
std::string value_text(const T& v) {
  if constexpr (std::is_floating_point_v<T>) {
    char buf[40];
    const auto res = std::to_chars(buf, buf + sizeof buf, v);   // shortest round-trip form
    return std::string(buf, res.ptr);
  } else if constexpr (std::is_same_v<T, bool>) {
    return v ? "true" : "false";
  } else if constexpr (std::is_enum_v<T>) {
    return enum_to_string(v);
  } else if constexpr (std::is_arithmetic_v<T>) {
    return std::to_string(v);
  } else {
    return to_json(v).dump();
  }
}

template <class T>
bool same_bits(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, double>) return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
  else return a == b;
}

template <class T>
std::optional<FieldDiff> first_difference(const T& a, const T& b, const std::string& path = "") {
  if constexpr (is_hana_struct<T>) {
    std::optional<FieldDiff> found;
    boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
      if (found) return;
      const std::string name = boost::hana::to<const char*>(boost::hana::first(pair));
      found = first_difference(boost::hana::second(pair)(a), boost::hana::second(pair)(b),
                               path.empty() ? name : path + "." + name);
    });
    return found;
  } else if constexpr (IsArray<T>::value) {
    // Small arrays of numbers (cells, points) are shown whole: "(3,4)".
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_bits(a[i], b[i])) {
        auto text = [](const T& v) {
          std::string s = "(";
          for (std::size_t k = 0; k < v.size(); ++k) s += (k ? "," : "") + value_text(v[k]);
          return s + ")";
        };
        return FieldDiff{path, text(a), text(b)};
      }
    return std::nullopt;
  } else if constexpr (IsVector<T>::value) {
    if (a.size() != b.size())
      return FieldDiff{path + ".size", std::to_string(a.size()), std::to_string(b.size())};
    for (std::size_t i = 0; i < a.size(); ++i)
      if (auto d = first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]")) return d;
    return std::nullopt;
  } else if constexpr (IsOptional<T>::value) {
    if (a.has_value() != b.has_value())
      return FieldDiff{path, a ? value_text(*a) : "null", b ? value_text(*b) : "null"};
    if (a) return first_difference(*a, *b, path);
    return std::nullopt;
  } else {
    if (same_bits(a, b)) return std::nullopt;
    return FieldDiff{path, value_text(a), value_text(b)};
  }
}

}  // namespace swarmcheck::json_io
