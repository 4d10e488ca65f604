# Builds and checks the CGAL-MPM manual (doc/MPM). Run as a script:
#
#   cmake -DMODE=<mode> -DSOURCE_DIR=<repository root> [-DOUTPUT_DIR=<dir>]
#         [-DDOXYGEN=<doxygen>] -P doc/MPM/manual.cmake
#
# MODE build     runs Doxygen on doc/MPM/Doxyfile into OUTPUT_DIR/html
#                (pictures are found in doc/MPM and below, IMAGE_PATH).
# MODE warnings  runs Doxygen into a fresh OUTPUT_DIR with its warnings sent
#                to a log and fails listing them (undocumented members,
#                unresolved \ref, missing examples or images); then checks,
#                on Doxygen's XML index, that the classified reference list of
#                PackageDescription.txt names exactly the documented classes,
#                enumerations, type aliases and functions of CGAL::MPM.
# MODE examples  fails unless every examples/MPM/*.cpp is shown in the user
#                manual (\cgalExample in MPM.txt) and listed in examples.txt
#                (\example), and every program these name exists.
# MODE links     fails when a relative Markdown link or image of the manual
#                (doc/MPM/*.md, MPM.txt, PackageDescription.txt) names a file
#                that does not exist.
cmake_minimum_required(VERSION 3.16)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "manual.cmake: set -DSOURCE_DIR=<repository root>")
endif()
set(doc_dir "${SOURCE_DIR}/doc/MPM")

# Runs Doxygen from the repository root (the Doxyfile's paths are relative
# to it) with the extra settings EXTRA appended after the Doxyfile.
function(run_doxygen extra)
  if(NOT DOXYGEN)
    message(FATAL_ERROR "manual.cmake: set -DDOXYGEN=<doxygen executable>")
  endif()
  file(MAKE_DIRECTORY "${OUTPUT_DIR}")
  file(WRITE "${OUTPUT_DIR}/Doxyfile.run"
       "@INCLUDE = ${doc_dir}/Doxyfile\nOUTPUT_DIRECTORY = ${OUTPUT_DIR}\n${extra}")
  execute_process(COMMAND "${DOXYGEN}" "${OUTPUT_DIR}/Doxyfile.run"
                  WORKING_DIRECTORY "${SOURCE_DIR}"
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "doxygen failed (${status})")
  endif()
endfunction()

if(MODE STREQUAL "build")
  run_doxygen("")
  message(STATUS "The manual: ${OUTPUT_DIR}/html/index.html")

elseif(MODE STREQUAL "warnings")
  file(REMOVE_RECURSE "${OUTPUT_DIR}")
  run_doxygen("WARN_LOGFILE = ${OUTPUT_DIR}/warnings.log\nGENERATE_XML = YES\n")
  file(STRINGS "${OUTPUT_DIR}/warnings.log" warnings REGEX ".")
  list(LENGTH warnings count)
  if(count GREATER 0)
    string(REPLACE ";" "\n" listing "${warnings}")
    message(FATAL_ERROR "Doxygen reported ${count} warnings:\n${listing}")
  endif()

  # Documented names of namespace CGAL::MPM from the XML index: compounds
  # (classes, structs) and members of the namespace itself.
  file(READ "${OUTPUT_DIR}/xml/index.xml" index)
  string(REGEX MATCHALL "<compound refid=\"[^\"]*\" kind=\"(class|struct)\"><name>CGAL::MPM::[A-Za-z0-9_]+</name>"
         class_entries "${index}")
  set(documented "")
  foreach(entry IN LISTS class_entries)
    string(REGEX REPLACE ".*<name>CGAL::MPM::([A-Za-z0-9_]+)</name>" "\\1" name "${entry}")
    list(APPEND documented "${name}")
  endforeach()
  # The package's namespace and its named parameters' one.
  foreach(namespace IN ITEMS "MPM" "MPM_1_1parameters")
    string(REGEX MATCH "<compound refid=\"namespaceCGAL_1_1${namespace}\" kind=\"namespace\">.*" ns "${index}")
    string(REGEX REPLACE "</compound>.*" "" ns "${ns}")
    string(REGEX MATCHALL "kind=\"(function|enum|typedef|variable)\"><name>[A-Za-z0-9_]+</name>" member_entries "${ns}")
    string(REGEX REPLACE "^MPM(_1_1)?" "" prefix "${namespace}")
    if(prefix)
      set(prefix "${prefix}::")
    endif()
    foreach(entry IN LISTS member_entries)
      string(REGEX REPLACE ".*<name>([A-Za-z0-9_]+)</name>" "\\1" name "${entry}")
      list(APPEND documented "${prefix}${name}")
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES documented)

  file(READ "${doc_dir}/PackageDescription.txt" description)
  string(REGEX MATCHALL "`CGAL::MPM::(parameters::)?[A-Za-z0-9_]+" listed_entries "${description}")
  set(listed "")
  foreach(entry IN LISTS listed_entries)
    string(REPLACE "`CGAL::MPM::" "" name "${entry}")
    list(APPEND listed "${name}")
  endforeach()

  set(problems "")
  foreach(name IN LISTS documented)
    if(NOT name IN_LIST listed)
      string(APPEND problems "\n  CGAL::MPM::${name} is documented but not listed in PackageDescription.txt")
    endif()
  endforeach()
  foreach(name IN LISTS listed)
    if(NOT name IN_LIST documented)
      string(APPEND problems "\n  PackageDescription.txt lists CGAL::MPM::${name}, which is not a documented name")
    endif()
  endforeach()
  if(problems)
    message(FATAL_ERROR "The classified reference list is out of date:${problems}")
  endif()
  list(LENGTH documented n)
  message(STATUS "No Doxygen warnings; ${n} documented names, all in the classified reference list")

