#pragma once
// JSON I/O derived from one BOOST_HANA_DEFINE_STRUCT declaration (DESIGN.md: record types are
// declared once; JSON, field diffs and variable lists come from that declaration).
//
//   to_json(value)                    -> nlohmann::json object, keys in declaration order
//   from_json(json, path, value&)     -> overlays the keys present onto `value` (so a default
//                                        value supplies what is missing); unknown keys, wrong
//                                        types and out-of-range integers throw InputError
//                                        naming the JSON path, e.g. "params.a1" or "robots[2][0]".
//   require_complete<T>(json, path)   -> InputError naming the first member (at any depth) that
//                                        `json` leaves out: for records that must be whole, such
//                                        as a trace's, where a default would hide a missing field
//   field_names<T>()                  -> the member names, in order
//
// Enums are written as strings through EnumNames<E> (a specialisation lists the pairs).
#include <array>
#include <boost/hana.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "spec/util/input_error.hpp"

namespace swarmcheck::json_io {

using Json = nlohmann::ordered_json;

// JSON text for a user to read: a string that is not UTF-8 (a path the user typed, taken from
// the system as bytes) is printed with U+FFFD in place of its bad bytes instead of throwing.
inline std::string dump_text(const Json& j, int indent = -1) {
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

// o[key] when o is an object holding a string there, else "" (for sniffing a record's kind:
// Json::value throws type_error on a member of another type, which is bad input, not a bug).
inline std::string string_member(const Json& o, const char* key) {
  if (!o.is_object()) return "";
  const auto it = o.find(key);
  return it != o.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// Specialise with: static constexpr std::array<std::pair<E, std::string_view>, N> names{...};
template <class E>
struct EnumNames;

// A type with its own JSON form: specialise with
//   static Json write(const T&);  static void read(const Json&, const std::string& path, T&);
template <class T>
struct JsonCodec;
template <class T>
concept HasJsonCodec = requires(const T& v) { JsonCodec<T>::write(v); };

// A struct member of type T is left out of its object when it equals T{} (specialise as
// std::true_type): keys added to a format later stay out of files that do not use them, so those
// files keep their bytes.
template <class T>
struct OmitWhenDefault : std::false_type {};

template <class T>
struct IsVector : std::false_type {};
template <class T>
struct IsVector<std::vector<T>> : std::true_type {};
template <class T>
struct IsArray : std::false_type {};
template <class T, std::size_t N>
struct IsArray<std::array<T, N>> : std::true_type {};
template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};

template <class T>
constexpr bool is_hana_struct = boost::hana::Struct<T>::value;

inline std::string join_key(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}
inline std::string join_index(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

inline std::string type_name(const Json& j) {
  if (j.is_number_integer() || j.is_number_unsigned()) return "an integer";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "a list";
  if (j.is_object()) return "an object";
  return "null";
}

template <class E>
std::string enum_to_string(E e) {
  for (const auto& [value, name] : EnumNames<E>::names)
    if (value == e) return std::string(name);
  return "?";
}

template <class E>
std::string enum_choices() {
  std::string out;
  for (const auto& [value, name] : EnumNames<E>::names) {
    (void)value;
    if (!out.empty()) out += "|";
    out += name;
  }
  return out;
}

template <class E>
E enum_from_string(const std::string& s, const std::string& path) {
  for (const auto& [value, name] : EnumNames<E>::names)
    if (name == s) return value;
  throw InputError(path, "expected one of " + enum_choices<E>() + ", got \"" + s + "\"");
}

template <class T>
Json to_json(const T& v);

template <class T>
void from_json(const Json& j, const std::string& path, T& out);

template <class T>
Json to_json(const T& v) {
  if constexpr (HasJsonCodec<T>) {
    return JsonCodec<T>::write(v);
  } else if constexpr (is_hana_struct<T>) {
    Json o = Json::object();
    boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
      const auto& member = boost::hana::second(pair)(v);
      using Member = std::decay_t<decltype(member)>;
      if constexpr (OmitWhenDefault<Member>::value) {
        if constexpr (IsOptional<Member>::value) {
          if (!member.has_value()) return;
        } else {
          if (member == Member{}) return;
        }
      }
      o[boost::hana::to<const char*>(boost::hana::first(pair))] = to_json(member);
    });
    return o;
  } else if constexpr (std::is_enum_v<T>) {
    return enum_to_string(v);
  } else if constexpr (IsVector<T>::value || IsArray<T>::value) {
    Json a = Json::array();
    for (const auto& e : v) a.push_back(to_json(e));
    return a;
  } else if constexpr (IsOptional<T>::value) {
    return v ? to_json(*v) : Json(nullptr);
  } else {
    return Json(v);
  }
}

template <class Int>
Int integer_from_json(const Json& j, const std::string& path) {
  if (!(j.is_number_integer() || j.is_number_unsigned()))
    throw InputError(path, "expected an integer, got " + type_name(j));
  if (j.is_number_unsigned()) {
    const auto u = j.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<Int>::max()))
      throw InputError(path, "integer " + std::to_string(u) + " is out of range");
    return static_cast<Int>(u);
  }
  const auto s = j.get<std::int64_t>();
  if constexpr (std::is_unsigned_v<Int>) {
    if (s < 0) throw InputError(path, "expected a non-negative integer, got " + std::to_string(s));
    return static_cast<Int>(s);
  } else {
    if (s < static_cast<std::int64_t>(std::numeric_limits<Int>::min()) ||
        s > static_cast<std::int64_t>(std::numeric_limits<Int>::max()))
      throw InputError(path, "integer " + std::to_string(s) + " is out of range");
    return static_cast<Int>(s);
  }
}

