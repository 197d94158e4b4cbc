# Layering the build enforces.
#
# Every include is written from the repository root ("core/link/seriallink.h"), but no target
# sees the whole root. Each layer publishes an *include view*: a folder in the build tree that
# holds a symbolic link to the layer's own source folder and nothing else. A target sees the
# views of the layers it links (PUBLIC dependencies pass theirs on), so an include of a layer
# it does not depend on — core including ui or sim, a codec including a link, the simulator
# including client-side drive code — finds no file and fails to build.
#
#   drivedesk_layer(<target> <folder>...)   folders relative to the repository root
function(drivedesk_layer target)
  set(view "${PROJECT_BINARY_DIR}/include-views/${target}")
  foreach(folder ${ARGN})
    if(NOT IS_DIRECTORY "${PROJECT_SOURCE_DIR}/${folder}")
      message(FATAL_ERROR "drivedesk_layer(${target}): no folder ${folder}")
    endif()
    get_filename_component(parent "${view}/${folder}" DIRECTORY)
    file(MAKE_DIRECTORY "${parent}")
    if(NOT IS_SYMLINK "${view}/${folder}")
      file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${folder}" "${view}/${folder}" SYMBOLIC)
    endif()
  endforeach()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    target_include_directories(${target} INTERFACE "${view}")
  elseif(type STREQUAL "EXECUTABLE")
    target_include_directories(${target} PRIVATE "${view}")
  else()
    target_include_directories(${target} PUBLIC "${view}")
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    # Its precompiled header is chosen once its links are known (drivedesk_precompile_layers).
    set_property(GLOBAL APPEND PROPERTY DRIVEDESK_LAYER_LIBRARIES ${target})
  endif()
endfunction()

# Every layer library gets its precompiled Qt headers (cmake/DriveDeskBuildSpeed.cmake); one
# that links Qt Widgets gets the widget headers too. Called once, after all layers exist.
function(drivedesk_precompile_layers)
  get_property(layers GLOBAL PROPERTY DRIVEDESK_LAYER_LIBRARIES)
  foreach(layer ${layers})
    get_target_property(links ${layer} LINK_LIBRARIES)
    if("Qt6::Widgets" IN_LIST links)
      drivedesk_precompile(${layer} WIDGETS)
    else()
      drivedesk_precompile(${layer})
    endif()
  endforeach()
endfunction()
