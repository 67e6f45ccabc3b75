# FindLua54.cmake — locate Lua 5.4 (headers and library), via pkg-config when
# available, else by name.  Result: target Lua54::Lua, Lua54_FOUND.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_search_module(PC_LUA54 QUIET lua5.4 lua-5.4 lua54)
endif()
find_path(LUA54_INCLUDE_DIR NAMES lua.h
          HINTS ${PC_LUA54_INCLUDE_DIRS} ${LUA_ROOT} ENV LUA_ROOT
          PATH_SUFFIXES include/lua5.4 lua5.4 include/lua54 include)
find_library(LUA54_LIBRARY NAMES lua5.4 lua54 lua-5.4 lua
             HINTS ${PC_LUA54_LIBRARY_DIRS} ${LUA_ROOT} ENV LUA_ROOT PATH_SUFFIXES lib lib64)
if(LUA54_INCLUDE_DIR AND EXISTS "${LUA54_INCLUDE_DIR}/lua.h")
  file(STRINGS "${LUA54_INCLUDE_DIR}/lua.h" _vigen_lua_minor REGEX "^#define[ \t]+LUA_VERSION_MINOR[ \t]")
  if(NOT _vigen_lua_minor MATCHES "\"4\"")
    message(STATUS "Lua headers in ${LUA54_INCLUDE_DIR} are not Lua 5.4")
    set(LUA54_INCLUDE_DIR LUA54_INCLUDE_DIR-NOTFOUND)
  endif()
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Lua54 REQUIRED_VARS LUA54_LIBRARY LUA54_INCLUDE_DIR)
if(Lua54_FOUND AND NOT TARGET Lua54::Lua)
  add_library(Lua54::Lua INTERFACE IMPORTED)
  set_target_properties(Lua54::Lua PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${LUA54_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${LUA54_LIBRARY};m;${CMAKE_DL_LIBS}")
endif()
mark_as_advanced(LUA54_INCLUDE_DIR LUA54_LIBRARY)