template <class T>
void struct_from_json(const Json& j, const std::string& path, T& out) {
  if (!j.is_object()) throw InputError(path.empty() ? "(top level)" : path,
                                       "expected an object, got " + type_name(j));
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
      if (it.key() == boost::hana::to<const char*>(boost::hana::first(pair))) {
        known = true;
        from_json(it.value(), join_key(path, it.key()), boost::hana::second(pair)(out));
      }
    });
    if (!known) {
      std::string keys;
      boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
        keys += (keys.empty() ? "" : ", ");
        keys += boost::hana::to<const char*>(boost::hana::first(pair));
      });
      throw InputError(join_key(path, it.key()), "unknown key (expected one of: " + keys + ")");
    }
  }
}

template <class T>
void from_json(const Json& j, const std::string& path, T& out) {
  if constexpr (HasJsonCodec<T>) {
    JsonCodec<T>::read(j, path, out);
  } else if constexpr (is_hana_struct<T>) {
    struct_from_json(j, path, out);
  } else if constexpr (std::is_same_v<T, bool>) {
    if (!j.is_boolean()) throw InputError(path, "expected a boolean, got " + type_name(j));
    out = j.get<bool>();
  } else if constexpr (std::is_enum_v<T>) {
    if (!j.is_string())
      throw InputError(path, "expected one of " + enum_choices<T>() + ", got " + type_name(j));
    out = enum_from_string<T>(j.get<std::string>(), path);
  } else if constexpr (std::is_integral_v<T>) {
    out = integer_from_json<T>(j, path);
  } else if constexpr (std::is_floating_point_v<T>) {
    if (!j.is_number()) throw InputError(path, "expected a number, got " + type_name(j));
    out = j.get<T>();
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (!j.is_string()) throw InputError(path, "expected a string, got " + type_name(j));
    out = j.get<std::string>();
  } else if constexpr (IsVector<T>::value) {
    if (!j.is_array()) throw InputError(path, "expected a list, got " + type_name(j));
    T v(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) from_json(j[i], join_index(path, i), v[i]);
    out = std::move(v);
  } else if constexpr (IsArray<T>::value) {
    if (!j.is_array() || j.size() != std::tuple_size_v<T>)
      throw InputError(path, "expected a list of " + std::to_string(std::tuple_size_v<T>) +
                                 " values, got " +
                                 (j.is_array() ? std::to_string(j.size()) + " values"
                                               : type_name(j)));
    for (std::size_t i = 0; i < j.size(); ++i) from_json(j[i], join_index(path, i), out[i]);
  } else if constexpr (IsOptional<T>::value) {
    if (j.is_null()) {
      out.reset();
    } else {
      typename T::value_type v{};
      from_json(j, path, v);
      out = std::move(v);
    }
  } else {
    static_assert(sizeof(T) == 0, "from_json: unsupported member type");
  }
}

template <class T>
std::vector<std::string> field_names() {
  std::vector<std::string> names;
  boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
    names.emplace_back(boost::hana::to<const char*>(boost::hana::first(pair)));
  });
  return names;
}

template <class T>
void require_complete(const Json& j, const std::string& path) {
  if constexpr (HasJsonCodec<T>) {
    return;   // its codec reads it whole or refuses it
  } else if constexpr (is_hana_struct<T>) {
    if (!j.is_object()) return;   // from_json names the wrong type
    boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
      const char* name = boost::hana::to<const char*>(boost::hana::first(pair));
      using Member = std::decay_t<decltype(boost::hana::second(pair)(std::declval<T&>()))>;
      const auto it = j.find(name);
      if (it == j.end() && OmitWhenDefault<Member>::value) return;   // left out: the default
      if (it == j.end()) throw InputError(join_key(path, name), "missing (a record must have every field)");
      require_complete<Member>(*it, join_key(path, name));
    });
  } else if constexpr (IsVector<T>::value || IsArray<T>::value) {
    if (!j.is_array()) return;
    for (std::size_t i = 0; i < j.size(); ++i) require_complete<typename T::value_type>(j[i], join_index(path, i));
  } else if constexpr (IsOptional<T>::value) {
    if (!j.is_null()) require_complete<typename T::value_type>(j, path);
  }
}

}  // namespace swarmcheck::json_io
