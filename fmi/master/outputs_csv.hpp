#pragma once
// outputs.csv as the INTO-CPS engine writes it (its CSV result logger), so that tools reading the
// engine's results read swarmcheck's:
//   time,step-size,{FMU}.instance.variable,...    the recorded variables (Master::recorded_names:
//                                                 connected outputs and logVariables), sorted
//   0.0,0.0,...                                   after initialisation: startTime, step-size 0
//   0.1,0.1,...                                   after each step: the time after it, the step
// Reals as Java's Double.toString writes them (java_double_text), Integers in decimal, Booleans
// true / false, Strings in double quotes (a quote doubled).
#include <ostream>
#include <string>

#include "fmi/master/master.hpp"

namespace swarmcheck::fmi::master {

// Java's Double.toString (JDK 19 and later, which pick the shortest decimal that reads back to
// the same double; earlier JDKs sometimes wrote one digit more): "0.1", "0.30000000000000004",
// "1.0", "100.0", "1.0E-5", "1.234E7", "-0.0", "NaN", "Infinity". Plain notation for
// 10^-3 <= |v| < 10^7, else d.ddddE[-]n; always a digit after the point.
std::string java_double_text(double v);

class OutputsCsv {
 public:
  explicit OutputsCsv(const Master& master) : master_(master) {}
  void header(std::ostream& out) const;
  // One row with the recorded variables' values now.
  void row(std::ostream& out, double time_s, double step_s) const;

 private:
  const Master& master_;
};

}  // namespace swarmcheck::fmi::master
