#pragma once
// InputError: bad input from a user (scenario, mission, .fsm, trace, command line).
// The CLI prints what() once and exits with status 2; nothing is half-written.
#include <stdexcept>
#include <string>

namespace swarmcheck {

class InputError : public std::runtime_error {
 public:
  // where: "file:line:col", "file: params.a1" or a JSON path; what_expected: the sentence.
  InputError(const std::string& where, const std::string& what_expected)
      : std::runtime_error(where.empty() ? what_expected : where + ": " + what_expected),
        where_(where) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

}  // namespace swarmcheck
