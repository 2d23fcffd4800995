# The header-only packages for an Emscripten build, from Debian's /usr/include.
# Emscripten compiles against its own sysroot; adding /usr/include to the search path would put
# glibc's headers in front of Emscripten's libc. So each package's folder alone is linked into
# build/<preset>/web-include, and targets of the names find_package gives natively point there.
set(COOLAABER_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${COOLAABER_WEB_INCLUDE})
foreach(package_dir nlohmann fmt CLI)
  if(NOT EXISTS /usr/include/${package_dir})
    message(FATAL_ERROR "/usr/include/${package_dir} is missing: run scripts/install-deps --web")
  endif()
  file(CREATE_LINK /usr/include/${package_dir} ${COOLAABER_WEB_INCLUDE}/${package_dir} SYMBOLIC)
endforeach()

add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${COOLAABER_WEB_INCLUDE})
add_library(CLI11::CLI11 INTERFACE IMPORTED)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${COOLAABER_WEB_INCLUDE})
# Debian ships fmt compiled for the host only; its headers also build it inline.
add_library(fmt::fmt INTERFACE IMPORTED)
target_include_directories(fmt::fmt SYSTEM INTERFACE ${COOLAABER_WEB_INCLUDE})
target_compile_definitions(fmt::fmt INTERFACE FMT_HEADER_ONLY=1)

# Programs run by Node (the CLI, the tests' programs): the real file system, memory as needed,
# the exit status passed on.
add_link_options(-sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1)
# Bad input is reported by exceptions (game::LoadError): Emscripten only catches them when asked.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
