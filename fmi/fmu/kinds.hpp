#pragma once
// The kinds of component (component.hpp), one file each (the thesis interface's Environment too).
#include <memory>
#include <span>
#include <vector>

#include "fmi/fmu/component.hpp"

namespace swarmcheck::fmi {

std::unique_ptr<Component> make_environment_component(const FmuSetup& setup);
std::unique_ptr<Component> make_thesis_environment_component(const FmuSetup& setup);
std::unique_ptr<Component> make_controller_component(const FmuSetup& setup);
std::unique_ptr<Component> make_thesis_controller_component(const FmuSetup& setup);
std::unique_ptr<Component> make_body_component(const FmuSetup& setup);
std::unique_ptr<Component> make_intocps_body_component(const FmuSetup& setup);

// Little-endian 8-byte fields of a saved state (component.cpp).
void put_state_u64(std::vector<uint8_t>& out, uint64_t v);
uint64_t take_state_u64(std::span<const uint8_t>& in);

}  // namespace swarmcheck::fmi
