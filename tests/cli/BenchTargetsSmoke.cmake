# cli/bench-targets-smoke: `vct-bench targets` on a tiny configuration, with a path-traced reference at half
# the frame size (so the box downsampling is exercised), writes every row of the targets table with finite
# figures. No timing asserts: CI machines vary too much.
# Run as cmake -DRENDER=<vct-render> -DBENCH=<vct-bench> -DOUT=<dir> -P BenchTargetsSmoke.cmake.
if(NOT RENDER OR NOT BENCH OR NOT OUT)
    message(FATAL_ERROR "usage: cmake -DRENDER=<vct-render> -DBENCH=<vct-bench> -DOUT=<dir> -P BenchTargetsSmoke.cmake")
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(
    COMMAND ${RENDER} builtin:cornell_point --reference --spp 2 --threads 1 --width 16 --height 16
            --out ${OUT}/reference.pfm
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "vct-render --reference exited with ${result}")
endif()
execute_process(
    COMMAND ${BENCH} targets builtin:cornell_point --width 32 --height 32 --voxel-res 16 --frames 2
            --reference ${OUT}/reference.pfm --out ${OUT}/targets.md
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "vct-bench targets exited with ${result}")
endif()
file(READ ${OUT}/targets.md markdown)
foreach(pattern
        "\\| full frame \\(every pass re-run\\) \\| [0-9.]+ \\| [0-9.]+ \\| \\*\\*[0-9.]+×\\*\\*"
        "\\| camera-only frame \\| [0-9.]+ \\| [0-9.]+ \\| \\*\\*[0-9.]+×\\*\\*"
        "\\| interactive preview 11×11, camera-only \\| \\| [0-9.]+ \\| \\*\\*[0-9.]+ fps\\*\\*"
        "\\| relative MSE against the reference \\(full frames\\) \\| [0-9.]+ \\| [0-9.]+ \\| [-+][0-9.]+%")
    string(REGEX MATCH "${pattern}" found "${markdown}")
    if(NOT found)
        message(FATAL_ERROR "targets.md has no row matching '${pattern}':\n${markdown}")
    endif()
endforeach()
string(FIND "${markdown}" "nan" nan)
string(FIND "${markdown}" "inf" inf)
if(NOT nan EQUAL -1 OR NOT inf EQUAL -1)
    message(FATAL_ERROR "targets.md holds a non-finite figure:\n${markdown}")
endif()

# A reference whose size the frame is no multiple of is refused before anything is rendered.
execute_process(
    COMMAND ${BENCH} targets builtin:cornell_point --width 24 --height 24 --voxel-res 16 --frames 1
            --reference ${OUT}/reference.pfm
    RESULT_VARIABLE result ERROR_VARIABLE error)
if(result EQUAL 0 OR NOT error MATCHES "integer multiple")
    message(FATAL_ERROR "a 16x16 reference for a 24x24 frame was not refused (exit ${result}): ${error}")
endif()
