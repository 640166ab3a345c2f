/* A library the test FMU built with SWARMCHECK_TEST_FMU_HELPER needs and ships beside its binary
 * (test_fmu.c): the master must load it from the FMU's binaries/linux64 folder. */
__attribute__((visibility("default"))) double swarmcheck_test_helper_scale(double x) { return x; }
