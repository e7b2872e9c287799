# gui/editor-screenshot: the editor as the README's screenshots are taken, `vct-editor SCENE --size WxH
# --screenshot FILE`, under a virtual X server. It must quit by itself once the light has converged (a view
# that never settled would hang until the test's timeout) and leave a PNG as wide as asked; a malformed --size
# is refused with a message naming it.
# Run as cmake -DXVFB_RUN=<xvfb-run> -DEDITOR=<vct-editor> -DOUT=<dir> -P EditorScreenshot.cmake.
if(NOT XVFB_RUN OR NOT EDITOR OR NOT OUT)
    message(FATAL_ERROR "usage: cmake -DXVFB_RUN=<xvfb-run> -DEDITOR=<vct-editor> -DOUT=<dir> -P EditorScreenshot.cmake")
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(
    COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1000x24" ${EDITOR} builtin:cornell_point --size 1440x900
            --screenshot ${OUT}/editor.png
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors TIMEOUT 300)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "vct-editor --screenshot exited with ${result}: ${output} ${errors}")
endif()
# A PNG's width is the big-endian word at byte 16 (the IHDR chunk).
file(READ ${OUT}/editor.png header LIMIT 24 HEX)
string(SUBSTRING "${header}" 32 8 widthHex)
math(EXPR width "0x${widthHex}")
if(NOT width EQUAL 1440)
    message(FATAL_ERROR "the screenshot is ${width} pixels wide, not 1440")
endif()
execute_process(
    COMMAND ${XVFB_RUN} -a ${EDITOR} builtin:cornell_point --size 1440by900 --screenshot ${OUT}/never.png
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors TIMEOUT 60)
if(result EQUAL 0 OR NOT "${output}${errors}" MATCHES "--size: '1440by900'")
    message(FATAL_ERROR "a malformed --size was not refused by name: ${result}: ${output} ${errors}")
endif()
