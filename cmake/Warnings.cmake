# swarmcheck_warnings(target): our own code builds clean under -Wall -Wextra -Werror.
function(swarmcheck_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror -Wshadow -Wconversion
    -Wno-sign-conversion)
endfunction()
