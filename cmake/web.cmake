# The Emscripten builds: `web-cli` (the engine and coolaaber-cli, run by Node) and `web` (the
# whole game as a web page: COOLAABER_GAME on). docs/web.md.
#
# The header-only packages, from Debian's /usr/include. Emscripten compiles against its own
# sysroot; adding /usr/include to the search path would put glibc's headers in front of
# Emscripten's libc. So each package's folder alone is linked into build/<preset>/web-include,
# and targets of the names find_package gives natively point there.
set(COOLAABER_WEB_INCLUDE ${CMAKE_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${COOLAABER_WEB_INCLUDE})
set(header_packages nlohmann fmt CLI)
if(COOLAABER_GAME)
  list(APPEND header_packages glm stb)
endif()
foreach(package_dir ${header_packages})
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

# Bad input is reported by exceptions (game::LoadError): Emscripten only catches them when asked.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

if(NOT COOLAABER_GAME)
  # Programs run by Node (the CLI, the tests' programs): the real file system, memory as needed,
  # the exit status passed on.
  add_link_options(-sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1 -sEXIT_RUNTIME=1)
  return()
endif()

# ---- The game in the browser
# Threads (the computer player and Hint think on a worker, the page never freezes): every object
# is compiled with -pthread; the page then needs the COOP/COEP headers (docs/web.md). The
# fallback without them (the `web-nothreads` preset) is the same game without -pthread, whose
# thinking runs in time slices between frames (app/platform_task_sliced.cpp).
if(COOLAABER_WEB_THREADS)
  add_compile_options(-pthread)
  add_link_options(-pthread)
endif()

# render's OpenGL: WebGL 2 is OpenGL ES 3.0. The sources include <epoxy/gl.h> (the desktop's
# loader); here that name is cmake/web-shims/epoxy/gl.h, Emscripten's GLES 3 header, and the
# shaders' #version line is picked by COOLAABER_GLSL_ES (render/shaders.hpp).
set(WEB_SHIMS ${PROJECT_SOURCE_DIR}/cmake/web-shims)
add_library(PkgConfig::EPOXY INTERFACE IMPORTED)
target_include_directories(PkgConfig::EPOXY SYSTEM INTERFACE ${WEB_SHIMS})
target_compile_definitions(PkgConfig::EPOXY INTERFACE COOLAABER_GLSL_ES=1)
add_library(glm::glm INTERFACE IMPORTED)
target_include_directories(glm::glm SYSTEM INTERFACE ${COOLAABER_WEB_INCLUDE})
# Debian's libstb is compiled for the host: the functions render uses, from its headers.
add_library(stb_web STATIC ${WEB_SHIMS}/stb_implementations.cpp)
target_include_directories(stb_web SYSTEM PUBLIC ${COOLAABER_WEB_INCLUDE}/stb)
target_compile_options(stb_web PRIVATE -w)
add_library(PkgConfig::STB ALIAS stb_web)
# Emscripten's OpenAL plays through Web Audio; it has no alext.h (cmake/web-shims/AL).
add_library(openal_web STATIC ${WEB_SHIMS}/openal_web.cpp)
target_include_directories(openal_web SYSTEM PUBLIC ${WEB_SHIMS})
target_link_libraries(openal_web PUBLIC -lopenal)
add_library(OpenAL::OpenAL ALIAS openal_web)

# Dear ImGui: its core and the GLFW and OpenGL ES 3 backends, compiled from Debian's source
# package (the same 1.86 as the desktop's libimgui-dev), fetched once into the build folder.
# The fallback's build shares the threaded build's copy (COOLAABER_IMGUI_CACHE, CMakePresets.json).
set(COOLAABER_IMGUI_CACHE ${CMAKE_BINARY_DIR}/imgui-src CACHE PATH "Dear ImGui's fetched sources")
set(IMGUI_CACHE ${COOLAABER_IMGUI_CACHE})
execute_process(COMMAND ${PROJECT_SOURCE_DIR}/scripts/fetch-imgui-source ${IMGUI_CACHE}
                RESULT_VARIABLE fetched)
file(GLOB IMGUI_DIR ${IMGUI_CACHE}/imgui-*)
if(NOT fetched EQUAL 0 OR NOT EXISTS "${IMGUI_DIR}/imgui.cpp")
  message(FATAL_ERROR "Dear ImGui's sources could not be fetched (scripts/fetch-imgui-source)")
endif()
add_library(imgui_web STATIC
  ${IMGUI_DIR}/imgui.cpp ${IMGUI_DIR}/imgui_draw.cpp ${IMGUI_DIR}/imgui_tables.cpp
  ${IMGUI_DIR}/imgui_widgets.cpp ${IMGUI_DIR}/backends/imgui_impl_glfw.cpp
  ${IMGUI_DIR}/backends/imgui_impl_opengl3.cpp)
# The desktop includes <imgui.h> and <backends/...> from /usr/include/imgui.
target_include_directories(imgui_web SYSTEM PUBLIC ${IMGUI_DIR})
target_compile_definitions(imgui_web PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(imgui_web PRIVATE -w -sUSE_GLFW=3)
target_link_options(imgui_web PUBLIC -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2)

# The page: coolaaber.html (from src/app/web/shell.html), .js, .wasm, .data (the fonts), the
# worker script for the threads, and the installable app's files.
function(coolaaber_web_page target)
  set(web ${PROJECT_SOURCE_DIR}/src/app/web)
  # The fonts where the desktop finds them: the panel's, and the balls' numbers.
  set(fonts /usr/share/fonts/truetype/dejavu)
  target_link_options(${target} PRIVATE
    -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=64MB
    -sEXPORTED_RUNTIME_METHODS=FS -sENVIRONMENT=web,worker
    -lidbfs.js "SHELL:--pre-js ${web}/files.js"
    # SHELL: keeps each pair (CMake would merge the repeated --preload-file).
    "SHELL:--preload-file ${fonts}/DejaVuSans.ttf@${fonts}/DejaVuSans.ttf"
    "SHELL:--preload-file ${fonts}/DejaVuSans-Bold.ttf@${fonts}/DejaVuSans-Bold.ttf")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${web}/files.js)
  if(NOT COOLAABER_WEB_THREADS)
    coolaaber_web_fallback(${target})
    return()
  endif()
  set_target_properties(${target} PROPERTIES SUFFIX .html)
  target_link_options(${target} PRIVATE "SHELL:--shell-file ${web}/shell.html" -sMINIFY_HTML=0
                      -sPTHREAD_POOL_SIZE=4)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${web}/shell.html)
  # The installable app: the service worker (offline, and the headers), its manifest and icon.
  foreach(file sw.js coolaaber.webmanifest icon.svg)
    add_custom_command(TARGET ${target} POST_BUILD COMMAND ${CMAKE_COMMAND} -E copy_if_different
                       ${web}/${file} $<TARGET_FILE_DIR:${target}>/${file})
  endforeach()
endfunction()

# The fallback without threads: coolaaber-nothreads.js (.wasm, .data) beside the threaded page
# (COOLAABER_WEB_PAGE_DIR), which loads it where the page is not cross-origin isolated. The
# thinking's fibers swap stacks by Asyncify; the modules that never hold a paused stack (no AI
# pause point below them) are left uninstrumented, which keeps the wasm small and fast.
function(coolaaber_web_fallback target)
  set_target_properties(${target} PROPERTIES SUFFIX .js OUTPUT_NAME coolaaber-nothreads)
  if(COOLAABER_WEB_PAGE_DIR)
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${COOLAABER_WEB_PAGE_DIR})
  endif()
  target_link_options(${target} PRIVATE -sASYNCIFY
    "-sASYNCIFY_REMOVE=['physics::*','rules::*','render::*','audio::*','Im*']")
endfunction()
