# Warning sets. The library's own set is the strict one that the project
# promises (-std=c99 -Wall -Wextra -Wpedantic -Wconversion); hosts tools get a
# lighter one. SSDA_WERROR turns both into errors.
set(SSDA_LIB_WARNINGS
    -Wall -Wextra -Wpedantic -Wconversion -Wsign-conversion -Wshadow
    -Wstrict-prototypes -Wmissing-prototypes -Wcast-qual -Wundef)
set(SSDA_HOST_WARNINGS -Wall -Wextra)
if(SSDA_WERROR)
  list(APPEND SSDA_LIB_WARNINGS -Werror)
  list(APPEND SSDA_HOST_WARNINGS -Werror)
endif()

# ssda_host_target(<target>): C99 + host warnings for tests and tools.
function(ssda_host_target tgt)
  set_target_properties(${tgt} PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
  target_compile_options(${tgt} PRIVATE ${SSDA_HOST_WARNINGS})
endfunction()
