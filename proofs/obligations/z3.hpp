#pragma once
// z3++.h does not build clean under our warning flags (-Wconversion, -Wshadow): include it
// through this header only, with those diagnostics silenced for the library's code.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#include <z3++.h>
#pragma GCC diagnostic pop
