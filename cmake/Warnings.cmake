# swarmcheck_warnings(target): our own code builds clean under -Wall -Wextra -Werror.
# -Wno-restrict: GCC 12 reports std::string concatenation at -O3 as overlapping memcpy
# (a false positive, GCC bug 105329).
function(swarmcheck_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror -Wshadow -Wconversion
    -Wno-sign-conversion $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
endfunction()
