# The browser build's dependencies (scripts/web.sh configures with emcmake): the same target names
# the native build takes from pkg-config and find_package, here made from the wasm libraries that
# scripts/web-deps.sh builds from Debian's source packages into SW_WEB_CACHE, and from the host's
# header-only packages (CGAL, Boost, nlohmann-json, CLI11, stb, GLM), seen through a folder of links to
# just those headers: the host's /usr/include as a whole would shadow emscripten's libc.
set(SW_WEB_CACHE "/var/cache/stepwise-web" CACHE PATH "The wasm libraries' prefix (scripts/web-deps.sh)")
if(NOT EXISTS ${SW_WEB_CACHE}/lib/libgmpxx.a)
  message(FATAL_ERROR "no wasm GMP in ${SW_WEB_CACHE}: run scripts/web-deps.sh (scripts/web.sh does)")
endif()
set(SW_HOST_HEADERS ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${SW_HOST_HEADERS})
foreach(dir CGAL boost nlohmann CLI stb glm)
  if(NOT EXISTS /usr/include/${dir})
    message(FATAL_ERROR "/usr/include/${dir} is missing: scripts/web-deps.sh installs the header-only packages")
  endif()
  file(CREATE_LINK /usr/include/${dir} ${SW_HOST_HEADERS}/${dir} SYMBOLIC)
endforeach()

function(sw_web_library name)  # name [LIBS libs...] [INCLUDES dirs...] [DEFINES defs...]
  cmake_parse_arguments(W "" "" "LIBS;INCLUDES;DEFINES" ${ARGN})
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  list(TRANSFORM W_LIBS PREPEND ${SW_WEB_CACHE}/lib/)
  target_link_libraries(${name} INTERFACE ${W_LIBS})
  target_include_directories(${name} SYSTEM INTERFACE ${W_INCLUDES})
  target_compile_definitions(${name} INTERFACE ${W_DEFINES})
endfunction()
sw_web_library(PkgConfig::GMPXX LIBS libgmpxx.a libgmp.a INCLUDES ${SW_WEB_CACHE}/include)
set(MPFR_LIBRARY ${SW_WEB_CACHE}/lib/libmpfr.a)
sw_web_library(nlohmann_json::nlohmann_json INCLUDES ${SW_HOST_HEADERS})
sw_web_library(CLI11::CLI11 INCLUDES ${SW_HOST_HEADERS})
sw_web_library(PkgConfig::STB INCLUDES ${SW_HOST_HEADERS}/stb)
# wasm cannot set the FPU's rounding mode, which CGAL's intervals would: they round to nearest and
# widen instead (CGAL/FPU.h).
sw_web_library(CGAL::CGAL INCLUDES ${SW_HOST_HEADERS} DEFINES CGAL_ALWAYS_ROUND_TO_NEAREST)
sw_web_library(PkgConfig::MD4C LIBS libmd4c.a INCLUDES ${SW_WEB_CACHE}/include)
# 32-bit vertex indices, as scripts/web-deps.sh builds ImGui: WebGL has no base vertex to split a
# draw list of more than 65,536 vertices by (the 3D view of a mesh has more).
sw_web_library(PkgConfig::IMGUI LIBS libimgui.a INCLUDES ${SW_WEB_CACHE}/include/imgui ${SW_HOST_HEADERS}/stb
               DEFINES "ImDrawIdx=unsigned int")

# Exceptions carry every refusal (InputError) in the app: catching must be on, in every unit. The
# browser's own (wasm) exceptions, not emscripten's JavaScript ones: 30 % less code, no call wrappers.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
