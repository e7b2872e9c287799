# cli/bench-perf-smoke: `vct-bench perf` on a tiny configuration writes every table and chart. No timing
# asserts: CI machines vary too much. Run as cmake -DBENCH=<vct-bench> -DOUT=<dir> -P BenchPerfSmoke.cmake.
if(NOT BENCH OR NOT OUT)
    message(FATAL_ERROR "usage: cmake -DBENCH=<vct-bench> -DOUT=<dir> -P BenchPerfSmoke.cmake")
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(
    COMMAND ${BENCH} perf builtin:cornell_point --sizes 16x16,24x16 --grids 8,16 --triangles 1,4
            --base-size 16x16 --base-grid 16 --frames 1 --out ${OUT}
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "vct-bench perf exited with ${result}")
endif()

foreach(name results.csv efficiency.csv memory.csv perf.md
        frame_vs_pixels.svg frame_vs_pixels.png frame_vs_grid.svg frame_vs_grid.png
        frame_vs_triangles.svg frame_vs_triangles.png)
    if(NOT EXISTS ${OUT}/${name})
        message(FATAL_ERROR "${OUT}/${name} was not written")
    endif()
    file(SIZE ${OUT}/${name} size)
    if(size LESS 100)
        message(FATAL_ERROR "${OUT}/${name} is only ${size} bytes")
    endif()
endforeach()

# Four configurations (the base point serves all three curves), two modes, every pass plus two frame rows.
file(STRINGS ${OUT}/results.csv rows REGEX "cone trace")
list(LENGTH rows coneRows)
if(NOT coneRows EQUAL 8)
    message(FATAL_ERROR "results.csv has ${coneRows} cone-trace rows, expected 4 configurations x 2 modes")
endif()
file(READ ${OUT}/perf.md markdown)
foreach(heading "## Whole frame" "## Cone-trace efficiency" "## 3D texture memory")
    string(FIND "${markdown}" "${heading}" at)
    if(at LESS 0)
        message(FATAL_ERROR "perf.md lacks '${heading}'")
    endif()
endforeach()
file(READ ${OUT}/frame_vs_grid.svg svg)
string(FIND "${svg}" "</svg>" at)
if(at LESS 0)
    message(FATAL_ERROR "frame_vs_grid.svg is cut short")
endif()
