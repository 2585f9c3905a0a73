# Findhttplib: cpp-httplib, the small HTTP server `whitted explore` serves its page with, found the
# same way on every platform as the imported target httplib::httplib:
#   - where the library installs its own CMake files (vcpkg's cpp-httplib port on Windows and macOS,
#     Homebrew's cpp-httplib, a build of its sources): those, as they are;
#   - Debian/Ubuntu's libcpp-httplib-dev, which ships no CMake files: a compiled library
#     (libcpp-httplib.so) whose header declares only, and which was built with HTTPS, zlib and
#     Brotli on. A program must see its header with those same switches on, or the classes it
#     shares with the library differ; the package's own description (cpp-httplib.pc, read here
#     as a file, no pkg-config needed) names the switches, and its dependencies bring their headers.
#
#   - upstream's header-only httplib.h in the folder httplib_INCLUDE_DIR, with WHITTED_HTTPLIB_HEADER_ONLY
#     on: compiled with the program, no library (instructor/scripts/test-platforms.sh, for the
#     cross-builds, which cannot link Debian's library).
#
# Defines httplib_FOUND and httplib::httplib. Not finding it is no error: `whitted explore` then says
# what to install.
option(WHITTED_HTTPLIB_HEADER_ONLY "httplib_INCLUDE_DIR holds upstream's header-only httplib.h: link no library" OFF)
if(WHITTED_HTTPLIB_HEADER_ONLY)
  if(NOT EXISTS "${httplib_INCLUDE_DIR}/httplib.h")
    message(FATAL_ERROR "WHITTED_HTTPLIB_HEADER_ONLY: no httplib.h in httplib_INCLUDE_DIR ('${httplib_INCLUDE_DIR}')")
  endif()
  set(httplib_LIBRARY "" CACHE FILEPATH "" FORCE)
else()
  find_package(httplib ${httplib_FIND_VERSION} CONFIG QUIET)
endif()
if(TARGET httplib::httplib)
  set(httplib_FOUND TRUE)
  return()
endif()
find_path(httplib_INCLUDE_DIR NAMES httplib.h DOC "The folder with cpp-httplib's httplib.h")
if(NOT WHITTED_HTTPLIB_HEADER_ONLY)
  find_library(httplib_LIBRARY NAMES cpp-httplib DOC "Debian's compiled cpp-httplib (libcpp-httplib-dev)")
endif()
set(httplib_DEFINITIONS "")
if(httplib_LIBRARY)
  get_filename_component(httplib_library_dir "${httplib_LIBRARY}" DIRECTORY)
  set(httplib_pc "${httplib_library_dir}/pkgconfig/cpp-httplib.pc")
  if(EXISTS "${httplib_pc}")
    file(STRINGS "${httplib_pc}" httplib_cflags REGEX "^Cflags:")
    string(REGEX MATCHALL "-D(CPPHTTPLIB_[A-Z_]+)" httplib_switches "${httplib_cflags}")
    foreach(switch IN LISTS httplib_switches)
      string(SUBSTRING "${switch}" 2 -1 switch)
      list(APPEND httplib_DEFINITIONS "${switch}")
    endforeach()
  endif()
endif()
# Its version, from the header: 0.11 or later (the exception handler explore's server sets takes an
# std::exception_ptr since 0.11; Ubuntu 22.04 ships 0.10).
if(httplib_INCLUDE_DIR AND EXISTS "${httplib_INCLUDE_DIR}/httplib.h")
  file(STRINGS "${httplib_INCLUDE_DIR}/httplib.h" httplib_version_line REGEX "^#define CPPHTTPLIB_VERSION \"[0-9.]+\"" LIMIT_COUNT 1)
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" httplib_VERSION "${httplib_version_line}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(httplib REQUIRED_VARS httplib_INCLUDE_DIR VERSION_VAR httplib_VERSION)
if(httplib_FOUND AND NOT TARGET httplib::httplib)
  add_library(httplib::httplib INTERFACE IMPORTED)
  set_target_properties(httplib::httplib PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${httplib_INCLUDE_DIR}"
                                                    INTERFACE_COMPILE_DEFINITIONS "${httplib_DEFINITIONS}")
  if(httplib_LIBRARY)
    set_property(TARGET httplib::httplib PROPERTY INTERFACE_LINK_LIBRARIES "${httplib_LIBRARY}")
  endif()
  if(WIN32)
    set_property(TARGET httplib::httplib APPEND PROPERTY INTERFACE_LINK_LIBRARIES ws2_32)
  endif()
endif()
mark_as_advanced(httplib_INCLUDE_DIR httplib_LIBRARY)
