#include "spec/exploration/trace_field.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "spec/exploration/trace.hpp"
#include "spec/util/demand.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::exploration {
namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

std::string float32_bytes(const std::vector<double>& values) {
  std::string out(values.size() * 4, '\0');
  for (std::size_t k = 0; k < values.size(); ++k) {
    const uint32_t bits = std::bit_cast<uint32_t>(static_cast<float>(values[k]));
    for (int b = 0; b < 4; ++b) out[k * 4 + b] = static_cast<char>((bits >> (8 * b)) & 0xffU);
  }
  return out;
}

std::string bit_bytes(const std::vector<bool>& bits) {
  std::string out((bits.size() + 7) / 8, '\0');
  for (std::size_t k = 0; k < bits.size(); ++k)
    if (bits[k]) out[k / 8] = static_cast<char>(static_cast<unsigned char>(out[k / 8]) | (1U << (k % 8)));
  return out;
}

}  // namespace

std::string base64_encode(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    uint32_t v = 0;
    for (std::size_t b = 0; b < 3; ++b)
      v = (v << 8) | (b < n ? static_cast<unsigned char>(bytes[k + b]) : 0U);
    for (std::size_t s = 0; s < 4; ++s)
      out += s <= n ? kAlphabet[(v >> (18 - 6 * s)) & 63U] : '=';
  }
  SWARM_DEMAND(out.size() % 4 == 0);
  return out;
}

std::string base64_decode(std::string_view text, const std::string& where) {
  if (text.size() % 4 != 0)
    throw InputError(where, "expected base64 text (a multiple of 4 characters), got " +
                                std::to_string(text.size()) + " characters");
  std::string out;
  out.reserve(text.size() / 4 * 3);
  for (std::size_t k = 0; k < text.size(); k += 4) {
    uint32_t v = 0;
    int pad = 0;
    for (std::size_t s = 0; s < 4; ++s) {
      const char c = text[k + s];
      const bool last_group = k + 4 == text.size();
      if (c == '=' && last_group && s >= 2) {
        ++pad;
        v <<= 6;
        continue;
      }
      const int x = sextet(c);
      if (x < 0 || pad > 0)
        throw InputError(where, "expected base64 text, got the character '" + std::string(1, c) +
                                    "' at offset " + std::to_string(k + s));
      v = (v << 6) | static_cast<uint32_t>(x);
    }
    for (int b = 0; b < 3 - pad; ++b) out += static_cast<char>((v >> (16 - 8 * b)) & 0xffU);
  }
  return out;
}

json_io::Json field_record(const FieldSnapshot& f) {
  const std::size_t cells = static_cast<std::size_t>(f.map_size) * static_cast<std::size_t>(f.map_size);
  SWARM_DEMAND(f.pheromone.size() == cells);
  SWARM_DEMAND(f.visited.size() == cells);
  Fnv1a digest;
  double max = 0.0;
  for (const double v : f.pheromone) {
    digest.add(v);
    max = std::max(max, v);
  }
  json_io::Json j = json_io::Json::object();
  j["type"] = "field";
  j["step"] = f.step;
  j["map_size"] = f.map_size;
  j["encoding"] = kFieldEncoding;
  j["pheromone"] = base64_encode(float32_bytes(f.pheromone));
  j["visited"] = base64_encode(bit_bytes(f.visited));
  j["pheromone_max"] = max;
  j["digest"] = digest.h;
  return j;
}

namespace {

DecodedField decode_field_unchecked(const json_io::Json& j, const std::string& where) {
  if (!j.is_object() || j.value("type", "") != "field")
    throw InputError(where, "expected a field record ({\"type\": \"field\", ...})");
  if (j.value("encoding", "") != kFieldEncoding)
    throw InputError(where, std::string("expected \"encoding\": \"") + kFieldEncoding + "\"");
  DecodedField d;
  json_io::from_json(j.at("step"), where + ": step", d.step);
  json_io::from_json(j.at("map_size"), where + ": map_size", d.map_size);
  json_io::from_json(j.at("pheromone_max"), where + ": pheromone_max", d.pheromone_max);
  json_io::from_json(j.at("digest"), where + ": digest", d.digest);
  if (d.map_size < 1 || d.map_size > 65536) throw InputError(where, "map_size out of range");
  const std::size_t cells = static_cast<std::size_t>(d.map_size) * static_cast<std::size_t>(d.map_size);
  const std::string ph = base64_decode(j.at("pheromone").get<std::string>(), where + ": pheromone");
  const std::string vis = base64_decode(j.at("visited").get<std::string>(), where + ": visited");
  if (ph.size() != cells * 4 || vis.size() != (cells + 7) / 8)
    throw InputError(where, "the field's size does not match map_size " + std::to_string(d.map_size));
  d.pheromone.resize(cells);
  d.visited.resize(cells);
  for (std::size_t k = 0; k < cells; ++k) {
    uint32_t bits = 0;
    for (int b = 0; b < 4; ++b) bits |= uint32_t{static_cast<unsigned char>(ph[k * 4 + b])} << (8 * b);
    d.pheromone[k] = std::bit_cast<float>(bits);
    d.visited[k] = ((static_cast<unsigned char>(vis[k / 8]) >> (k % 8)) & 1U) != 0;
  }
  return d;
}


}  // namespace

DecodedField decode_field_record(const json_io::Json& j, const std::string& where) {
  try {
    return decode_field_unchecked(j, where);
  } catch (const nlohmann::json::exception&) {
    throw InputError(where, "expected a field record with step, map_size, pheromone, visited, "
                            "pheromone_max and digest");
  }
}

}  // namespace swarmcheck::exploration