elseif(MODE STREQUAL "examples")
  file(READ "${doc_dir}/MPM.txt" manual)
  file(READ "${doc_dir}/examples.txt" listing)
  file(GLOB programs RELATIVE "${SOURCE_DIR}/examples" "${SOURCE_DIR}/examples/MPM/*.cpp")
  set(problems "")
  foreach(program IN LISTS programs)
    string(FIND "${manual}" "\\cgalExample{${program}}" at)
    if(at EQUAL -1)
      string(APPEND problems "\n  examples/${program} is not shown in doc/MPM/MPM.txt (\\cgalExample{${program}} in its own subsection)")
    endif()
    string(FIND "${listing}" "\\example ${program}" at)
    if(at EQUAL -1)
      string(APPEND problems "\n  examples/${program} is not listed in doc/MPM/examples.txt (\\example ${program})")
    endif()
  endforeach()
  string(REGEX MATCHALL "\\\\cgalExample{[^}]+}" shown "${manual}")
  string(REGEX MATCHALL "\\\\example [^ \n]+" examples "${listing}")
  foreach(entry IN LISTS shown examples)
    string(REGEX REPLACE "^\\\\(cgalExample{|example )" "" program "${entry}")
    string(REPLACE "}" "" program "${program}")
    if(NOT EXISTS "${SOURCE_DIR}/examples/${program}")
      string(APPEND problems "\n  the manual names examples/${program}, which does not exist")
    endif()
  endforeach()
  if(problems)
    message(FATAL_ERROR "Examples and manual disagree:${problems}")
  endif()
  list(LENGTH programs n)
  message(STATUS "All ${n} example programs are shown in the manual and listed in examples.txt")

elseif(MODE STREQUAL "links")
  file(GLOB pages "${doc_dir}/*.md")
  list(APPEND pages "${doc_dir}/MPM.txt" "${doc_dir}/PackageDescription.txt")
  set(problems "")
  set(checked 0)
  foreach(page IN LISTS pages)
    file(READ "${page}" text)
    get_filename_component(page_name "${page}" NAME)
    # Square brackets would confuse CMake's list splitting: mark the links first.
    string(REPLACE "](" "<link>(" text "${text}")
    string(REPLACE "[" "" text "${text}")
    string(REPLACE "]" "" text "${text}")
    string(REGEX MATCHALL "<link>\\([^)]+\\)" links "${text}")
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^<link>\\(([^ )#]*).*" "\\1" target "${link}")
      if(target STREQUAL "" OR target MATCHES "^[a-z]+:")
        continue()
      endif()
      math(EXPR checked "${checked} + 1")
      if(NOT EXISTS "${doc_dir}/${target}")
        string(APPEND problems "\n  ${page_name}: link to ${target}, which is not in doc/MPM")
      endif()
    endforeach()
  endforeach()
  if(problems)
    message(FATAL_ERROR "Broken links in the manual:${problems}")
  endif()
  message(STATUS "${checked} relative links of the manual resolve")

else()
  message(FATAL_ERROR "manual.cmake: MODE must be build, warnings, examples or links")
endif()
