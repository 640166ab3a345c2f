/* The FMUs' shared library (target swarmcheck_fmu), built into swarmcheck so that `fmu export`
   needs no file beside the binary. FMU_SO_PATH (a string literal) is defined by fmi/CMakeLists.txt. */
    .section .rodata
    .global swarmcheck_fmu_so_begin
    .global swarmcheck_fmu_so_end
    .balign 16
swarmcheck_fmu_so_begin:
    .incbin FMU_SO_PATH
swarmcheck_fmu_so_end:
    .byte 0
    .section .note.GNU-stack,"",@progbits
