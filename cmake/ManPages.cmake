# Generates the manual pages of abalike from its --help, so they never drift from the program: abalike.6 and one
# abalike-SUBCOMMAND.6 for every subcommand `abalike --help` lists (new subcommands get a page by themselves).
# Usage: cmake -DABALIKE=exe -DOUT=dir -DVERSION=x.y.z -DHELP2MAN=path -DINCLUDE=abalike.h2m -P ManPages.cmake
execute_process(COMMAND "${ABALIKE}" --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "abalike --help failed (${status})")
endif()

# CLI11 lists them as "  NAME   description" under "Subcommands:", up to the next blank line.
string(REPLACE "\n" ";" lines "${help}")
set(in_list FALSE)
set(names "")
foreach(line IN LISTS lines)
    if(line MATCHES "^Subcommands:")
        set(in_list TRUE)
    elseif(in_list AND line MATCHES "^  ([a-z][a-z0-9-]*) +(.*)$")
        list(APPEND names "${CMAKE_MATCH_1}")
        set(summary_${CMAKE_MATCH_1} "${CMAKE_MATCH_2}")
    elseif(in_list AND NOT line MATCHES "^ ")
        set(in_list FALSE)
    endif()
endforeach()
if(NOT names)
    message(FATAL_ERROR "no subcommands found in `abalike --help`")
endif()

file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}/wrappers")

# help2man reads one program's --help; a wrapper per subcommand makes `abalike NAME --help` such a program.
set(see_also "")
foreach(name IN LISTS names)
    set(wrapper "${OUT}/wrappers/abalike-${name}")
    file(WRITE "${wrapper}" "#!/bin/sh\nexec \"${ABALIKE}\" ${name} \"$@\"\n")
    file(CHMOD "${wrapper}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE)
    string(REGEX REPLACE "\\.$" "" summary "${summary_${name}}")
    # "Open the game window" reads as "abalike-play - open the game window" in NAME.
    string(SUBSTRING "${summary}" 0 1 first)
    string(SUBSTRING "${summary}" 1 -1 rest)
    string(TOLOWER "${first}" first)
    set(summary "${first}${rest}")
    file(WRITE "${OUT}/abalike-${name}.h2m" "[SEE ALSO]\n.BR abalike (6)\n")
    execute_process(
        COMMAND "${HELP2MAN}" --no-info --section=6 --version-string=${VERSION} "--name=${summary}"
                "--include=${OUT}/abalike-${name}.h2m" "--output=${OUT}/abalike-${name}.6" "${wrapper}"
        RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "help2man failed for abalike ${name}")
    endif()
    string(APPEND see_also ".BR abalike-${name} (6),\n")
endforeach()
string(REGEX REPLACE ",\n$" "\n" see_also "${see_also}")

file(READ "${INCLUDE}" include_text)
file(WRITE "${OUT}/abalike.h2m" "${include_text}\n[SEE ALSO]\n${see_also}")
execute_process(
    COMMAND "${HELP2MAN}" --no-info --section=6 "--version-string=${VERSION}"
            "--name=slingshot physics game and physics teaching tool" "--include=${OUT}/abalike.h2m"
            "--output=${OUT}/abalike.6" "${ABALIKE}"
    RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "help2man failed for abalike")
endif()

# Debian installs manual pages compressed, without a time stamp (gzip -n) so builds are reproducible.
file(GLOB pages "${OUT}/*.6")
foreach(page IN LISTS pages)
    execute_process(COMMAND gzip -9nf "${page}" RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "gzip failed for ${page}")
    endif()
endforeach()
file(REMOVE_RECURSE "${OUT}/wrappers")
file(GLOB fragments "${OUT}/*.h2m")
file(REMOVE ${fragments})
list(LENGTH names count)
message(STATUS "Manual pages: abalike and ${count} subcommands (${names})")
