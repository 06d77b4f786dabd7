# Run at every build, not only at configure time (cmake -DSRC=<source dir> -DOUT=<file> -P this):
# the commit and whether the source tree is dirty (tracked changes or untracked files that are
# not ignored, under sph/, reference/, verification/ and CMakeLists.txt), as a C++ source file.
# OUT is rewritten only when that changes, so an unchanged tree recompiles nothing.
execute_process(COMMAND git rev-parse HEAD WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE no_git)
execute_process(COMMAND git status --porcelain --untracked-files=all -- sph reference verification CMakeLists.txt
                WORKING_DIRECTORY ${SRC} OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if((no_git OR NOT commit) AND NOT "$ENV{SPHV_ARCHIVE_COMMIT}" STREQUAL "")
  # An unpacked `git archive` of that commit, which the bundle's reproduce.sh checked (its SHA-256
  # and the commit in the archive's header) just before it builds.
  set(commit "$ENV{SPHV_ARCHIVE_COMMIT}")
  set(dirty "false")
  set(changes "")
elseif(no_git OR NOT commit)
  set(commit "unknown")
  set(dirty "true")  # no git: nothing says the sources are a committed state
  set(changes "not a git checkout")
elseif(changes)
  set(dirty "true")
else()
  set(dirty "false")
endif()
string(REPLACE "\\" "\\\\" changes "${changes}")
string(REPLACE "\"" "\\\"" changes "${changes}")
string(REPLACE "\n" "\\n" changes "${changes}")
set(text "// Generated at build time by verification/support/build_state.cmake.
#include \"build_info.hpp\"
namespace sphv::build {
const char* const git_commit = \"${commit}\";
const bool tree_dirty = ${dirty};
const char* const tree_changes = \"${changes}\";
}  // namespace sphv::build
")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
