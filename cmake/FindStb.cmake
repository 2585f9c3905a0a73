# FindStb: Sean Barrett's single-file libraries (stb_image.h, stb_image_write.h), found
# the same way on every platform: Debian/Ubuntu's libstb-dev (/usr/include/stb/), vcpkg's
# stb port (<prefix>/include/), or any folder given as Stb_INCLUDE_DIR or on CMAKE_PREFIX_PATH.
# Only the headers are used: the framework compiles their implementation once
# (framework/src/stb_implementation.cpp), so no platform's prebuilt library is needed.
#
# Defines Stb_FOUND, Stb_INCLUDE_DIR and the imported target Stb::Stb (the headers).
find_path(Stb_INCLUDE_DIR NAMES stb_image.h stb_image_write.h PATH_SUFFIXES stb
          DOC "The folder with stb_image.h and stb_image_write.h")
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Stb REQUIRED_VARS Stb_INCLUDE_DIR
                                  REASON_FAILURE_MESSAGE "install stb: libstb-dev (Debian/Ubuntu), the vcpkg manifest (Windows, macOS), or give -DStb_INCLUDE_DIR=<folder with stb_image.h>")
if(Stb_FOUND AND NOT TARGET Stb::Stb)
  add_library(Stb::Stb INTERFACE IMPORTED)
  set_target_properties(Stb::Stb PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${Stb_INCLUDE_DIR}")
endif()
mark_as_advanced(Stb_INCLUDE_DIR)
