#pragma once
// The variables of the thesis interface (`fmu export --interface thesis`): the FMUs of thesis
// A's published INTO-CPS project, name for name, type for type (its handshake is Real: 0.0 /
// 1.0), causality for causality, so that its multi-model runs with swarmcheck's FMUs in place of
// its own. Declared as ports.hpp's are (the model description and fmi2Get/Set derive from them).
//
// The Controller is UController.fmu's variables with the thesis controller's law; the Body is
// Body_Block's with the intocps body (both for any number of instances: no global state).
//
// The Environment (thesis Environment.fmu, the PVSio-web FMU): N robots and M obstacle slots
// fixed at export, of which the first nRobots and nObstacles take part; plus four parameters the
// thesis's code fixes and swarmcheck's rules read (cellSize, epsilon, rule, seed).
#include <boost/hana.hpp>
#include <cstdint>

namespace swarmcheck::fmi {

struct ThesisEnvironmentParameters {   // causality parameter, variability fixed
  BOOST_HANA_DEFINE_STRUCT(ThesisEnvironmentParameters,
      (double, a1), (double, a2), (double, ertu_perc), (double, eta), (int32_t, flag), (double, lambda),
      (int32_t, mapSize), (double, max_ph), (int32_t, nRobots), (double, phi), (int32_t, port), (int32_t, s_range),
      (double, step_size), (int32_t, stepCount), (int32_t, nObstacles),
      (double, cellSize), (double, epsilon), (int32_t, rule), (int32_t, seed));
};
struct ThesisEnvironmentOutputs {
  BOOST_HANA_DEFINE_STRUCT(ThesisEnvironmentOutputs, (double, onDestinationOutput), (double, eP), (double, sTime));
};
struct ThesisEnvironmentRobotInputs {   // per robot
  BOOST_HANA_DEFINE_STRUCT(ThesisEnvironmentRobotInputs, (double, onDestination__Input), (double, x_), (double, y_));
};
struct ThesisEnvironmentRobotOutputs {   // per robot
  BOOST_HANA_DEFINE_STRUCT(ThesisEnvironmentRobotOutputs, (double, xDesired), (double, yDesired));
};
// Per robot lx_, ly_ and per obstacle ox_, oy_: ports.hpp's EnvironmentRobotParameters and
// EnvironmentObstacleParameters.

// The Controller (thesis UController.fmu, PVSio-web): every port Real; its state variables are
// parameters as PVSio-web exports them (maneuver, beta: the start state; then the current values).
struct ThesisControllerParameters {
  BOOST_HANA_DEFINE_STRUCT(ThesisControllerParameters,
      (double, k_beta), (double, k_v), (int32_t, maneuver), (double, beta), (double, rho), (double, v), (double, w));
};
struct ThesisControllerInputs {
  BOOST_HANA_DEFINE_STRUCT(ThesisControllerInputs,
      (double, x), (double, y), (double, phi), (double, xDesired), (double, yDesired), (double, onDestinationInput));
};
struct ThesisControllerOutputs {
  BOOST_HANA_DEFINE_STRUCT(ThesisControllerOutputs, (double, servoLeft), (double, servoRight), (double, onDestinationOutput));
};
// The Body (thesis Body_Block1..4.fmu, 20-sim): the intocps body's variables, named in
// intocps_body_component.cpp from spec/exploration/body_intocps.hpp's parameter list.

}  // namespace swarmcheck::fmi
