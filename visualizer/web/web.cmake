# stepwise-web: the app for the browser, one self-contained page (scripts/web.sh writes it to
# out/web/stepwise.html). Included by visualizer/CMakeLists.txt in the emscripten build.
add_executable(stepwise-web web/web_main.cpp web/stb.cpp headless/gl_texture.cpp)
set_source_files_properties(web/stb.cpp PROPERTIES COMPILE_OPTIONS -w)  # third-party code
set_target_properties(stepwise-web PROPERTIES SUFFIX ".html")
# emcc's JavaScript optimizer needs Debian's node modules (acorn) under any node: the link sets
# their folder, so a plain `cmake --build` works as scripts/web.sh does.
set_target_properties(stepwise-web PROPERTIES CXX_LINKER_LAUNCHER "${CMAKE_COMMAND};-E;env;NODE_PATH=/usr/share/nodejs")
target_link_libraries(stepwise-web PRIVATE sw_panels CLI11::CLI11)
# The data the app reads, at the paths it reads them from: the built-in data root /stepwise
# (runtime/data_root.cpp) and the fonts' own folder (panels/theme.cpp). Lessons' pictures are not
# read by the app; one mesh is named by a lesson.
set(SW_FONTS /usr/share/fonts/truetype/dejavu)
# Every example scene but the bunny, whose mesh alone (75,408 triangles, 2.6 MB) would be a sixth
# of the page; no lesson opens it.
file(GLOB lesson_texts ${PROJECT_SOURCE_DIR}/lessons/*.md ${PROJECT_SOURCE_DIR}/lessons/manifest.txt)
file(GLOB scene_files RELATIVE ${PROJECT_SOURCE_DIR} ${PROJECT_SOURCE_DIR}/scenes/*.json ${PROJECT_SOURCE_DIR}/scenes/textures/*)
list(REMOVE_ITEM scene_files scenes/bunny.json)
set(SW_WEB_DATA
  ${PROJECT_SOURCE_DIR}/lessons/calls@/stepwise/lessons/calls
  ${PROJECT_SOURCE_DIR}/out/meshes/elephant.off@/stepwise/out/meshes/elephant.off
  ${SW_FONTS}/DejaVuSans.ttf@${SW_FONTS}/DejaVuSans.ttf
  ${SW_FONTS}/DejaVuSans-Bold.ttf@${SW_FONTS}/DejaVuSans-Bold.ttf
  ${SW_FONTS}/DejaVuSansMono.ttf@${SW_FONTS}/DejaVuSansMono.ttf)
set(embed "")
foreach(file IN LISTS lesson_texts)
  cmake_path(GET file FILENAME name)
  list(APPEND SW_WEB_DATA ${file}@/stepwise/lessons/${name})
endforeach()
foreach(file IN LISTS scene_files)
  list(APPEND SW_WEB_DATA ${PROJECT_SOURCE_DIR}/${file}@/stepwise/${file})
endforeach()
foreach(item IN LISTS SW_WEB_DATA)
  list(APPEND embed "SHELL:--embed-file ${item}")
endforeach()
target_link_options(stepwise-web PRIVATE
  -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
  -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=64MB
  -sEXPORTED_FUNCTIONS=_main,_sw_state,_sw_open -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,FS
  -sMINIFY_HTML=0  # Debian's emcc 3.1.6 passes htmlmin a list where a string goes, and fails
  "SHELL:--shell-file ${CMAKE_CURRENT_SOURCE_DIR}/web/shell.html"
  "SHELL:--pre-js ${CMAKE_CURRENT_SOURCE_DIR}/web/pre.js"
  ${embed})
# How far the linker's wasm-opt shrinks the code (-O2 as the objects; -Os, -Oz: smaller, slower).
set(SW_WEB_LINK_OPT -O2 CACHE STRING "The browser page's link-time optimisation level")
target_link_options(stepwise-web PRIVATE ${SW_WEB_LINK_OPT})
set_property(TARGET stepwise-web APPEND PROPERTY LINK_DEPENDS
  ${CMAKE_CURRENT_SOURCE_DIR}/web/shell.html ${CMAKE_CURRENT_SOURCE_DIR}/web/pre.js ${lesson_texts})
# One file: the script and the wasm put into the page (single_file.py says why not -sSINGLE_FILE).
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_custom_command(TARGET stepwise-web POST_BUILD
  COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/web/single_file.py $<TARGET_FILE:stepwise-web>
          $<TARGET_FILE_DIR:stepwise-web>/stepwise.html
  VERBATIM)
