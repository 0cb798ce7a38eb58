# The ctest labels of SPEC §12: every test is `fast` (the everyday loop,
# `ctest -L fast`, under 3 minutes for a Release build on the 2-core CI
# machine) or `slow` (over ~5 s each there), and may also be `gpu` (needs the
# Vulkan backend), `mpi` (mpirun), `browser` (headless Chromium) or `fuzz`
# (libFuzzer harnesses and the replay of what they found).
# tests/labels_test.py holds every registered test to that.
include(GoogleTest)

# vri_discover_tests(TARGET [FILTER gtest-filter] [SLOW gtest-filter]
#                    [LABELS label...] [PROPERTIES name value...]):
# gtest_discover_tests for the tests of TARGET that FILTER keeps (all when
# none), labelled `slow` where SLOW names them and `fast` otherwise, each with
# LABELS added. (gtest_discover_tests flattens a list-valued property, so the
# labels are set by a ctest include file that runs after the discovery's.)
function(vri_discover_tests target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "FILTER;SLOW" "LABELS;PROPERTIES")
  if(NOT arg_FILTER)
    set(arg_FILTER "*")
  endif()
  # gtest's filter is POSITIVE[-NEGATIVE]: the exclusions go after the one '-'.
  string(FIND "${arg_FILTER}" "-" dash)
  if(dash EQUAL -1)
    set(fast_filter "${arg_FILTER}-")
  else()
    set(fast_filter "${arg_FILTER}:")
  endif()
  string(MAKE_C_IDENTIFIER "${target}_${arg_FILTER}" id)
  set(script "")
  set(kinds fast)
  if(arg_SLOW)
    string(APPEND fast_filter "${arg_SLOW}")
    list(APPEND kinds slow)
  else()
    string(REGEX REPLACE "[-:]$" "" fast_filter "${fast_filter}")
  endif()
  foreach(kind IN LISTS kinds)
    if(kind STREQUAL fast)
      set(filter "${fast_filter}")
    else()
      set(filter "${arg_SLOW}")
    endif()
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 120 TEST_FILTER "${filter}" TEST_LIST ${id}_${kind}
                         PROPERTIES ${arg_PROPERTIES})
    set(labels ${kind} ${arg_LABELS})
    string(APPEND script "if(${id}_${kind})\n  set_tests_properties(\${${id}_${kind}} PROPERTIES LABELS \"${labels}\")\nendif()\n")
  endforeach()
  set(file ${CMAKE_CURRENT_BINARY_DIR}/${id}_labels.cmake)
  file(WRITE ${file} "${script}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${file})
endfunction()
