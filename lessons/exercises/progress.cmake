# The progress overview: `cmake --build build --target progress` in a
# student's build (lessons/exercises/README.md). LIST, written by
# CMakeLists.txt, has a line per exercise: its folder, whether its stub is
# untouched or started, and its test program (built on your code) or "-".
# An untouched exercise is "not started"; a started one runs its tests and
# is "passing" or "failing", with doctest's count of test cases.
file(STRINGS ${LIST} lines)
message("exercise                    progress")
foreach(line IN LISTS lines)
  list(GET line 0 exercise)
  list(GET line 1 state)
  list(GET line 2 program)
  string(LENGTH "${exercise}" length)
  math(EXPR padding "28 - ${length}")
  string(REPEAT " " ${padding} pad)
  if(state STREQUAL "untouched")
    message("${exercise}${pad}not started")
    continue()
  endif()
  execute_process(COMMAND ${program} --no-version RESULT_VARIABLE result
                  OUTPUT_VARIABLE output ERROR_VARIABLE output)
  # doctest's summary: "[doctest] test cases: 6 | 4 passed | 2 failed | 0 skipped"
  set(count "")
  if(output MATCHES "test cases: *([0-9]+) *\\| *([0-9]+) passed *\\| *([0-9]+) failed")
    set(count " (${CMAKE_MATCH_2} of ${CMAKE_MATCH_1} tests pass)")
  endif()
  if(result EQUAL 0)
    message("${exercise}${pad}passing${count}")
  else()
    message("${exercise}${pad}failing${count}: ${program} "
            "says why")
  endif()
endforeach()
