#pragma once
// UTF-8 checks for text that ends up in JSON (names in .fsm files, paths): nlohmann's dump throws
// on invalid UTF-8, so text is validated where it is read, or printed with replacement where it
// comes from the system (a path the user typed).
#include <cstddef>
#include <string_view>

namespace swarmcheck::utf8 {

// The length of a UTF-8 byte order mark at the start of s (3), or 0. Editors on Windows write
// one; nlohmann's parser skips it in JSON, and the other readers skip it with this.
inline std::size_t byte_order_mark_size(std::string_view s) { return s.starts_with("\xEF\xBB\xBF") ? 3 : 0; }

// The offset of the first byte that does not begin a well-formed UTF-8 sequence (overlong forms,
// surrogates and code points above U+10FFFF included), or npos when the text is valid.
inline std::size_t first_invalid_byte(std::string_view s) {
  std::size_t k = 0;
  while (k < s.size()) {
    const auto b = static_cast<unsigned char>(s[k]);
    std::size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;   // the second byte's range
    if (b < 0x80) len = 1;
    else if (b >= 0xC2 && b <= 0xDF) len = 2;
    else if (b == 0xE0) len = 3, lo = 0xA0;
    else if (b >= 0xE1 && b <= 0xEC) len = 3;
    else if (b == 0xED) len = 3, hi = 0x9F;
    else if (b >= 0xEE && b <= 0xEF) len = 3;
    else if (b == 0xF0) len = 4, lo = 0x90;
    else if (b >= 0xF1 && b <= 0xF3) len = 4;
    else if (b == 0xF4) len = 4, hi = 0x8F;
    else return k;
    if (k + len > s.size()) return k;
    for (std::size_t i = 1; i < len; ++i) {
      const auto c = static_cast<unsigned char>(s[k + i]);
      if (i == 1 ? (c < lo || c > hi) : (c < 0x80 || c > 0xBF)) return k;
    }
    k += len;
  }
  return std::string_view::npos;
}

inline bool valid(std::string_view s) { return first_invalid_byte(s) == std::string_view::npos; }

}  // namespace swarmcheck::utf8
