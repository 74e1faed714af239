# m3055_library(NAME FOLDER folder [USES lib...] [EXTERNAL target...]
#               [PRIVATE_EXTERNAL target...] [SOURCES file...] [DESKTOP_ONLY file...])
#
# EXTERNAL: third-party targets its headers expose; PRIVATE_EXTERNAL: used only
# in its .cpp files. SOURCES: generated files that belong to it. DESKTOP_ONLY:
# files of the folder left out of the browser build (Emscripten: scripts/web),
# e.g. the headless EGL and OSMesa contexts.
#
# One folder of the source tree becomes one static library, m3055_<name>. Its
# headers are reached as "<leaf>/file.h" (leaf: the folder's last component),
# through an include root of its own in the build tree that holds nothing but a
# link to the folder. A library sees its own root and the roots of the libraries
# it USES (and what they use): an #include of any other folder fails to compile.
# The USES lists are the layering; docs/architecture.md shows them and
# tests/layering_test.cpp fails when the two disagree (it reads
# library_graph.txt, written below).
function(m3055_library name)
  cmake_parse_arguments(ARG "" "FOLDER" "USES;EXTERNAL;PRIVATE_EXTERNAL;SOURCES;DESKTOP_ONLY" ${ARGN})
  set(folder "${PROJECT_SOURCE_DIR}/${ARG_FOLDER}")
  get_filename_component(leaf "${folder}" NAME)
  set(root "${PROJECT_BINARY_DIR}/include_roots/${name}")
  file(MAKE_DIRECTORY "${root}")
  if(NOT EXISTS "${root}/${leaf}")
    file(CREATE_LINK "${folder}" "${root}/${leaf}" SYMBOLIC)
  endif()
  file(GLOB sources CONFIGURE_DEPENDS "${folder}/*.cpp")
  if(EMSCRIPTEN)
    foreach(file IN LISTS ARG_DESKTOP_ONLY)
      list(REMOVE_ITEM sources "${folder}/${file}")
    endforeach()
  endif()
  add_library(m3055_${name} STATIC ${sources} ${ARG_SOURCES})
  target_include_directories(m3055_${name} PUBLIC "${root}")
  set_target_properties(m3055_${name} PROPERTIES UNITY_BUILD ${M3055_UNITY})  # CMakeLists.txt says why
  set(uses "")
  foreach(dep IN LISTS ARG_USES)
    list(APPEND uses m3055_${dep})
  endforeach()
  target_link_libraries(m3055_${name} PUBLIC ${uses} ${ARG_EXTERNAL} PRIVATE ${ARG_PRIVATE_EXTERNAL})
  # library_graph.txt: "name folder: uses..." a line, in the order declared.
  list(JOIN ARG_USES " " uses_text)
  set_property(GLOBAL APPEND PROPERTY M3055_LIBRARY_GRAPH "${name} ${ARG_FOLDER}: ${uses_text}")
endfunction()

# Written once every library is declared (the top-level CMakeLists.txt calls it).
function(m3055_write_library_graph)
  get_property(lines GLOBAL PROPERTY M3055_LIBRARY_GRAPH)
  list(JOIN lines "\n" text)
  file(WRITE "${PROJECT_BINARY_DIR}/library_graph.txt" "${text}\n")
endfunction()
