# The .ts files are current: lupdate over src/ and ui/ with the build's options, into copies of
# translations/*.ts, must change nothing (no new, changed or vanished message). Otherwise run
#   cmake --build build --target update_translations
# and commit the .ts files. Arguments: -DLUPDATE=... -DSOURCE_DIR=... -DWORK_DIR=...
# -DOPTIONS="opt|opt|..." -DTS_FILES="a.ts|b.ts|..."
string(REPLACE "|" ";" OPTIONS "${OPTIONS}")
string(REPLACE "|" ";" TS_FILES "${TS_FILES}")
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(failed "")
foreach(ts ${TS_FILES})
    get_filename_component(name ${ts} NAME)
    configure_file(${ts} ${WORK_DIR}/${name} COPYONLY)
    execute_process(
        COMMAND ${LUPDATE} ${SOURCE_DIR}/src ${SOURCE_DIR}/ui ${OPTIONS} -ts ${WORK_DIR}/${name}
        WORKING_DIRECTORY ${SOURCE_DIR}
        RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "lupdate failed on ${name}:\n${out}\n${err}")
    endif()
    file(READ ${ts} before)
    file(READ ${WORK_DIR}/${name} after)
    if(NOT before STREQUAL after)
        string(REGEX MATCH "Found [^\n]*" found "${out}")
        list(APPEND failed "${name}: ${found}")
    endif()
endforeach()
if(failed)
    list(JOIN failed "\n  " text)
    message(FATAL_ERROR "translations/*.ts are not current (run the update_translations "
                        "target and commit them):\n  ${text}")
endif()
message(STATUS "translations/*.ts are current")
