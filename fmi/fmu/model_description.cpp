#include "fmi/fmu/model_description.hpp"

#include <fmt/format.h>

#include <memory>

#include "spec/util/xml_text.hpp"

namespace swarmcheck::fmi {
namespace {

using text::xml_escape;

const char* description_of(const FmuSetup& setup) {
  const bool thesis = setup.interface == Interface::thesis;
  if (setup.kind == Kind::body && (thesis || setup.scenario.body.kind == exploration::BodyKind::intocps))
    return "Thesis A's 20-sim Body_Block: motors with inductance and a PI speed loop, chassis mass and inertia, "
           "lateral wheel slip, RK4 at 1 ms (swarmcheck spec/exploration/body_intocps.hpp)";
  if (setup.kind == Kind::controller && (thesis || setup.scenario.controller == exploration::ControllerKind::thesis))
    return "Thesis A's published UController, as its binary computes "
           "(swarmcheck spec/exploration/controller_thesis.hpp)";
  switch (setup.kind) {
    case Kind::environment:
      return "Stigmergic exploration Environment: grid map, repulsive pheromone, exploration percentage "
             "(swarmcheck spec/exploration/environment_step.hpp)";
    case Kind::controller:
      return "Two-phase unicycle point-to-point controller with the atan2 fix and servo saturation "
             "(swarmcheck spec/exploration/controller.hpp)";
    case Kind::body:
      return "Differential-drive body, the INTO-CPS line follower Body_Block's steady state "
             "(swarmcheck spec/exploration/body.hpp)";
  }
  return "";
}

}  // namespace

std::string model_description_xml(const FmuSetup& setup, const std::string& tool_version) {
  const std::unique_ptr<Component> c = make_component(setup);
  const std::string id = model_identifier(setup.kind);
  std::string x;
  x += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format(
      "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"{}\" guid=\"{}\" description=\"{}\" version=\"{}\" "
      "generationTool=\"swarmcheck {}\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n",
      model_name(setup), fmu_guid(setup), xml_escape(description_of(setup)), xml_escape(tool_version),
      xml_escape(tool_version));
  x += fmt::format(
      "  <CoSimulation modelIdentifier=\"{}\" needsExecutionTool=\"false\" "
      "canHandleVariableCommunicationStepSize=\"{}\" canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\" "
      "canRunAsynchronuously=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\" "
      "canNotUseMemoryManagementFunctions=\"true\" canGetAndSetFMUstate=\"true\" canSerializeFMUstate=\"true\" "
      "providesDirectionalDerivative=\"false\"/>\n",
      id, setup.kind == Kind::environment ? "false" : "true");
  x += "  <LogCategories>\n    <Category name=\"logError\" description=\"errors\"/>\n"
       "    <Category name=\"logAll\" description=\"every message\"/>\n  </LogCategories>\n";
  x += fmt::format("  <DefaultExperiment startTime=\"0\" stepSize=\"{}\"/>\n", setup.scenario.params.step_size);
  x += "  <ModelVariables>\n";
  const auto& vars = c->table().variables();
  for (const Variable& v : vars) {
    x += fmt::format("    <ScalarVariable name=\"{}\" valueReference=\"{}\" causality=\"{}\" variability=\"{}\"",
                     xml_escape(v.name), v.value_reference, to_string(v.causality), to_string(v.variability));
    if (v.initial != Initial::none) x += fmt::format(" initial=\"{}\"", to_string(v.initial));
    const std::string& d = c->table().description(v.value_reference);
    if (!d.empty()) x += fmt::format(" description=\"{}\"", xml_escape(d));
    x += ">\n      ";
    const bool start = v.initial == Initial::exact || v.causality == Causality::input;
    if (v.type == BaseType::real) x += start ? fmt::format("<Real start=\"{:.17g}\"/>", *v.real) : "<Real/>";
    else x += start ? fmt::format("<Integer start=\"{}\"/>", *v.integer) : "<Integer/>";
    x += "\n    </ScalarVariable>\n";
  }
  x += "  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n";
  for (const Variable& v : vars)
    if (v.causality == Causality::output)
      x += fmt::format("      <Unknown index=\"{}\" dependencies=\"\"/>\n", v.value_reference + 1);
  x += "    </Outputs>\n    <InitialUnknowns>\n";
  for (const Variable& v : vars)
    if (v.causality == Causality::output && v.initial == Initial::calculated)
      x += fmt::format("      <Unknown index=\"{}\"/>\n", v.value_reference + 1);
  x += "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
  return x;
}

}  // namespace swarmcheck::fmi
