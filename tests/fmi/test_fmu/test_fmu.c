/* A test FMU that behaves as the thesis's FMUs do, for the master's tests (tests/fmi/engine_test.cpp,
 * tests/fmi/timeout_test.cpp). Plain C, FMI 2.0 co-simulation:
 *   - all its state is global (one model per loaded copy of the library), as the thesis's 20-sim
 *     Body; its model description declares canBeInstantiatedOnlyOncePerProcess="true";
 *   - it does not apply its own start values: init sets its own constants (gain = 0.2f, a float
 *     literal, where the description says 2.0) and an input keeps what it was last given (u starts
 *     at 123.0 here, 0.25 in the description), as the thesis's PVSio-web FMUs;
 *   - its handshake ports are Real (flagIn, flagOut: 0.0 / 1.0);
 *   - with blockAtStep = k it blocks in its k-th fmi2DoStep (from 1), forever, as the thesis's
 *     Environment waiting for a live-view client; with blockSignals = 1 it also blocks every
 *     signal first;
 *   - built with SWARMCHECK_TEST_FMU_HELPER it needs libswarmcheck_test_helper.so, which its
 *     archive ships beside it in binaries/linux64 (the binary has no RPATH: only a master that
 *     loads the shipped library first can load it).
 * Variables (value reference: name, causality, type):
 *   0 gain parameter Real       y += gain * u + offset each step
 *   1 offset parameter Integer
 *   2 u input Real
 *   3 y output Real
 *   4 flagIn input Real
 *   5 flagOut output Real        flagIn as of the step before
 *   6 blockAtStep parameter Integer
 *   7 blockSignals parameter Integer
 *   8 instancesInLibrary output Integer   fmi2Instantiate calls this copy of the library served
 *   9 steps output Integer
 *  10 tag parameter String
 *  11 tagLength output Integer
 * If SWARMCHECK_TEST_FMU_TRACE names a file, fmi2Instantiate and fmi2FreeInstance append a line
 * "instantiate NAME" / "free NAME" to it (the tests check that every instance is freed). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fmi/fmi2/fmi2_api.h"

#define EXPORT __attribute__((visibility("default")))

#ifdef SWARMCHECK_TEST_FMU_HELPER
double swarmcheck_test_helper_scale(double x);
#define SCALE(x) swarmcheck_test_helper_scale(x)
#else
#define SCALE(x) (x)
#endif

static double gain, u, y, flag_in, flag_out;
static int offset, block_at_step, block_signals, instances, steps, tag_length;
static char tag[256];
static char name[256];
static int handle;   /* the address returned as the fmi2Component */

static void trace(const char* what) {
  const char* file = getenv("SWARMCHECK_TEST_FMU_TRACE");
  if (!file || !*file) return;
  FILE* f = fopen(file, "a");
  if (!f) return;
  fprintf(f, "%s %s\n", what, name);
  fclose(f);
}

static void init(void) {
  /* Its own constants, not the description's start values. */
  gain = 0.2f;
  offset = 0;
  u = 123.0;
  y = 0.0;
  flag_in = 0.0;
  flag_out = 0.0;
  block_at_step = -1;
  block_signals = 0;
  steps = 0;
  strcpy(tag, "init");
  tag_length = 4;
}

EXPORT const char* fmi2GetTypesPlatform(void) { return "default"; }
EXPORT const char* fmi2GetVersion(void) { return "2.0"; }
EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[]) {
  (void)c, (void)on, (void)n, (void)cat;
  return fmi2OK;
}

EXPORT fmi2Component fmi2Instantiate(fmi2String instance, fmi2Type type, fmi2String guid, fmi2String resources,
                                     const fmi2CallbackFunctions* functions, fmi2Boolean visible, fmi2Boolean logging) {
  (void)type, (void)guid, (void)resources, (void)functions, (void)visible, (void)logging;
  snprintf(name, sizeof name, "%s", instance ? instance : "");
  init();
  ++instances;
  trace("instantiate");
  return &handle;
}
EXPORT void fmi2FreeInstance(fmi2Component c) {
  (void)c;
  trace("free");
}
EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean a, fmi2Real b, fmi2Real start, fmi2Boolean d, fmi2Real e) {
  (void)c, (void)a, (void)b, (void)start, (void)d, (void)e;
  return fmi2OK;
}
EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  (void)c;
  tag_length = (int)strlen(tag);
  return fmi2OK;
}
EXPORT fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
EXPORT fmi2Status fmi2Reset(fmi2Component c) {
  (void)c;
  init();
  return fmi2OK;
}

static double* real_of(fmi2ValueReference vr) {
  switch (vr) {
    case 0: return &gain;
    case 2: return &u;
    case 3: return &y;
    case 4: return &flag_in;
    case 5: return &flag_out;
    default: return NULL;
  }
}
static int* integer_of(fmi2ValueReference vr) {
  switch (vr) {
    case 1: return &offset;
    case 6: return &block_at_step;
    case 7: return &block_signals;
    case 8: return &instances;
    case 9: return &steps;
    case 11: return &tag_length;
    default: return NULL;
  }
}

EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    double* v = real_of(vr[k]);
    if (!v) return fmi2Error;
    value[k] = *v;
  }
  return fmi2OK;
}
EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    double* v = real_of(vr[k]);
    if (!v) return fmi2Error;
    *v = value[k];
  }
  return fmi2OK;
}
EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    int* v = integer_of(vr[k]);
    if (!v) return fmi2Error;
    value[k] = *v;
  }
  return fmi2OK;
}
EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    int* v = integer_of(vr[k]);
    if (!v) return fmi2Error;
    *v = value[k];
  }
  return fmi2OK;
}
EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean value[]) {
  (void)c, (void)vr, (void)value;
  return n == 0 ? fmi2OK : fmi2Error;
}
EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean value[]) {
  (void)c, (void)vr, (void)value;
  return n == 0 ? fmi2OK : fmi2Error;
}
EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != 10) return fmi2Error;
    value[k] = tag;
  }
  return fmi2OK;
}
EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String value[]) {
  (void)c;
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != 10 || !value[k]) return fmi2Error;
    snprintf(tag, sizeof tag, "%s", value[k]);
  }
  return fmi2OK;
}

static void block_forever(void) {
  if (block_signals) {
    sigset_t all;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, NULL);
  }
  for (;;) pause();
}

EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean no_prior) {
  (void)c, (void)t, (void)h, (void)no_prior;
  ++steps;
  if (steps == block_at_step) block_forever();
  y += SCALE(gain * u) + offset;
  flag_out = flag_in;
  return fmi2OK;
}
EXPORT fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }
EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status* s) {
  (void)c, (void)k, (void)s;
  return fmi2Error;
}
EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real* v) {
  (void)c, (void)k, (void)v;
  return fmi2Error;
}
EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer* v) {
  (void)c, (void)k, (void)v;
  return fmi2Error;
}
EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean* v) {
  (void)c, (void)k, (void)v;
  return fmi2Error;
}
EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String* v) {
  (void)c, (void)k, (void)v;
  return fmi2Error;
}
