# The ParaView plugin, included from the top-level CMakeLists.txt. ParaView
# brings its own VTK (5.11: VTK 9.2 as libvtk*-pv5.11), whose imported targets
# are named like the system VTK 9.1 targets the CLI uses, so the plugin is a
# CMake project of its own (plugins/paraview/CMakeLists.txt) that links the
# render core built here: tg_scale (the option ranges and their
# messages, and --pipeline auto's calibration, with tg_synth's random
# fields), tg_render, tg_gl with the embedded shaders, tg_ref,
# tg_view, tg_tensor, the VTK-free tg_field and tg_util. Nothing else crosses.
find_file(TG_PARAVIEW_CONFIG ParaViewConfig.cmake paraview-config.cmake
  PATH_SUFFIXES cmake/paraview-5.11 lib/cmake/paraview-5.11 lib/x86_64-linux-gnu/cmake/paraview-5.11)
if(TG_PARAVIEW_CONFIG)
  set(_tg_pv_default ON)
else()
  set(_tg_pv_default OFF)
endif()
option(TG_PARAVIEW_PLUGIN "Build the ParaView 5.11 plugin (plugins/paraview)" ${_tg_pv_default})
set(TG_PARAVIEW_PLUGIN_FILE "")
if(TG_PARAVIEW_PLUGIN)
  if(NOT TG_PARAVIEW_CONFIG)
    message(FATAL_ERROR "TG_PARAVIEW_PLUGIN is on but ParaView 5.11's CMake package was not found (paraview-dev)")
  endif()
  get_filename_component(_tg_pv_dir ${TG_PARAVIEW_CONFIG} DIRECTORY)
  # The plugin is a shared object: the core it links goes in with it.
  set(_tg_pv_libs tg_scale tg_synth tg_io tg_render tg_gl tg_field tg_ref tg_view tg_tensor tg_util)
  set(_tg_pv_lib_args "")
  foreach(l ${_tg_pv_libs})
    string(TOUPPER ${l} _tg_pv_var)
    list(APPEND _tg_pv_lib_args -D${_tg_pv_var}_LIB=$<TARGET_FILE:${l}>)
  endforeach()
  set_target_properties(${_tg_pv_libs} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  include(ExternalProject)
  set(TG_PARAVIEW_PLUGIN_FILE
    ${CMAKE_BINARY_DIR}/paraview-plugin/lib/paraview-5.11/plugins/TensorGlyphRayCast/TensorGlyphRayCast.so)
  ExternalProject_Add(tg_paraview_plugin
    SOURCE_DIR ${CMAKE_SOURCE_DIR}/plugins/paraview
    BINARY_DIR ${CMAKE_BINARY_DIR}/paraview-plugin
    CMAKE_ARGS -DParaView_DIR=${_tg_pv_dir} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
      -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER} -DTG_SOURCE_DIR=${CMAKE_SOURCE_DIR}
      -DTG_GLM_INCLUDE_DIR=${GLM_INCLUDE_DIR} -DTG_WERROR=${TG_WERROR}
      ${_tg_pv_lib_args}
    BUILD_ALWAYS ON
    INSTALL_COMMAND ""
    BUILD_BYPRODUCTS ${TG_PARAVIEW_PLUGIN_FILE}
    DEPENDS ${_tg_pv_libs})
  # The plugin and the .xml that names it to ParaView's plugin manager
  # (PLUGINS_FILE_NAME, plugins/paraview/CMakeLists.txt), under the prefix's
  # ParaView plugin directory: with the prefix /usr, ParaView's own.
  include(GNUInstallDirs)
  install(DIRECTORY ${CMAKE_BINARY_DIR}/paraview-plugin/lib/paraview-5.11/plugins/
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/paraview-5.11/plugins USE_SOURCE_PERMISSIONS)
endif()
