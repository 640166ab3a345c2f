# Every dependency is a Debian package (scripts/install-deps installs them).
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED)              # Hana is header-only, in Boost::boost
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(fmt REQUIRED)
find_package(TBB REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(Z3 REQUIRED IMPORTED_TARGET z3)   # Z3 ships no CMake config on Debian
if(SWARMCHECK_TESTS)
  find_package(GTest REQUIRED)
  find_package(rapidcheck REQUIRED)
endif()
if(SWARMCHECK_BENCH)
  find_package(benchmark REQUIRED)
endif()
# Optional: Open MPI spreads `dse` and `conform` over ranks (mpirun); without it they run on one
# machine's threads and say how to get MPI when started under mpirun.
find_package(MPI COMPONENTS CXX QUIET)   # the C API, found through the C++ compiler
if(MPI_CXX_FOUND)
  message(STATUS "swarmcheck: Open MPI found: dse and conform can run under mpirun")
else()
  message(STATUS "swarmcheck: MPI not found (install libopenmpi-dev openmpi-bin): building without distribution")
endif()
